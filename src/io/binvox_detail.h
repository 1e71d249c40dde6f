#pragma once
// What the .binvox encoder (binvox.cpp) shares with the streamed converter from .vxm (binvox_stream.cpp): the
// header, the runs, and the 64 x 64 bit transpose that turns x rows into y columns. Private to io.
#include <algorithm>
#include <cstdint>
#include <string>

#include "io/voxel_file_common.h"
#include "vox/core/voxel_grid.h"

namespace vox::io::binvox_detail {

using voxel_file_detail::Writer;

// Transposes a 64 x 64 bit matrix in place: afterwards bit c of a[r] is what bit r of a[c] was.
void transpose64(uint64_t* a);

// The ASCII header of a grid of these dims and frame, through its "data" line (D = the largest dim).
std::string binvoxHeader(const Dims& dims, const GridFrame& frame);

// (value, count) byte pairs with counts of at most 255, merging adjacent runs of one value.
class BinvoxRuns {
 public:
  explicit BinvoxRuns(Writer& out) : out_(out) {}
  void add(bool filled, uint64_t n) {
    if (n == 0) return;
    if (uint8_t(filled) != value_) {
      flush();
      value_ = uint8_t(filled);
    }
    run_ += n;
  }
  void flush() {
    while (run_ > 0) {
      const uint64_t piece = std::min<uint64_t>(run_, 255);
      out_.pair(value_, uint8_t(piece));
      run_ -= piece;
    }
  }

 private:
  Writer& out_;
  uint8_t value_ = 0;
  uint64_t run_ = 0;
};

}  // namespace vox::io::binvox_detail
