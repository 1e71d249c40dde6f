#pragma once
// A STEP file (ISO 10303-21) checked before Open CASCADE reads it, for what its reader handles badly:
// - a file cut short: Open CASCADE keeps what it parsed, so a STEP file must end with "END-ISO-10303-21;";
// - an entity instance name defined twice (#12 = ... twice). Open CASCADE 7.6 refuses such a file too, but only after
//   a second resolution pass (StepData_StepReaderData::SetEntityNumbers) that searches the whole file for every
//   reference it cannot resolve through its map: quadratic in the file's size, and in a fuzzing session the same
//   malformed file took from 30 ms to over 25 s there, depending on what the process had read before
//   (found by tests/fuzz/fuzz_mesh_file.cpp). voxmod refuses a name defined twice even inside &SCOPE blocks, where
//   Open CASCADE would accept it: no exporter of the CAD files voxmod reads writes scopes.
// - a value followed by another value or by bytes that are not STEP (a list whose commas are missing, binary data
//   spliced into the file): Open CASCADE's recovery from that syntax error costs time and memory growing with the
//   square of what follows (40,000 numbers separated by spaces: 7.6 s and 5.2 GB), where a file without the error
//   reads in a fraction of a second.
// The walk reads tokens as Open CASCADE's lexer does (see step_check.cpp); it is not a parser: the grammar is left to
// Open CASCADE, which refuses every file with a syntax error anyway (io/cad_read.cpp).
#include <cstdint>
#include <span>
#include <string>

#include "vox/core/result.h"

namespace vox::io {

// Errors (kParse) name the file and, for a name defined twice, the line: "part.step:1210: malformed STEP file:
// entity #12 is defined a second time (first at line 40)".
Status checkStep(std::span<const uint8_t> bytes, const std::string& name);

}  // namespace vox::io
