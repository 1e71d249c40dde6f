// STEP and IGES through Open CASCADE, on parts made in the test (tests/support/cad_parts.h) whose exact geometry is
// known: bodies, units, the tessellation's distance from the exact surface, sewing, progress and cancel, and the
// files that must be refused.
#include "vox/io/cad.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <gtest/gtest.h>

#include "support/cad_parts.h"
#include "support/test_support.h"
#include "vox/io/mesh_file.h"

namespace vox::io {
namespace {

using test::CadPart;
using test::CadShape;

MeshFileLoad loadOk(const std::filesystem::path& path, MeshFileOptions options = {}) {
  auto r = loadMeshFile(path, options);
  EXPECT_TRUE(r.ok()) << r.error().message;
  return r.ok() ? std::move(r).value() : MeshFileLoad{};
}

// Distance from p to the surface of the part (exact signed-distance functions of a box, a capped cylinder, a ball).
double distanceToSurface(const CadPart& part, const glm::dvec3& p) {
  switch (part.shape) {
    case CadShape::kBox:
    case CadShape::kOpenBox: {
      const glm::dvec3 c = part.corner + 0.5 * part.size, half = 0.5 * part.size;
      const glm::dvec3 q = glm::abs(p - c) - half;
      const double outside = glm::length(glm::max(q, glm::dvec3(0.0)));
      return std::abs(outside + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0));
    }
    case CadShape::kCylinder: {
      const double rho = std::hypot(p.x - part.corner.x, p.y - part.corner.y);
      const glm::dvec2 q(rho - part.size.x, std::abs(p.z - part.corner.z - 0.5 * part.size.z) - 0.5 * part.size.z);
      const double outside = glm::length(glm::max(q, glm::dvec2(0.0)));
      return std::abs(outside + std::min(std::max(q.x, q.y), 0.0));
    }
    case CadShape::kSphere:
      return std::abs(glm::length(p - part.corner) - part.size.x);
    case CadShape::kTorus: {
      const glm::dvec3 d = p - part.corner;
      return std::abs(glm::length(glm::dvec2(std::hypot(d.x, d.y) - part.size.x, d.z)) - part.size.y);
    }
  }
  return 0.0;
}

// The largest distance from the exact surface over the corners and 12 more points inside each triangle.
double largestDistance(const TriangleMesh& mesh, const CadPart& part) {
  double worst = 0.0;
  for (const Triangle& t : mesh.triangles) {
    for (int i = 0; i <= 4; ++i) {
      for (int j = 0; i + j <= 4; ++j) {
        const glm::dvec3 p =
            (double(i) * glm::dvec3(t.v[0]) + double(j) * glm::dvec3(t.v[1]) + double(4 - i - j) * glm::dvec3(t.v[2])) /
            4.0;
        worst = std::max(worst, distanceToSurface(part, p));
      }
    }
  }
  return worst;
}

TEST(CadFile, stepBoxIsOneClosedSolidInMillimetres) {
  test::TempDir tmp;
  test::writeStep(tmp / "box.step", {{CadShape::kBox, {1, 2, 3}, {10, 20, 30}}});
  MeshFileOptions options;
  options.resolution = 100;
  const MeshFileLoad m = loadOk(tmp / "box.step", options);
  EXPECT_EQ(m.format, MeshFormat::kStep);
  EXPECT_EQ(m.units, "mm");
  EXPECT_EQ(m.file_units, "millimetre");
  ASSERT_EQ(m.bodies.size(), 1u);
  EXPECT_EQ(m.bodies[0].triangle_count, m.mesh.triangles.size());
  EXPECT_TRUE(m.topology.watertight());
  EXPECT_EQ(m.topology.degenerate_triangles, 0);
  EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
  // Planar faces: the mesh is the box itself, its corners exactly where the file puts them.
  EXPECT_EQ(m.mesh.bounds().min, glm::dvec3(1, 2, 3));
  EXPECT_EQ(m.mesh.bounds().max, glm::dvec3(11, 22, 33));
  EXPECT_NEAR(signedVolume(m.mesh), 6000.0, 1e-9 * 6000.0);
  EXPECT_DOUBLE_EQ(m.deflection, kCadDeflectionVoxels * 30.0 / 100.0);
  EXPECT_EQ(m.deflection, 0.012);
  ASSERT_FALSE(m.notes.empty());
  EXPECT_EQ(m.notes[0], (tmp / "box.step").string() +
                            ": STEP (AUTOMOTIVE_DESIGN), unit 'millimetre' (read as mm), 1 solid, 10 x 20 x 30 mm; "
                            "tessellated within 0.012 mm");
  ASSERT_NE(m.cad, nullptr);
  EXPECT_EQ(m.cad->solids(), 1);
}

// AP203 and AP242 files (the schemas besides AP214 that CAD systems write) read as the AP214 file does: the same
// solids, the same exact corners, the schema named in the format.
TEST(CadFile, stepAp203AndAp242FilesReadAsAp214Does) {
  test::TempDir tmp;
  const std::pair<const char*, const char*> schemas[] = {{"AP203", "CONFIG_CONTROL_DESIGN"},
                                                         {"AP242DIS", "AP242_MANAGED_MODEL_BASED_3D_ENGINEERING"}};
  for (const auto& [schema, name] : schemas) {
    SCOPED_TRACE(schema);
    const auto path = tmp / (std::string(schema) + ".step");
    test::writeStep(path, {{CadShape::kBox, {1, 2, 3}, {10, 20, 30}}, {CadShape::kCylinder, {30, 0, 0}, {5, 0, 10}}},
                    "MM", schema);
    const std::string text = test::readFile(path);
    EXPECT_NE(text.find(name), std::string::npos) << "FILE_SCHEMA not " << name;
    MeshFileOptions options;
    options.resolution = 100;
    const MeshFileLoad m = loadOk(path, options);
    EXPECT_EQ(m.format, MeshFormat::kStep);
    EXPECT_NE(m.format_detail.find(name), std::string::npos) << m.format_detail;
    EXPECT_EQ(m.units, "mm");
    ASSERT_EQ(m.bodies.size(), 2u);
    EXPECT_TRUE(m.topology.watertight());
    const TriangleMesh box = bodyMesh(m.mesh, fileBodies(m.bodies, m.mesh.triangles.size(), true)->bodies, 0);
    EXPECT_EQ(box.bounds().min, glm::dvec3(1, 2, 3));
    EXPECT_EQ(box.bounds().max, glm::dvec3(11, 22, 33));
    EXPECT_NEAR(signedVolume(box), 6000.0, 1e-9 * 6000.0);
  }
}

TEST(CadFile, inchFileIsConvertedToMillimetresAndSaysItsUnit) {
  test::TempDir tmp;
  test::writeStep(tmp / "inch.step", {{CadShape::kBox, {0, 0, 0}, {25.4, 50.8, 12.7}}}, "INCH");
  const std::string text = test::readFile(tmp / "inch.step");
  EXPECT_NE(text.find("INCH"), std::string::npos);  // the file's numbers are inches
  const MeshFileLoad m = loadOk(tmp / "inch.step");
  EXPECT_EQ(m.file_units, "INCH");
  EXPECT_EQ(m.units, "mm");
  EXPECT_NEAR(m.mesh.bounds().max.x, 25.4, 1e-5);
  EXPECT_NEAR(m.mesh.bounds().max.y, 50.8, 1e-5);
}

TEST(CadFile, aUnitGivenByTheCallerReplacesTheFilesOwn) {
  test::TempDir tmp;
  test::writeStep(tmp / "box.step", {{CadShape::kBox, {0, 0, 0}, {1, 2, 3}}});
  MeshFileOptions options;
  options.units = "in";  // the file says mm, but its numbers are really inches
  const MeshFileLoad m = loadOk(tmp / "box.step", options);
  EXPECT_EQ(m.units, "mm");
  EXPECT_NEAR(m.mesh.bounds().max.z, 3 * 25.4, 1e-4);
  ASSERT_GE(m.notes.size(), 2u);
  EXPECT_NE(m.notes[1].find("coordinates taken as in (the file says 'millimetre'): scaled by 25.4"), std::string::npos)
      << m.notes[1];
}

// docs/accuracy.md, "CAD tessellation": within kCadSurfaceBoundVoxels (0.1 voxel) of the exact surface, at
// resolutions whose deflections hit both the good and the bad cases of BRepMesh's sphere grid.
TEST(CadFile, tessellationLiesWithinATenthOfAVoxelOfTheExactSurface) {
  test::TempDir tmp;
  for (const CadPart& part :
       {CadPart{CadShape::kCylinder, {5, -3, 2}, {10, 0, 30}}, CadPart{CadShape::kSphere, {0, 0, 0}, {10, 0, 0}},
        CadPart{CadShape::kTorus, {1, 2, 3}, {10, 3, 0}}}) {
    test::writeStep(tmp / "part.step", {part});
    double worst_ratio = 0.0;
    for (int64_t r : {20, 50, 100, 170, 400}) {
      MeshFileOptions options;
      options.resolution = r;
      const MeshFileLoad m = loadOk(tmp / "part.step", options);
      ASSERT_FALSE(m.mesh.triangles.empty());
      const double h = m.deflection / kCadDeflectionVoxels;
      const double worst = largestDistance(m.mesh, part);
      EXPECT_LE(worst, kCadSurfaceBoundVoxels * h) << "shape " << int(part.shape) << " R=" << r;
      worst_ratio = std::max(worst_ratio, worst / m.deflection);
      // Poles and seams leave no hole, no sliver and no doubled edge.
      EXPECT_TRUE(m.topology.watertight()) << "shape " << int(part.shape) << " R=" << r;
      EXPECT_EQ(m.topology.degenerate_triangles, 0) << "shape " << int(part.shape) << " R=" << r;
    }
    RecordProperty("worst_over_deflection_shape" + std::to_string(int(part.shape)), std::to_string(worst_ratio));
  }
}

TEST(CadFile, eachSolidOfAnAssemblyIsABody) {
  test::TempDir tmp;
  test::writeStep(tmp / "two.step",
                  {{CadShape::kBox, {0, 0, 0}, {1, 1, 1}}, {CadShape::kCylinder, {5, 0, 0}, {1, 0, 2}}});
  const MeshFileLoad m = loadOk(tmp / "two.step");
  ASSERT_EQ(m.bodies.size(), 2u);
  EXPECT_EQ(m.bodies[0].name, "solid 1");
  EXPECT_EQ(m.bodies[1].name, "solid 2");
  EXPECT_EQ(m.bodies[0].first_triangle, 0u);
  EXPECT_EQ(m.bodies[1].first_triangle, m.bodies[0].triangle_count);
  EXPECT_EQ(m.bodies[0].triangle_count + m.bodies[1].triangle_count, m.mesh.triangles.size());
  EXPECT_EQ(m.bodies[0].triangle_count, 12u);  // the box
  EXPECT_TRUE(m.topology.watertight());
}

// A STEP file's solids take their products' names, numbered where a product is placed more than once; a solid of a
// product without a name is "solid N" (N its place among the solids).
TEST(CadFile, solidsAreNamedByTheirProducts) {
  test::TempDir tmp;
  test::writeStep(tmp / "named.step", {{CadShape::kBox, {0, 0, 0}, {4, 4, 1}, "plate"},
                                       {CadShape::kCylinder, {1, 1, 1}, {0.5, 0, 2}, "pin"},
                                       {CadShape::kCylinder, {3, 3, 1}, {0.5, 0, 2}, "pin"},
                                       {CadShape::kSphere, {8, 8, 8}, {1, 0, 0}, ""}});
  const MeshFileLoad m = loadOk(tmp / "named.step");
  ASSERT_EQ(m.bodies.size(), 4u);
  std::vector<std::string> names;
  for (const MeshBody& b : m.bodies) names.push_back(b.name);
  EXPECT_EQ(names, (std::vector<std::string>{"plate", "pin 1", "pin 2", "solid 4"}));
  EXPECT_EQ(m.bodies[0].triangle_count, 12u);  // the plate is the box
  // The names follow the solids through a unit given instead of the file's (the shape rescaled).
  MeshFileOptions inches;
  inches.units = "in";
  const MeshFileLoad scaled = loadOk(tmp / "named.step", inches);
  ASSERT_EQ(scaled.bodies.size(), 4u);
  for (size_t k = 0; k < 4; ++k) EXPECT_EQ(scaled.bodies[k].name, names[k]) << k;
  EXPECT_NEAR(scaled.mesh.bounds().extent().x, 25.4 * 9.0, 2.0);  // 0..9 "mm" read as inches (the ball tessellated)
}

TEST(CadFile, igesSurfaceModelIsSewnIntoAClosedSolid) {
  test::TempDir tmp;
  test::writeIgesFaces(tmp / "box.iges", {{CadShape::kBox, {0, 0, 0}, {10, 10, 10}}});
  const MeshFileLoad m = loadOk(tmp / "box.iges");
  EXPECT_EQ(m.format, MeshFormat::kIges);
  EXPECT_EQ(m.cad->solids(), 0);
  EXPECT_EQ(m.cad->looseFaces(), 6);
  ASSERT_EQ(m.bodies.size(), 1u);
  EXPECT_EQ(m.bodies[0].name, "closed shell 1");
  EXPECT_TRUE(m.topology.watertight());
  EXPECT_NEAR(signedVolume(m.mesh), 1000.0, 1e-6);  // outward, as a solid
  EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
  EXPECT_NE(m.notes.back().find("1 closed shells sewn from loose faces"), std::string::npos) << m.notes.back();
}

TEST(CadFile, openIgesSurfaceIsKeptWithAWarning) {
  test::TempDir tmp;
  test::writeIgesFaces(tmp / "open.iges", {{CadShape::kOpenBox, {0, 0, 0}, {10, 10, 10}}});
  const MeshFileLoad m = loadOk(tmp / "open.iges");
  ASSERT_EQ(m.bodies.size(), 1u);
  EXPECT_EQ(m.bodies[0].name, "open surface 1");
  EXPECT_FALSE(m.topology.watertight());
  ASSERT_FALSE(m.warnings.empty());
  EXPECT_EQ(m.warnings[0], (tmp / "open.iges").string() +
                               ": open surface: 5 faces that sewing (tolerance 0.002 mm) leaves open, with 4 free "
                               "edges; it has no inside of its own (voxelized as an open mesh: auto mode votes)");
}

TEST(CadFile, boundsComeBeforeTheTessellation) {
  test::TempDir tmp;
  test::writeStep(tmp / "c.step", {{CadShape::kCylinder, {0, 0, 0}, {10, 0, 40}}});
  auto model = readCadFile(tmp / "c.step");
  ASSERT_TRUE(model.ok()) << model.error().message;
  EXPECT_NEAR(model->bounds().min.x, -10.0, 1e-7);
  EXPECT_NEAR(model->bounds().max.z, 40.0, 1e-7);
  EXPECT_EQ(model->solids(), 1);
  auto deflection = cadDeflectionFor(model->bounds(), 400, 0.0);
  ASSERT_TRUE(deflection.ok());
  EXPECT_NEAR(*deflection, kCadDeflectionVoxels * 0.1, 1e-9);
  auto coarse = tessellateCad(*model, 1.0);
  auto fine = tessellateCad(*model, *deflection);
  ASSERT_TRUE(coarse.ok() && fine.ok());
  EXPECT_LT(coarse->mesh.triangles.size(), fine->mesh.triangles.size());
  EXPECT_EQ(fine->deflection, *deflection);
  EXPECT_FALSE(tessellateCad(*model, 0.0).ok());
}

TEST(CadFile, progressRisesToOneAndCancelStops) {
  test::TempDir tmp;
  test::writeStep(tmp / "s.step", {{CadShape::kSphere, {0, 0, 0}, {5, 0, 0}}});
  std::vector<double> seen;
  MeshFileOptions options;
  options.progress = [&](double f) {
    seen.push_back(f);
    return true;
  };
  loadOk(tmp / "s.step", options);
  ASSERT_FALSE(seen.empty());
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_DOUBLE_EQ(seen.back(), 1.0);

  for (double stop_at : {0.0, 0.5}) {
    options.progress = [stop_at](double f) { return f < stop_at; };  // 0: at the first report
    auto r = loadMeshFile(tmp / "s.step", options);
    ASSERT_FALSE(r.ok()) << "stop at " << stop_at;
    EXPECT_EQ(r.error().code, ErrorCode::kCancelled) << r.error().message;
  }
}

TEST(CadFile, truncatedAndBrokenFilesAreRefusedNamingTheFile) {
  test::TempDir tmp;
  test::writeStep(tmp / "box.step", {{CadShape::kBox, {0, 0, 0}, {1, 1, 1}}});
  const std::string step = test::readFile(tmp / "box.step");
  test::writeFile(tmp / "cut.step", step.substr(0, step.size() / 2));
  auto r = loadMeshFile(tmp / "cut.step");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kParse);
  EXPECT_EQ(r.error().message,
            (tmp / "cut.step").string() + ": STEP file truncated: it does not end with 'END-ISO-10303-21;'");

