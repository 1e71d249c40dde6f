#pragma once
// A STEP file (ISO 10303-21) checked before Open CASCADE reads it, for what its reader handles badly:
// - a file cut short: Open CASCADE keeps what it parsed, so a STEP file must end with "END-ISO-10303-21;";
// - an entity instance name defined twice (#12 = ... twice). Open CASCADE 7.6 refuses such a file too, but only after
//   a second resolution pass that searches the whole file for every reference it cannot resolve through its map:
//   quadratic, 4 s for a 1 MB file and minutes for larger ones (found by tests/fuzz/fuzz_mesh_file.cpp).
// The walk knows only what it needs: strings ('...' with '' inside), comments (/* ... */) and statements ending with
// ';'. A file with scopes (&SCOPE ... ENDSCOPE, where the same name may be defined in different scopes) is left to
// Open CASCADE.
#include <cstdint>
#include <span>
#include <string>

#include "vox/core/result.h"

namespace vox::io {

// Errors (kParse) name the file and, for a name defined twice, the line: "part.step:1210: malformed STEP file:
// entity #12 is defined a second time (first at line 40)".
Status checkStep(std::span<const uint8_t> bytes, const std::string& name);

}  // namespace vox::io
