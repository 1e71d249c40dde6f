#pragma once
// What a CadModel holds (vox/io/cad.h): the healed Open CASCADE shape in millimetres and what reading found.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <TopoDS_Shape.hxx>

#include "vox/io/cad.h"

namespace vox::io {

struct CadModel::Impl {
  TopoDS_Shape shape;  // solids placed by their instances' locations; loose faces beside them
  Box3d bounds;        // mm
  int64_t solids = 0;
  int64_t loose_faces = 0;
  MeshFormat format = MeshFormat::kUnknown;
  std::string format_detail, file_units, name;
  std::vector<std::string> warnings, notes;
  // STEP: the solids the transfer made with their products' names (io/step_names.h), then, once healed, a name per
  // solid of `shape` in the order TopExp_Explorer meets them (empty where the file names none).
  std::vector<std::pair<TopoDS_Shape, std::string>> named_solids;
  std::vector<std::string> solid_names;
};

}  // namespace vox::io