  test::writeFile(tmp / "junk.step", "ISO-10303-21;\nHEADER;\nthis is not STEP\nENDSEC;\nEND-ISO-10303-21;\n");
  r = loadMeshFile(tmp / "junk.step");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kParse);
  EXPECT_EQ(r.error().message.rfind((tmp / "junk.step").string() + ": not a readable STEP file", 0), 0u)
      << r.error().message;

  // A reference that is not one (found by the fuzzer: Open CASCADE 7.6 crashes transferring it).
  std::string broken = step;
  const size_t at = broken.find("VERTEX_POINT('',#");
  ASSERT_NE(at, std::string::npos);
  broken.erase(at + 16, 1);
  test::writeFile(tmp / "broken.step", broken);
  r = loadMeshFile(tmp / "broken.step");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(
      r.error().message.rfind((tmp / "broken.step").string() + ": malformed STEP file: 1 error (Open CASCADE: ", 0), 0u)
      << r.error().message;

  test::writeIgesFaces(tmp / "box.iges", {{CadShape::kBox, {0, 0, 0}, {1, 1, 1}}});
  const std::string iges = test::readFile(tmp / "box.iges");
  test::writeFile(tmp / "cut.iges", iges.substr(0, iges.size() - 200));
  r = loadMeshFile(tmp / "cut.iges");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, (tmp / "cut.iges").string() +
                                   ": IGES file truncated: its last line is not a Terminate record ('T' in column 73)");
}

