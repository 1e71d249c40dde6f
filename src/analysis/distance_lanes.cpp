// The sites a distance line's lower envelope can do without, see analysis/distance_lanes.h.
#include "analysis/distance_lanes.h"

#include <algorithm>
#include <atomic>
#include <bit>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define VOX_DISTANCE_LANES_X86 1
#include <immintrin.h>
#else
#define VOX_DISTANCE_LANES_X86 0
#endif

namespace vox::analysis_detail {

namespace {

constexpr int kSteps[] = {1, 2, 4, 8};  // k; the floor of a division by 2k is a shift by 1 + log2(k)
static_assert(kSteps[3] <= kSitePad);

// Site q of line j: beaten at every integer position by the sites k before and after it (the header's test).
inline bool beatenScalar(const uint32_t* rows, int64_t q, int64_t j) {
  const auto h = int32_t(rows[q * kLanes + j]);
  int32_t l = INT32_MAX, r = INT32_MAX;
  for (int k : kSteps) {
    const int shift = 1 + std::countr_zero(unsigned(k));
    l = std::min(l, (int32_t(rows[(q - k) * kLanes + j]) + k * k - h) >> shift);
    r = std::min(r, (int32_t(rows[(q + k) * kLanes + j]) + k * k - h) >> shift);
  }
  return l + r < 0;
}

#if VOX_DISTANCE_LANES_X86
__attribute__((target("avx2"))) inline __m256i load8(const uint32_t* rows, int64_t q, int64_t j0) {
  return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(rows + q * kLanes + j0));
}

// Step k of the test for eight lanes: l and r take the floors of the sites k before and after.
template <int kK>
__attribute__((target("avx2"))) inline void step8(const uint32_t* rows, int64_t q, int64_t j0, __m256i h, __m256i& l,
                                                  __m256i& r) {
  constexpr int kShift = 1 + std::countr_zero(unsigned(kK));
  const __m256i c = _mm256_sub_epi32(_mm256_set1_epi32(kK * kK), h);
  l = _mm256_min_epi32(l, _mm256_srai_epi32(_mm256_add_epi32(load8(rows, q - kK, j0), c), kShift));
  r = _mm256_min_epi32(r, _mm256_srai_epi32(_mm256_add_epi32(load8(rows, q + kK, j0), c), kShift));
}

// Eight lanes at a time: the bits of lanes j0 .. j0 + 7 at step q (kSteps, unrolled).
__attribute__((target("avx2"))) inline unsigned beaten8(const uint32_t* rows, int64_t q, int64_t j0) {
  static_assert(sizeof(kSteps) / sizeof(kSteps[0]) == 4 && kSteps[0] == 1 && kSteps[1] == 2 && kSteps[2] == 4 &&
                kSteps[3] == 8);
  const __m256i h = load8(rows, q, j0);
  __m256i l = _mm256_set1_epi32(INT32_MAX), r = l;
  step8<1>(rows, q, j0, h, l, r);
  step8<2>(rows, q, j0, h, l, r);
  step8<4>(rows, q, j0, h, l, r);
  step8<8>(rows, q, j0, h, l, r);
  const __m256i neg = _mm256_cmpgt_epi32(_mm256_setzero_si256(), _mm256_add_epi32(l, r));
  return unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(neg)));
}

__attribute__((target("avx2"))) void keepSitesAvx2(const uint32_t* rows, int64_t len, const uint64_t* masks,
                                                   uint64_t* keep) {
  for (int64_t q = 0; q < len; ++q) {
    const uint64_t m = masks[q];
    uint64_t beaten = 0;
    for (int64_t c = 0; c < kLanes / 8; ++c) {
      if ((m >> (8 * c)) & 0xff) beaten |= uint64_t(beaten8(rows, q, 8 * c)) << (8 * c);
    }
    keep[q] = m & ~beaten;
  }
}

#endif

std::atomic<bool> g_vector_lanes{true};

}  // namespace

bool vectorLanes() {
#if VOX_DISTANCE_LANES_X86
  static const bool has = __builtin_cpu_supports("avx2");
  return has && g_vector_lanes.load(std::memory_order_relaxed);
#else
  return false;
#endif
}

void setVectorLanes(bool on) { g_vector_lanes.store(on, std::memory_order_relaxed); }

#if VOX_DISTANCE_LANES_X86

__attribute__((target("avx2"))) uint32_t writeLanes8(uint32_t* rows, const uint64_t* masks, int32_t* starts,
                                                     const int32_t* values, int64_t j0, int64_t q0, int64_t q1,
                                                     uint32_t mx) {
  const __m256i none = _mm256_set1_epi32(kNoStart), bits = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
  __m256i site = _mm256_setzero_si256(), value = site, best = _mm256_set1_epi32(int32_t(mx));
  for (int64_t q = q0; q < q1; ++q) {
    __m256i* sq = reinterpret_cast<__m256i*>(starts + 8 * q);
    const __m256i s = _mm256_loadu_si256(sq);
    const __m256i v = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(values + 8 * q));
    const __m256i kept = _mm256_cmpeq_epi32(s, none);  // no parabola starts here: the lowest stays
    site = _mm256_blendv_epi8(s, site, kept);
    value = _mm256_blendv_epi8(v, value, kept);
    _mm256_storeu_si256(sq, none);
    const __m256i d = _mm256_sub_epi32(_mm256_set1_epi32(int32_t(q)), site);
    const __m256i out = _mm256_add_epi32(_mm256_mullo_epi32(d, d), value);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(rows + q * kLanes + j0), out);
    const __m256i lane = _mm256_and_si256(_mm256_set1_epi32(int32_t((masks[q] >> j0) & 0xff)), bits);
    best = _mm256_max_epu32(best, _mm256_and_si256(out, _mm256_cmpeq_epi32(lane, bits)));
  }
  alignas(32) uint32_t lanes[8];
  _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), best);
  return *std::max_element(lanes, lanes + 8);
}
#else
uint32_t writeLanes8(uint32_t*, const uint64_t*, int32_t*, const int32_t*, int64_t, int64_t, int64_t, uint32_t mx) {
  return mx;  // not called: vectorLanes() is false
}
#endif

void keepSitesScalar(const uint32_t* rows, int64_t len, const uint64_t* masks, uint64_t* keep) {
  for (int64_t q = 0; q < len; ++q) {
    uint64_t k = masks[q];
    for (uint64_t m = k; m; m &= m - 1) {
      const int j = std::countr_zero(m);
      k &= ~(uint64_t(beatenScalar(rows, q, j)) << j);
    }
    keep[q] = k;
  }
}

void keepSites(const uint32_t* rows, int64_t len, const uint64_t* masks, uint64_t* keep) {
#if VOX_DISTANCE_LANES_X86
  if (vectorLanes()) {
    keepSitesAvx2(rows, len, masks, keep);
    return;
  }
#endif
  (void)rows;
  std::copy(masks, masks + len, keep);  // one lane at a time the test costs twice what it spares
}

}  // namespace vox::analysis_detail
