#pragma once
// CAD parts made in the tests with Open CASCADE's primitives (BRepPrimAPI) and written with its STEP and IGES
// writers, so the readers are tested on files whose exact geometry is known.
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace vox::test {

// Which solid: a box [corner, corner + size]; a cylinder about the Z axis through `corner` (x, y), from z =
// corner.z up by size.z, radius size.x; a sphere about `corner`, radius size.x; the box's faces without its top
// (an open surface, not a solid); a torus about the Z axis through `corner`, ring radius size.x, tube radius size.y.
enum class CadShape { kBox, kCylinder, kSphere, kOpenBox, kTorus };

struct CadPart {
  CadShape shape = CadShape::kBox;
  glm::dvec3 corner{0.0};
  glm::dvec3 size{1.0};
  std::string name{};  // STEP: the name of the part's product (empty: none)
};

// Writes the parts as one STEP file (each part its own solid), lengths in `unit` ("MM", "INCH", "M"; the parts'
// numbers are millimetres and the writer converts them), in `schema` (Open CASCADE's write.step.schema: "AP214IS",
// "AP203", "AP242DIS"). Fails the calling test on an error.
void writeStep(const std::filesystem::path& path, const std::vector<CadPart>& parts, const char* unit = "MM",
               const char* schema = "AP214IS");
// Writes the parts as an IGES surface model: trimmed surfaces only, no solid entity (IGES "faces" mode), mm.
void writeIgesFaces(const std::filesystem::path& path, const std::vector<CadPart>& parts);

}  // namespace vox::test
