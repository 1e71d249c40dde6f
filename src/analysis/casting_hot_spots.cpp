// The regions of a casting that freeze last (vox/analysis/casting.h, docs/conventions.md "Casting"): a union-find
// over the metal cells taken from the latest to freeze to the earliest, 6-connected (metal feeds through faces).
// When two sets meet at a cell, the one whose peak froze later survives; the other's dip is its peak's time less the
// meeting cell's. A set dipping by at least the tolerance cannot be fed: every path from it to later metal crosses
// metal that froze earlier by that much. One dipping less is fed through the meeting cell (its saddle).
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include "analysis/casting_detail.h"

namespace vox::casting_detail {
namespace {

struct Set {
  int64_t peak = 0;          // cell freezing last
  int64_t voxels = 0;        // cells in the set
  int64_t absorbed_by = -1;  // the set it merged into (a cell index of that set's root at the time)
  int32_t spot = -1;         // index in the list, when listed
};

int64_t findRoot(std::vector<int64_t>& parent, int64_t i) {
  int64_t r = i;
  while (parent[size_t(r)] != r) r = parent[size_t(r)];
  while (parent[size_t(i)] != r) {
    const int64_t next = parent[size_t(i)];
    parent[size_t(i)] = r;
    i = next;
  }
  return r;
}

}  // namespace

std::vector<TimeSpot> findTimeSpots(const Dims& d, const std::vector<uint8_t>& kind, const std::vector<float>& time,
                                    const GridFrame& frame, double abs_tolerance, double rel_tolerance,
                                    int64_t min_voxels) {
  std::vector<int64_t> order;
  for (int64_t i = 0; i < d.count(); ++i)
    if (kind[size_t(i)] & kMetal) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](int64_t a, int64_t b) { return time[size_t(a)] > time[size_t(b)]; });
  const int64_t nx = d.nx, layer = nx * d.ny;
  std::vector<int64_t> parent(size_t(d.count()), -1);  // -1: not reached yet
  std::vector<Set> sets;                               // by root... kept per cell index that started them
  std::vector<int64_t> set_of(size_t(d.count()), -1);  // a root cell's set
  std::vector<TimeSpot> out;
  const auto centre = [&](int64_t i) { return frame.voxelCentre(i % nx, i / nx % d.ny, i / layer); };
  const auto listSpot = [&](Set& s, bool isolated, int64_t saddle, int64_t fed_by_root) {
    TimeSpot t;
    t.cell = s.peak;
    t.spot.centre = centre(s.peak);
    t.spot.solidification_s = time[size_t(s.peak)];
    t.spot.voxels = s.voxels;
    t.spot.isolated = isolated;
    t.spot.in_feeder = (kind[size_t(s.peak)] & kFeeder) != 0;
    if (!isolated) {
      t.spot.saddle = centre(saddle);
      t.fed_by_root = fed_by_root;  // resolved to a spot below
    }
    s.spot = int32_t(out.size());
    out.push_back(t);
  };
  for (const int64_t i : order) {
    parent[size_t(i)] = i;
    const int64_t x = i % nx, y = i / nx % d.ny, z = i / layer;
    const int64_t nb[6] = {x > 0 ? i - 1 : -1,         x + 1 < nx ? i + 1 : -1, y > 0 ? i - nx : -1,
                           y + 1 < d.ny ? i + nx : -1, z > 0 ? i - layer : -1,  z + 1 < d.nz ? i + layer : -1};
    int64_t root = -1;  // the set i joins: the latest peak about it
    for (const int64_t q : nb) {
      if (q < 0 || parent[size_t(q)] < 0) continue;
      const int64_t r = findRoot(parent, q);
      if (r == root) continue;
      if (root < 0) {
        root = r;
        continue;
      }
      Set& a = sets[size_t(set_of[size_t(root)])];
      Set& b = sets[size_t(set_of[size_t(r)])];
      const bool a_wins = time[size_t(a.peak)] > time[size_t(b.peak)] ||
                          (time[size_t(a.peak)] == time[size_t(b.peak)] && a.peak < b.peak);
      Set& loser = a_wins ? b : a;
      Set& winner = a_wins ? a : b;
      const int64_t winner_root = a_wins ? root : r, loser_root = a_wins ? r : root;
      const double peak = time[size_t(loser.peak)];
      const double dip = peak - double(time[size_t(i)]);
      if (dip >= std::max(abs_tolerance, rel_tolerance * peak)) {
        listSpot(loser, true, i, -1);
      } else if (loser.voxels >= min_voxels) {
        listSpot(loser, false, i, winner_root);
      }
      loser.absorbed_by = winner_root;
      winner.voxels += loser.voxels;
      parent[size_t(loser_root)] = winner_root;
      root = winner_root;
    }
    if (root < 0) {  // a new maximum
      set_of[size_t(i)] = int64_t(sets.size());
      sets.push_back(Set{i, 1, -1, -1});
    } else {
      parent[size_t(i)] = root;
      ++sets[size_t(set_of[size_t(root)])].voxels;
    }
  }
  for (size_t k = 0; k < sets.size(); ++k) {  // the survivors: the latest of each connected piece of metal
    if (sets[k].absorbed_by < 0) listSpot(sets[k], true, 0, -1);
  }
  // A fed spot's feeder: the listed isolated spot its surviving set ended in.
  for (TimeSpot& t : out) {
    if (t.spot.isolated) continue;
    int64_t r = t.fed_by_root;
    for (;;) {
      const Set& s = sets[size_t(set_of[size_t(r)])];
      if (s.spot >= 0 && out[size_t(s.spot)].spot.isolated) {
        t.spot.fed_by = s.spot;
        break;
      }
      r = s.absorbed_by;
    }
  }
  // Latest first, fed_by renumbered.
  std::vector<int32_t> rank(out.size());
  std::iota(rank.begin(), rank.end(), 0);
  std::stable_sort(rank.begin(), rank.end(), [&](int32_t a, int32_t b) {
    return out[size_t(a)].spot.solidification_s > out[size_t(b)].spot.solidification_s;
  });
  std::vector<int32_t> position(out.size());
  for (size_t k = 0; k < rank.size(); ++k) position[size_t(rank[k])] = int32_t(k);
  std::vector<TimeSpot> sorted;
  for (const int32_t k : rank) {
    sorted.push_back(out[size_t(k)]);
    if (sorted.back().spot.fed_by >= 0) sorted.back().spot.fed_by = position[size_t(sorted.back().spot.fed_by)];
  }
  return sorted;
}

}  // namespace vox::casting_detail