// Line (1-based) of the first occurrence of what in text.
size_t lineOf(const std::string& text, const std::string& what) {
  const size_t at = text.find(what);
  EXPECT_NE(at, std::string::npos) << what;
  return size_t(std::count(text.begin(), text.begin() + std::ptrdiff_t(std::min(at, text.size())), '\n')) + 1;
}

TEST(CadFile, anEntityNameDefinedTwiceIsRefusedBeforeOpenCascadeSearchesForIt) {
  test::TempDir tmp;
  test::writeStep(tmp / "box.step", {{CadShape::kBox, {0, 0, 0}, {1, 1, 1}}});
  const std::string step = test::readFile(tmp / "box.step");

  // #1 defined again just before the end of the data section.
  const size_t first = step.find("#1 =") != std::string::npos ? step.find("#1 =") : step.find("#1=");
  ASSERT_NE(first, std::string::npos);
  const std::string first_statement = step.substr(first, step.find(';', first) + 1 - first);
  std::string twice = step;
  twice.insert(twice.rfind("ENDSEC;"), first_statement + "\n");
  test::writeFile(tmp / "twice.step", twice);
  auto r = loadMeshFile(tmp / "twice.step");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().code, ErrorCode::kParse);
  EXPECT_EQ(r.error().message, (tmp / "twice.step").string() + ":" +
                                   std::to_string(lineOf(twice, "\n" + first_statement + "\nENDSEC;") + 1) +
                                   ": malformed STEP file: entity #1 is defined a second time (first at line " +
                                   std::to_string(lineOf(twice, first_statement)) + ")");

  // An apostrophe inside a string ends it only before ')' or ',' (as Open CASCADE reads strings): the second
  // definition after "O'Brien" is still seen.
  std::string quoted = twice;
  const size_t file_name = quoted.find("FILE_NAME('");
  ASSERT_NE(file_name, std::string::npos);
  quoted.insert(file_name + 11, "O'Brien ");
  test::writeFile(tmp / "quoted.step", quoted);
  r = loadMeshFile(tmp / "quoted.step");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find(": malformed STEP file: entity #1 is defined a second time"), std::string::npos)
      << r.error().message;

  // The fuzzer's shape of it: one name twice and many references to names that do not exist. Open CASCADE alone
  // searches the whole file for each of them (seconds per megabyte, growing with the square of the size).
  std::string many =
      "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\nFILE_NAME('','',(''),(''),'','','');\n"
      "FILE_SCHEMA(('AUTOMOTIVE_DESIGN'));\nENDSEC;\nDATA;\n#1=A(#999999);\n";
  for (int i = 1; i < 20000; ++i) {
    many += "#" + std::to_string(i) + "=A(#" + std::to_string(900000 + i) + ");\n";
  }
  many += "ENDSEC;\nEND-ISO-10303-21;\n";
  test::writeFile(tmp / "many.step", many);
  r = loadMeshFile(tmp / "many.step");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, (tmp / "many.step").string() +
                                   ":9: malformed STEP file: entity #1 is defined a second time (first at line 8)");
}

