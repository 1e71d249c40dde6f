// .vti export read back by VTK's own reader (vtkXMLImageDataReader): dimensions, spacing, origin at the centre of
// voxel (0, 0, 0), the voxels and the fields value for value, the units.
#include <gtest/gtest.h>

#include <string>

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkXMLImageDataReader.h>

#include "support/grids.h"
#include "vox/io/vti.h"

namespace vox::io {
namespace {

GridFrame frame() {
  return GridFrame{.origin = glm::dvec3(-1.0, 2.0, 0.5), .voxel_size = 0.25, .units = "mm", .source = ""};
}

struct ReadBack {
  vtkNew<vtkXMLImageDataReader> reader;
  vtkImageData* image = nullptr;
};

void readBack(const std::vector<uint8_t>& bytes, ReadBack& r) {
  r.reader->ReadFromInputStringOn();
  r.reader->SetInputString(std::string(bytes.begin(), bytes.end()));
  r.reader->Update();
  r.image = r.reader->GetOutput();
}

TEST(Vti, vtkReadsTheVoxelsWithTheirPlacementAndUnits) {
  VoxelGrid g = test::randomGrid(Dims{70, 9, 5}, 0.4, 7);  // rows longer than one 64-bit word
  g.frame() = frame();
  auto bytes = encodeVti(voxelsOnly(g));
  ASSERT_TRUE(bytes.ok()) << bytes.error().message;
  ReadBack r;
  readBack(*bytes, r);
  ASSERT_NE(r.image, nullptr);
  int dims[3];
  r.image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 70);
  EXPECT_EQ(dims[1], 9);
  EXPECT_EQ(dims[2], 5);
  double spacing[3], origin[3];
  r.image->GetSpacing(spacing);
  r.image->GetOrigin(origin);
  for (int a = 0; a < 3; ++a) EXPECT_DOUBLE_EQ(spacing[a], 0.25);
  EXPECT_DOUBLE_EQ(origin[0], -0.875);  // the centre of voxel (0, 0, 0): origin + half a voxel
  EXPECT_DOUBLE_EQ(origin[1], 2.125);
  EXPECT_DOUBLE_EQ(origin[2], 0.625);

  vtkDataArray* voxels = r.image->GetPointData()->GetArray("voxels");
  ASSERT_NE(voxels, nullptr);
  EXPECT_EQ(voxels->GetDataType(), VTK_UNSIGNED_CHAR);
  EXPECT_EQ(r.image->GetPointData()->GetScalars(), voxels);
  ASSERT_EQ(voxels->GetNumberOfTuples(), g.dims().count());
  int64_t filled = 0;
  for (int32_t z = 0; z < 5; ++z)
    for (int32_t y = 0; y < 9; ++y)
      for (int32_t x = 0; x < 70; ++x) {
        const double v = voxels->GetTuple1(vtkIdType(g.index(x, y, z)));  // x fastest, then y, then z
        ASSERT_EQ(v, g.get(x, y, z) ? 1.0 : 0.0) << x << " " << y << " " << z;
        filled += v > 0.0;
      }
  EXPECT_EQ(filled, g.filledCount());

  auto* units = vtkStringArray::SafeDownCast(r.image->GetFieldData()->GetAbstractArray("units"));
  ASSERT_NE(units, nullptr);
  EXPECT_EQ(units->GetValue(0), "mm");
}

TEST(Vti, fieldsAreFloatArraysUnderTheirNamesBesideTheVoxels) {
  VoxelGrid g = test::randomGrid(Dims{6, 5, 4}, 0.5, 3);
  g.frame() = frame();
  ScalarField thickness(g.dims(), g.frame()), distance(g.dims(), g.frame());
  for (size_t i = 0; i < thickness.values.size(); ++i) {
    thickness.values[i] = float(i) * 0.125f;
    distance.values[i] = -float(i) * 0.5f;
  }
  VolumeContent content{&g, {{"thickness", &thickness}, {"distance", &distance}}};
  auto bytes = encodeVti(content);
  ASSERT_TRUE(bytes.ok()) << bytes.error().message;
  ReadBack r;
  readBack(*bytes, r);
  for (const NamedField& f : content.fields) {
    vtkDataArray* a = r.image->GetPointData()->GetArray(f.name.c_str());
    ASSERT_NE(a, nullptr) << f.name;
    EXPECT_EQ(a->GetDataType(), VTK_FLOAT);
    ASSERT_EQ(a->GetNumberOfTuples(), vtkIdType(f.field->values.size()));
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
      ASSERT_EQ(float(a->GetTuple1(i)), f.field->values[size_t(i)]);
  }
  EXPECT_EQ(r.image->GetPointData()->GetScalars()->GetName(), std::string("voxels"));
}

TEST(Vti, aFieldAloneCarriesItsOwnPlacement) {
  ScalarField f(Dims{3, 2, 2}, frame(), 2.5f);
  auto bytes = encodeVti(oneField("thickness", f));
  ASSERT_TRUE(bytes.ok()) << bytes.error().message;
  ReadBack r;
  readBack(*bytes, r);
  double origin[3];
  r.image->GetOrigin(origin);
  EXPECT_DOUBLE_EQ(origin[0], -0.875);
  ASSERT_NE(r.image->GetPointData()->GetArray("thickness"), nullptr);
  EXPECT_EQ(r.image->GetPointData()->GetArray("voxels"), nullptr);
}

TEST(Vti, fieldsOffTheVoxelsLatticeAreRefused) {
  VoxelGrid g(Dims{4, 4, 4}, frame());
  ScalarField other(Dims{4, 4, 3}, frame());
  auto r = encodeVti(VolumeContent{&g, {{"thickness", &other}}});
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("thickness"), std::string::npos) << r.error().message;
}

}  // namespace
}  // namespace vox::io
