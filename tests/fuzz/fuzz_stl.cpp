// libFuzzer target: the STL reader (binary and ASCII) must return a value or an error for any bytes, never crash,
// hang or allocate more than the input justifies.
#include <cstddef>
#include <cstdint>

#include "vox/io/stl.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  auto result = vox::io::parseStl({data, size}, "fuzz.stl");
  if (result.ok()) {
    // Every accepted mesh has finite coordinates and at least one triangle.
    if (result->mesh.triangles.empty()) __builtin_trap();
  }
  return 0;
}