TEST(CadFile, aValueWithoutItsCommaIsRefusedBeforeOpenCascadeRecoversFromIt) {
  test::TempDir tmp;
  test::writeStep(tmp / "box.step", {{CadShape::kBox, {0, 0, 0}, {1, 1, 1}}});
  const std::string step = test::readFile(tmp / "box.step");
  // A list whose commas are missing (Open CASCADE's recovery costs the square of its length) and binary bytes after
  // a number: both refused at the line they are on.
  std::string spaced = step;
  const size_t end = spaced.rfind("ENDSEC;");
  spaced.insert(end, "#999999 = CARTESIAN_POINT('',(1.5\n2.5 3.5));\n");
  test::writeFile(tmp / "spaced.step", spaced);
  auto r = loadMeshFile(tmp / "spaced.step");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, (tmp / "spaced.step").string() + ":" + std::to_string(lineOf(spaced, "#999999") + 1) +
                                   ": malformed STEP file: another value follows a value where ',' or ')' belongs");

  std::string binary = step;
  binary.insert(binary.rfind("ENDSEC;"), std::string("#999999 = CARTESIAN_POINT('',(1.5\xab\x00, 2.));\n", 43));
  test::writeFile(tmp / "binary.step", binary);
  r = loadMeshFile(tmp / "binary.step");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, (tmp / "binary.step").string() + ":" + std::to_string(lineOf(binary, "#999999")) +
                                   ": malformed STEP file: byte 171 follows a value where ',' or ')' belongs");
}

