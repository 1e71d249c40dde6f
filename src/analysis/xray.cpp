// X-ray scan (thesis 5.2.3, 6.5): R^2 rays parallel to a coordinate axis; per ray the minimum, maximum or total
// length of the filled runs ("section thicknesses") along it. Runs are found from word masks, never voxel by voxel:
//  - rays along X are rows: run starts are filled & ~(x-1 filled), run ends filled & ~(x+1 filled);
//  - rays along Y and Z cross rows or layers: a run starts where a row (layer) has a bit its predecessor lacks and
//    ends where it loses one, so prev ^ cur marks every boundary and whole words without a boundary are skipped.
// The cost is O(words + run boundaries); rays along X and Y split over Z, rays along Z over Y.
#include <algorithm>
#include <bit>
#include <cctype>
#include <climits>
#include <cstdio>
#include <string>

#include "analysis/layer_ops.h"
#include "vox/core/parallel.h"
#include "vox/analysis/analysis.h"

namespace vox {
namespace {

// Folds one run length into a ray's value. 0 means "no run yet"; runs are at least one voxel long.
struct Accumulate {
  XrayMode mode;
  void operator()(int32_t& acc, int32_t len) const {
    switch (mode) {
      case XrayMode::kMin:
        acc = acc == 0 ? len : std::min(acc, len);
        break;
      case XrayMode::kMax:
        acc = std::max(acc, len);
        break;
      case XrayMode::kTotal:
        acc += len;
        break;
    }
  }
};

// Rays along X: one per row (y, z). Image x right = y, up = z.
// rays_hit, min, max and mean from the image.
void xrayStatistics(XrayResult& r);

void raysAlongX(const VoxelGrid& g, Accumulate acc, Image2D<int32_t>& img) {
  const int64_t wpr = g.wordsPerRow();
  const int threads = threadsFor(g.allocatedLayers() * g.wordsPerLayer());
  parallelChunks(0, g.nz(), 4, threads, [&](int, int64_t z0, int64_t z1) {
    for (int32_t z = int32_t(z0); z < int32_t(z1); ++z) {
      if (!g.layerAllocated(z)) continue;
      int32_t* out = &img.at(0, g.nz() - 1 - z);
      for (int32_t y = 0; y < g.ny(); ++y) {
        const uint64_t* row = g.rowWords(y, z);
        int32_t value = 0;
        if (acc.mode == XrayMode::kTotal) {
          for (int64_t w = 0; w < wpr; ++w) value += analysis_detail::popcount64(row[w]);
        } else {
          int64_t start = 0;
          for (int64_t w = 0; w < wpr; ++w) {
            const uint64_t c = row[w];
            if (!c) continue;
            const uint64_t prev = w > 0 ? row[w - 1] : 0;
            const uint64_t next = w + 1 < wpr ? row[w + 1] : 0;
            const uint64_t starts = c & ~((c << 1) | (prev >> 63));
            const uint64_t ends = c & ~((c >> 1) | (next << 63));
            for (uint64_t m = starts | ends; m; m &= m - 1) {
              const int b = std::countr_zero(m);
              const int64_t pos = w * 64 + b;
              if ((starts >> b) & 1) start = pos;  // a one-voxel run starts and ends at the same bit
              if ((ends >> b) & 1) acc(value, int32_t(pos - start + 1));
            }
          }
        }
        out[y] = value;
      }
    }
  });
}

// Rays along Y: for each layer z, one ray per x, following the rows y = 0 .. ny (row ny is padding and closes
// every run). Image x right = x, up = z.
void raysAlongY(const VoxelGrid& g, Accumulate acc, Image2D<int32_t>& img) {
  const int64_t wpr = g.wordsPerRow();
  const int threads = threadsFor(g.allocatedLayers() * g.wordsPerLayer());
  std::vector<std::vector<int32_t>> start_buf(static_cast<size_t>(threads)), value_buf(static_cast<size_t>(threads));
  parallelChunks(0, g.nz(), 4, threads, [&](int t, int64_t z0, int64_t z1) {
    std::vector<int32_t>& start = start_buf[size_t(t)];
    std::vector<int32_t>& value = value_buf[size_t(t)];
    start.assign(size_t(wpr) * 64, 0);
    for (int32_t z = int32_t(z0); z < int32_t(z1); ++z) {
      if (!g.layerAllocated(z)) continue;
      value.assign(size_t(wpr) * 64, 0);
      for (int32_t y = 0; y <= g.ny(); ++y) {
        const uint64_t* prev = g.rowWords(y - 1, z);
        const uint64_t* cur = g.rowWords(y, z);
        for (int64_t w = 0; w < wpr; ++w) {
          const uint64_t changed = prev[w] ^ cur[w];
          for (uint64_t m = changed; m; m &= m - 1) {
            const int b = std::countr_zero(m);
            const size_t pos = size_t(w * 64 + b);
            if ((cur[w] >> b) & 1) {
              start[pos] = y;
            } else {
              acc(value[pos], y - start[pos]);
            }
          }
        }
      }
      int32_t* out = &img.at(0, g.nz() - 1 - z);
      for (int32_t x = 0; x < g.nx(); ++x) out[x] = value[size_t(x) + 1];
    }
  });
}

// Rays along Z: one per (x, y), following the layers z = 0 .. nz (layer nz is padding). Split over rows y; each
// chunk of rows walks all layers. Image x right = x, up = y.
// The boundary between layers z - 1 (`prev`, a row) and z (`cur`) of the rays of one row along Z: a run starts
// where cur is filled and prev not, and one ends (its length accumulated) where prev is filled and cur not.
void zBoundary(const uint64_t* prev, const uint64_t* cur, int64_t wpr, int32_t z, Accumulate acc, int32_t* st,
               int32_t* val) {
  for (int64_t w = 0; w < wpr; ++w) {
    for (uint64_t m = prev[w] ^ cur[w]; m; m &= m - 1) {
      const int b = std::countr_zero(m);
      const int64_t pos = w * 64 + b;
      if ((cur[w] >> b) & 1) {
        st[pos] = z;
      } else {
        acc(val[pos], z - st[pos]);
      }
    }
  }
}

void raysAlongZ(const VoxelGrid& g, Accumulate acc, Image2D<int32_t>& img) {
  const int64_t wpr = g.wordsPerRow();
  const int64_t bits = wpr * 64;
  constexpr int64_t kRowsPerChunk = 32;
  const int threads = threadsFor(g.allocatedLayers() * g.wordsPerLayer());
  parallelChunks(0, g.ny(), kRowsPerChunk, threads, [&](int, int64_t y0, int64_t y1) {
    const int64_t rows = y1 - y0;
    std::vector<int32_t> start(size_t(rows * bits), 0), value(size_t(rows * bits), 0);
    for (int32_t z = 0; z <= g.nz(); ++z) {
      if (!g.layerAllocated(z) && !g.layerAllocated(z - 1)) continue;  // no boundary between two empty layers
      for (int64_t r = 0; r < rows; ++r) {
        zBoundary(g.rowWords(int32_t(y0 + r), z - 1), g.rowWords(int32_t(y0 + r), z), wpr, z, acc,
                  start.data() + r * bits, value.data() + r * bits);
      }
    }
    for (int64_t r = 0; r < rows; ++r) {
      int32_t* out = &img.at(0, g.ny() - 1 - int32_t(y0 + r));
      const int32_t* val = value.data() + r * bits;
      for (int32_t x = 0; x < g.nx(); ++x) out[x] = val[x + 1];
    }
  });
}

}  // namespace

Result<XrayResult> computeXray(const VoxelGrid& grid, const XrayParams& params) {
  if (grid.empty()) return makeError(ErrorCode::kInvalidArgument, "X-ray of an empty grid (no dimensions)");
  XrayResult r;
  r.axis = params.axis;
  r.mode = params.mode;
  r.voxel_size = grid.voxelSize();
  r.units = grid.frame().units;
  const Accumulate acc{params.mode};
  switch (params.axis) {
    case Axis::kX:
      r.thickness = Image2D<int32_t>(grid.ny(), grid.nz(), 0);
      raysAlongX(grid, acc, r.thickness);
      break;
    case Axis::kY:
      r.thickness = Image2D<int32_t>(grid.nx(), grid.nz(), 0);
      raysAlongY(grid, acc, r.thickness);
      break;
    case Axis::kZ:
      r.thickness = Image2D<int32_t>(grid.nx(), grid.ny(), 0);
      raysAlongZ(grid, acc, r.thickness);
      break;
  }
  xrayStatistics(r);
  return r;
}

XrayAccumulator::XrayAccumulator(const Dims& dims, const GridFrame& frame, const XrayParams& params) : dims_(dims) {
  r_.axis = params.axis;
  r_.mode = params.mode;
  r_.voxel_size = frame.voxel_size;
  r_.units = frame.units;
  const int32_t width = params.axis == Axis::kX ? dims.ny : dims.nx;
  const int32_t height = params.axis == Axis::kZ ? dims.ny : dims.nz;
  r_.thickness = Image2D<int32_t>(width, height, 0);
  if (params.axis == Axis::kZ) {
    const size_t bits = size_t(VoxelGrid(Dims{dims.nx, 1, 1}).wordsPerRow()) * 64;
    start_.assign(bits * size_t(dims.ny), 0);
    value_.assign(bits * size_t(dims.ny), 0);
  }
}

void XrayAccumulator::add(const VoxelGrid& g, int32_t z0, int32_t z1, int32_t z_offset) {
  const Accumulate acc{r_.mode};
  if (r_.axis != Axis::kZ) {
    // Rays along X and Y lie within a layer: the window's own image, whose rows go where their layers belong.
    Image2D<int32_t> img(r_.thickness.width, g.nz(), 0);
    if (r_.axis == Axis::kX) raysAlongX(g, acc, img);
    if (r_.axis == Axis::kY) raysAlongY(g, acc, img);
    for (int32_t z = z0; z < z1; ++z) {
      std::copy_n(&img.at(0, g.nz() - 1 - z), img.width, &r_.thickness.at(0, dims_.nz - 1 - (z + z_offset)));
    }
    return;
  }
  // Along Z: the boundaries below each layer, and above the model's last one (the window's padding layer).
  const int64_t wpr = g.wordsPerRow(), bits = wpr * 64;
  const int32_t last = z1 + z_offset == dims_.nz ? z1 : z1 - 1;
  const int threads = threadsFor(g.allocatedLayers() * g.wordsPerLayer());
  parallelChunks(0, g.ny(), 32, threads, [&](int, int64_t y0, int64_t y1) {
    for (int32_t z = z0; z <= last; ++z) {
      if (!g.layerAllocated(z) && !g.layerAllocated(z - 1)) continue;
      for (int64_t y = y0; y < y1; ++y) {
        zBoundary(g.rowWords(int32_t(y), z - 1), g.rowWords(int32_t(y), z), wpr, z + z_offset, acc,
                  start_.data() + y * bits, value_.data() + y * bits);
      }
    }
  });
}

XrayResult XrayAccumulator::result() {
  if (r_.axis == Axis::kZ) {
    const int64_t bits = int64_t(start_.size()) / std::max<int64_t>(dims_.ny, 1);
    for (int32_t y = 0; y < dims_.ny; ++y) {
      int32_t* out = &r_.thickness.at(0, dims_.ny - 1 - y);
      for (int32_t x = 0; x < dims_.nx; ++x) out[x] = value_[size_t(y * bits + x + 1)];
    }
  }
  xrayStatistics(r_);
  return r_;
}

namespace {

void xrayStatistics(XrayResult& r) {
  int64_t sum = 0;
  int64_t lo = INT64_MAX, hi = 0;
  for (int32_t v : r.thickness.pixels) {
    if (v == 0) continue;
    ++r.rays_hit;
    sum += v;
    lo = std::min<int64_t>(lo, v);
    hi = std::max<int64_t>(hi, v);
  }
  if (r.rays_hit > 0) {
    r.min = lo;
    r.max = hi;
    r.mean = double(sum) / double(r.rays_hit);
  }
}

}  // namespace

std::string xrayCsv(const XrayResult& xray) {
  // Units go into a column name: keep it to letters, digits and '_'.
  std::string units = xray.units.empty() ? "model" : xray.units;
  for (char& c : units) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  std::string out = "u,v,thickness_voxels,thickness_" + units + "\n";
  const Image2D<int32_t>& t = xray.thickness;
  out.reserve(out.size() + size_t(xray.rays_hit) * 28);
  char line[96];
  // v is the image's "up" index (row 0 at the top holds the largest), so walk rows bottom-up for ascending v.
  for (int32_t v = 0; v < t.height; ++v) {
    const int32_t row = t.height - 1 - v;
    for (int32_t u = 0; u < t.width; ++u) {
      const int32_t d = t.at(u, row);
      if (d == 0) continue;
      const int n = std::snprintf(line, sizeof line, "%d,%d,%d,%.10g\n", u, v, d, double(d) * xray.voxel_size);
      out.append(line, size_t(n));
    }
  }
  return out;
}

ScalarMapLegend xrayLegend(const XrayResult& xray) {
  const double h = xray.voxel_size;
  ScalarMapLegend l;
  l.title = std::string("X-ray along ") + axisName(xray.axis) + ": " + xrayModeName(xray.mode) + " thickness per ray";
  l.value_name = "voxels";
  l.units_per_value = h;
  l.units = xray.units.empty() || xray.units == "model" ? "model units" : xray.units;
  l.right_axis = axisName(imageRightAxis(xray.axis));
  l.up_axis = axisName(imageUpAxis(xray.axis));
  char buf[200];
  if (xray.rays_hit == 0) {
    l.notes.push_back("No ray hits material.");
    return l;
  }
  std::snprintf(buf, sizeof buf, "%lld rays hit material: min %lld, max %lld, mean %.2f voxels",
                static_cast<long long>(xray.rays_hit), static_cast<long long>(xray.min),
                static_cast<long long>(xray.max), xray.mean);
  l.notes.push_back(buf);
  std::snprintf(buf, sizeof buf, "min %.4g, max %.4g, mean %.4g %s (voxel size %.4g %s)", double(xray.min) * h,
                double(xray.max) * h, xray.mean * h, l.units.c_str(), h, l.units.c_str());
  l.notes.push_back(buf);
  return l;
}

}  // namespace vox
