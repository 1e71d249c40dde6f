#include "support/cad_parts.h"

#include <cstdlib>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRep_Builder.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Controller.hxx>

#include <STEPControl_Writer.hxx>
#include <StepBasic_Product.hxx>
#include <TCollection_HAsciiString.hxx>
#include <StepData_StepModel.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Ax2.hxx>
#include <gtest/gtest.h>

namespace vox::test {
namespace {

TopoDS_Shape solidOf(const CadPart& p) {
  const gp_Pnt c(p.corner.x, p.corner.y, p.corner.z);
  switch (p.shape) {
    case CadShape::kBox:
      return BRepPrimAPI_MakeBox(c, p.size.x, p.size.y, p.size.z).Shape();
    case CadShape::kCylinder:
      return BRepPrimAPI_MakeCylinder(gp_Ax2(c, gp::DZ()), p.size.x, p.size.z).Shape();
    case CadShape::kSphere:
      return BRepPrimAPI_MakeSphere(c, p.size.x).Shape();
    case CadShape::kTorus:
      return BRepPrimAPI_MakeTorus(gp_Ax2(c, gp::DZ()), p.size.x, p.size.y).Shape();
    case CadShape::kOpenBox: {
      BRepPrimAPI_MakeBox box(c, p.size.x, p.size.y, p.size.z);
      BRep_Builder builder;
      TopoDS_Compound faces;
      builder.MakeCompound(faces);
      for (const TopoDS_Face& f :
           {box.BottomFace(), box.FrontFace(), box.BackFace(), box.LeftFace(), box.RightFace()}) {
        builder.Add(faces, f);
      }
      return faces;
    }
  }
  return {};
}

// The writers report on stdout through OCCT's default printers; voxmod's own collector (src/io) stays.
void quietWriters() {
  Message_SequenceOfPrinters& printers = Message::DefaultMessenger()->ChangePrinters();
  for (int i = printers.Length(); i >= 1; --i) {
    if (printers.Value(i)->IsKind(STANDARD_TYPE(Message_PrinterOStream))) printers.Remove(i);
  }
}

TopoDS_Compound compoundOf(const std::vector<CadPart>& parts) {
  BRep_Builder builder;
  TopoDS_Compound all;
  builder.MakeCompound(all);
  for (const CadPart& p : parts) builder.Add(all, solidOf(p));
  return all;
}

// The writer names the compound's product "Open CASCADE STEP translator <version> <n>" and part k's "... <n>.k", n
// counting the files the process wrote: each part's product takes the part's name instead.
void nameProducts(STEPControl_Writer& writer, const std::vector<CadPart>& parts) {
  const Handle(StepData_StepModel) model = writer.Model();
  for (int i = 1; i <= model->NbEntities(); ++i) {
    const auto product = Handle(StepBasic_Product)::DownCast(model->Value(i));
    if (product.IsNull() || product->Name().IsNull()) continue;
    const std::string name = product->Name()->ToCString();
    const size_t space = name.rfind(' '), dot = name.rfind('.');
    if (space == std::string::npos || dot == std::string::npos || dot < space) continue;
    const size_t k = size_t(std::atoi(name.c_str() + dot + 1));
    if (k < 1 || k > parts.size()) continue;
    const Handle(TCollection_HAsciiString) given = new TCollection_HAsciiString(parts[k - 1].name.c_str());
    product->SetName(given);
    product->SetId(given);
  }
}

}  // namespace

void writeStep(const std::filesystem::path& path, const std::vector<CadPart>& parts, const char* unit,
               const char* schema) {
  quietWriters();
  STEPControl_Controller::Init();  // defines the write.step.* settings
  ASSERT_TRUE(Interface_Static::SetCVal("write.step.schema", schema));
  ASSERT_TRUE(Interface_Static::SetCVal("write.step.unit", unit));  // read when the writer makes its model
  STEPControl_Writer writer;
  ASSERT_EQ(writer.Transfer(compoundOf(parts), STEPControl_AsIs), IFSelect_RetDone);
  nameProducts(writer, parts);
  ASSERT_EQ(writer.Write(path.c_str()), IFSelect_RetDone) << path;
  Interface_Static::SetCVal("write.step.unit", "MM");
  Interface_Static::SetCVal("write.step.schema", "AP214IS");
}

void writeIgesFaces(const std::filesystem::path& path, const std::vector<CadPart>& parts) {
  quietWriters();
  IGESControl_Controller::Init();
  IGESControl_Writer writer("MM", 0);  // mode 0: faces (trimmed surfaces), no solid
  ASSERT_TRUE(writer.AddShape(compoundOf(parts)));
  writer.ComputeModel();
  ASSERT_TRUE(writer.Write(path.c_str())) << path;
}

}  // namespace vox::test