TEST(CadFile, aMissingParameterIsRefusedBeforeOpenCascadeTakesANullEntity) {
  // Found by the fuzzer: with parameters left out (",,") Open CASCADE 7.6 can read a null entity into the model and
  // crash adding it. Refused at the line; an empty list "()" stays allowed (the box itself has them).
  test::TempDir tmp;
  test::writeStep(tmp / "box.step", {{CadShape::kBox, {0, 0, 0}, {1, 1, 1}}});
  const std::string step = test::readFile(tmp / "box.step");
  ASSERT_TRUE(loadMeshFile(tmp / "box.step").ok());
  for (const std::string& hole : {std::string("(1.5,,2.5)"), std::string("(1.5,2.5,)"), std::string("(,1.5,2.5)")}) {
    std::string holed = step;
    holed.insert(holed.rfind("ENDSEC;"), "#999999 = CARTESIAN_POINT('',\n" + hole + ");\n");
    test::writeFile(tmp / "holed.step", holed);
    auto r = loadMeshFile(tmp / "holed.step");
    ASSERT_FALSE(r.ok()) << hole;
    const std::string sep = hole[1] == ',' ? "(" : ",";
    EXPECT_EQ(r.error().message, (tmp / "holed.step").string() + ":" + std::to_string(lineOf(holed, "#999999") + 1) +
                                     ": malformed STEP file: a parameter is missing after '" + sep +
                                     "' (write $ for one left out)")
        << hole;
  }
}

