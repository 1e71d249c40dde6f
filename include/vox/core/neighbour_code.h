#pragma once
// Face-neighbour codes (thesis section 5.1) and the classic intensity table (thesis Table 5.2), as docs/conventions.md
// states them ("Face-neighbour code", "Classic intensity table"). The bit layout is defined here and nowhere else.
#include <array>
#include <cstdint>

namespace vox {

// Bit values of the 6-bit face-neighbour code, thesis order 1..6 with the first neighbour most significant.
inline constexpr uint8_t kCodeYMinus = 32;
inline constexpr uint8_t kCodeXMinus = 16;
inline constexpr uint8_t kCodeXPlus = 8;
inline constexpr uint8_t kCodeYPlus = 4;
inline constexpr uint8_t kCodeZMinus = 2;
inline constexpr uint8_t kCodeZPlus = 1;
inline constexpr uint8_t kCodeInterior = 63;

// Number of free (empty) faces of a voxel with this code.
constexpr int freeFaces(uint8_t code) { return 6 - __builtin_popcount(code & 63u); }

// Classic intensities on a 0..20 scale, index = code (docs/conventions.md, "Classic intensity table"). Code 63
// (interior, never drawn) is 0. The printed table lists code 2 twice and omits 28; the second "2" is 28. Code 0
// (isolated voxel) is 20.
inline constexpr std::array<uint8_t, 64> kClassicIntensity = {
    20, 12, 20, 14, 10, 16, 18, 16,  //  0.. 7
    14, 12, 16, 12, 20, 13, 10, 12,  //  8..15
    20, 14, 20, 14, 14, 15, 13, 14,  // 16..23
    16, 12, 16, 12, 20, 10, 10, 12,  // 24..31
    20, 14, 20, 14, 18, 16, 18, 16,  // 32..39
    16, 15, 15, 16, 20, 13, 13, 13,  // 40..47
    20, 15, 20, 18, 14, 19, 19, 16,  // 48..55
    16, 18, 18, 18, 20, 16, 17, 0,   // 56..63
};
inline constexpr int kClassicIntensityMax = 20;

// Classic intensity of a code, 0..20.
constexpr int classicIntensity(uint8_t code) { return kClassicIntensity[code & 63u]; }

}  // namespace vox
