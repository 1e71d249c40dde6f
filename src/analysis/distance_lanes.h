#pragma once
// The distance transform's vector steps (analysis/distance.cpp's Y and Z passes over a tile of 64 lines side by
// side), taken where the processor has AVX2; elsewhere the passes take every site and write line by line.
//
// Sites an envelope can do without. Along a line with values h, site r's parabola is (p - r)^2 + h(r). A site that,
// at every integer p, some other site of the line beats strictly is the lowest nowhere: leaving it out of the
// envelope changes no value, and every site that is lowest somewhere (with its ties) stays. The test compares site q
// with the sites k = 1, 2, 4 and 8 steps before and after it. Site q - k beats q at p = q + d exactly when
// 2kd + k^2 + h(q - k) - h(q) < 0, that is for every d <= -floor((h(q - k) + k^2 - h(q)) / 2k) - 1, and site q + k
// beats it for every d >= floor((h(q + k) + k^2 - h(q)) / 2k) + 1; with L and R the least of those floors over k,
// the sites before and after cover every integer d when L + R < 0. Divisions by 2k are arithmetic shifts, and the
// values (squared distances in a grid whose sides are at most VoxelGrid::kMaxDim, under 2^28) keep every sum inside
// 32 bits. On a solid part most sites are of that kind, and the envelope's sweep no longer pushes and hides them one
// by one.
//
// Eight lines written at once. The envelopes of eight neighbouring lines mark the step at which each of their
// parabolas starts being lowest; one sweep along the lines then carries each lane's lowest parabola forward and
// writes (q - site)^2 + value for the eight lanes, which lie side by side in the tile, with one store.
#include <climits>
#include <cstdint>

namespace vox::analysis_detail {

// A tile of kLanes lines side by side: the value of line j at step q is rows[q * kLanes + j], for q in
// [-kSitePad, len + kSitePad); the kSitePad steps past each end hold the values there (zeros for a distance line,
// whose ends are empty voxels).
inline constexpr int64_t kLanes = 64;
inline constexpr int64_t kSitePad = 8;

// Whether the vector steps run (the processor has AVX2, and no test has turned them off).
bool vectorLanes();
// Tests: false runs the passes as a processor without AVX2 does.
void setVectorLanes(bool on);

// For each step q in [0, len): keep[q] = masks[q] without the bits of the lines whose site at q other sites beat
// everywhere (above). Lines whose masks bit is clear are not looked at. Without the vector steps, keep = masks.
void keepSites(const uint32_t* rows, int64_t len, const uint64_t* masks, uint64_t* keep);
// The same test one lane at a time, on any processor (the tests' reference).
void keepSitesScalar(const uint32_t* rows, int64_t len, const uint64_t* masks, uint64_t* keep);

// Lines j0 .. j0 + 7 of the tile from their envelopes (vectorLanes() only): starts[8 q + l] is the site of the
// parabola of line j0 + l that is lowest from step q on (kNoStart where none starts at q: the one before stays
// lowest), values[8 q + l] that site's value. For each step q in [q0, q1), writes (q - site)^2 + value of each lane's
// lowest parabola into rows[q * kLanes + j0 + l] and puts kNoStart back in starts. A lane's steps before its first
// start, and those after a piece of its line ends, get values that mean nothing (the caller copies out only the
// steps whose masks bit is set). Returns the largest value written at a step whose masks bit is set, or mx when
// that is larger.
inline constexpr int32_t kNoStart = INT32_MIN;
uint32_t writeLanes8(uint32_t* rows, const uint64_t* masks, int32_t* starts, const int32_t* values, int64_t j0,
                     int64_t q0, int64_t q1, uint32_t mx);

}  // namespace vox::analysis_detail