TEST(CadFile, anOrientedEdgeLeadingRoundToItselfIsRefused) {
  // Found by the fuzzer: Open CASCADE follows oriented edges by recursion and overflows the stack on a cycle.
  test::TempDir tmp;
  test::writeStep(tmp / "box.step", {{CadShape::kBox, {0, 0, 0}, {1, 1, 1}}});
  std::string step = test::readFile(tmp / "box.step");
  const size_t at = step.find("ORIENTED_EDGE('',*,*,#");
  ASSERT_NE(at, std::string::npos);
  const size_t name_at = step.rfind('#', at);
  const std::string self = step.substr(name_at, step.find_first_of(" =", name_at) - name_at);
  const size_t ref = at + std::string("ORIENTED_EDGE('',*,*,").size();
  step.replace(ref, step.find(',', ref) - ref, self);
  test::writeFile(tmp / "cycle.step", step);
  auto r = loadMeshFile(tmp / "cycle.step");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().message, (tmp / "cycle.step").string() + ": malformed STEP file: the oriented edge " + self +
                                   " leads round to itself through its edge elements");
}

TEST(CadFile, namesInStringsAndCommentsAreNotDefinitions) {
  test::TempDir tmp;
  test::writeStep(tmp / "box.step", {{CadShape::kBox, {0, 0, 0}, {1, 1, 1}}});
  std::string step = test::readFile(tmp / "box.step");
  // A comment and a string that read like a second #1, and a string with an apostrophe and a ';' in it.
  const size_t data = step.find("DATA;");
  ASSERT_NE(data, std::string::npos);
  step.insert(data + 5, "\n/* #1 = NOT_AN_ENTITY(); */\n");
  const size_t description = step.find("FILE_DESCRIPTION(('");
  ASSERT_NE(description, std::string::npos);
  step.insert(description + 19, "it''s; #1 = not one either");
  test::writeFile(tmp / "quoted.step", step);
  const MeshFileLoad m = loadOk(tmp / "quoted.step");
  EXPECT_EQ(m.bodies.size(), 1u);
  EXPECT_FALSE(m.mesh.triangles.empty());
}

TEST(CadFile, bytesInMemoryReadAsTheFileDoes) {
  test::TempDir tmp;
  test::writeStep(tmp / "c.step", {{CadShape::kCylinder, {0, 0, 0}, {3, 0, 4}}});
  test::writeIgesFaces(tmp / "c.iges", {{CadShape::kCylinder, {0, 0, 0}, {3, 0, 4}}});
  for (const char* name : {"c.step", "c.iges"}) {
    const std::string s = test::readFile(tmp / name);
    auto from_memory = parseMeshFile(std::vector<uint8_t>(s.begin(), s.end()), name);
    ASSERT_TRUE(from_memory.ok()) << from_memory.error().message;
    const MeshFileLoad from_file = loadOk(tmp / name);
    EXPECT_EQ(from_memory->mesh.triangles.size(), from_file.mesh.triangles.size()) << name;
    EXPECT_EQ(from_memory->mesh.bounds().max, from_file.mesh.bounds().max) << name;
  }
}

}  // namespace
}  // namespace vox::io
