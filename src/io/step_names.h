#pragma once
// The names a STEP file gives its solids: the product each solid's shape belongs to ("bolt", "l-bracket").
#include <string>
#include <utility>
#include <vector>

#include <STEPControl_Reader.hxx>
#include <TopoDS_Shape.hxx>

namespace vox::io {

// After TransferRoots: each solid the transfer made from a solid B-rep of the file (as made, before its instances are
// placed), with the name of the product whose shape representation holds it; solids of unnamed products are left out.
std::vector<std::pair<TopoDS_Shape, std::string>> stepSolidNames(const STEPControl_Reader& reader);

}  // namespace vox::io
