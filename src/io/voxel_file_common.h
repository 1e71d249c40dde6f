#pragma once
// What the two voxel file codecs share (vxm.cpp, binvox.cpp): the little-endian byte writer that streams to a
// ByteSink, the CRC-32 it keeps, the memory check made before a decoder allocates, and the run finder over 64-bit
// words. Both codecs work on 64-bit words where the data allows: runs are found with countr_zero on whole words of
// a row, so encoding costs O(words + runs), not O(voxels). Private to the io module.
#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "vox/core/result.h"
#include "vox/core/voxel_grid.h"
#include "vox/io/file_util.h"

namespace vox::io::voxel_file_detail {

// Memory for `layers` allocated Z layers of a grid with dims d, compared with the machine's memory.
// `extra` is working memory the decoder needs besides the grid.
Status checkLayerMemory(const Dims& d, int64_t layers, const std::string& name, uint64_t limit, uint64_t extra = 0);

// CRC-32 of n bytes, continuing from `crc` (the CRC of the bytes before them; 0 to start).
uint32_t crc32Of(const uint8_t* data, size_t n, uint32_t crc_before = 0);

class Writer {
 public:
  Writer() = default;
  // Streaming: whenever a varint leaves more than kChunkBytes buffered, the buffer goes to `sink` (and into the
  // running CRC-32 of everything streamed); flush() sends the rest. The first failure is kept and later data dropped.
  explicit Writer(ByteSink* sink) : sink_(sink) {}
  static constexpr size_t kChunkBytes = size_t(1) << 20;

  std::vector<uint8_t> bytes;
  Status flush() {
    if (!sink_ || !status_.ok() || bytes.empty()) return status_;
    status_ = sink_->append(bytes);
    if (status_.ok()) {
      crc_ = crc32Of(bytes.data(), bytes.size(), crc_);
      streamed_ += bytes.size();
    }
    bytes.clear();
    return status_;
  }
  const Status& status() const { return status_; }
  uint64_t streamed() const { return streamed_; }  // bytes handed to the sink
  uint32_t crc() const { return crc_; }            // their CRC-32
  void u16(uint16_t v) { raw(&v, 2); }
  void u32(uint32_t v) { raw(&v, 4); }
  void u64(uint64_t v) { raw(&v, 8); }
  void f64(double v) { u64(std::bit_cast<uint64_t>(v)); }
  // Two bytes (a binvox run).
  void pair(uint8_t a, uint8_t b) {
    bytes.push_back(a);
    bytes.push_back(b);
    if (sink_ && bytes.size() >= kChunkBytes) (void)flush();  // a failure stays in status()
  }
  void varint(uint64_t v) {
    while (v >= 0x80) {
      bytes.push_back(uint8_t(v | 0x80));
      v >>= 7;
    }
    bytes.push_back(uint8_t(v));
    if (sink_ && bytes.size() >= kChunkBytes) (void)flush();  // a failure stays in status()
  }
  void text(const std::string& s) {
    const size_t n = std::min<size_t>(s.size(), 0xFFFF);  // longer strings are cut; the header field is 16-bit
    u16(uint16_t(n));
    bytes.insert(bytes.end(), s.begin(), s.begin() + std::ptrdiff_t(n));
  }
  void patchU64(size_t at, uint64_t v) { patch(at, &v, 8); }
  void patchU32(size_t at, uint32_t v) { patch(at, &v, 4); }

 private:
  template <class T>
  static T little(T v) {
    if constexpr (std::endian::native == std::endian::big) {
      if constexpr (sizeof(T) == 2) return T(__builtin_bswap16(v));
      if constexpr (sizeof(T) == 4) return T(__builtin_bswap32(v));
      if constexpr (sizeof(T) == 8) return T(__builtin_bswap64(v));
    }
    return v;
  }
  template <class T>
  void raw(const T* v, size_t n) {
    const T le = little(*v);
    const auto* p = reinterpret_cast<const uint8_t*>(&le);
    bytes.insert(bytes.end(), p, p + n);
  }
  template <class T>
  void patch(size_t at, const T* v, size_t n) {
    const T le = little(*v);
    std::memcpy(bytes.data() + at, &le, n);
  }

  ByteSink* sink_ = nullptr;
  Status status_ = Ok{};
  uint64_t streamed_ = 0;
  uint32_t crc_ = 0;
};

// A streaming encoder's output collected in memory (a memory sink does not fail).
std::vector<uint8_t> encodeToMemory(Status (*encode)(const VoxelGrid&, ByteSink&), const VoxelGrid& grid);

// Calls sink.add(value, length) for the runs of the first `nbits` bits of `words` (bit b of word w is element
// 64 w + b). Whole empty or full words cost O(1); otherwise one countr_zero per run. Zero-length runs may be
// passed; sinks ignore them.
template <class Sink>
void emitRuns(const uint64_t* words, int64_t nbits, Sink& sink) {
  bool state = false;
  const int64_t n = (nbits + 63) / 64;
  for (int64_t w = 0; w < n; ++w) {
    const int bits = (w + 1 == n && (nbits & 63)) ? int(nbits & 63) : 64;
    const uint64_t valid = bits == 64 ? ~uint64_t(0) : (uint64_t(1) << bits) - 1;
    int pos = 0;
    while (pos < bits) {
      // Bits that differ from the current state, from pos on: the run of `state` ends at the first of them.
      const uint64_t diff = ((state ? ~words[w] : words[w]) & valid) >> pos;
      const int len = diff == 0 ? bits - pos : std::countr_zero(diff);
      sink.add(state, uint64_t(len));
      pos += len;
      if (pos < bits) state = !state;
    }
  }
}

}  // namespace vox::io::voxel_file_detail
