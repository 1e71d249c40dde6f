// Maps of the distance and thickness fields: a section image with its legend, and whole-grid fields for export.
#include "vox/analysis/thickness_map.h"

#include <cmath>
#include <cstdio>

namespace vox {
namespace {

int32_t along(const Dims& d, Axis a) { return a == Axis::kX ? d.nx : (a == Axis::kY ? d.ny : d.nz); }

// The section `params` names of a grid of dims `dims`, each voxel's thickness in voxels from `voxels(x, y, z)`, in
// tenths of a voxel (0 where it reads 0).
template <class F>
Result<Image2D<int32_t>> tenthsSection(const Dims& dims, const SectionParams& params, F&& voxels) {
  const int a = int(params.axis);
  const int32_t n = along(dims, params.axis);
  if (params.index < 0 || params.index >= n) {
    return makeError(ErrorCode::kInvalidArgument, std::string("section index ") + std::to_string(params.index) +
                                                      " is outside 0.." + std::to_string(n - 1) + " along " +
                                                      axisName(params.axis));
  }
  const int right = int(imageRightAxis(params.axis)), up_axis = int(imageUpAxis(params.axis));
  const int32_t w = along(dims, Axis(right)), h = along(dims, Axis(up_axis));
  Image2D<int32_t> img(w, h, 0);
  for (int32_t row = 0; row < h; ++row) {
    for (int32_t col = 0; col < w; ++col) {
      int32_t v[3] = {0, 0, 0};
      v[a] = params.index;
      v[right] = col;
      v[up_axis] = h - 1 - row;
      const double t = voxels(v[0], v[1], v[2]);
      img.at(col, row) = t > 0.0 ? std::max<int32_t>(1, int32_t(std::lround(t * kThicknessTenths))) : 0;
    }
  }
  return img;
}

}  // namespace

Result<Image2D<int32_t>> thicknessSection(const Thickness& thickness, const SectionParams& params) {
  return tenthsSection(thickness.radius.gridDims(), params,
                       [&](int32_t x, int32_t y, int32_t z) { return thickness.voxels(x, y, z); });
}

Result<Image2D<int32_t>> fieldSection(const ScalarField& field, const SectionParams& params) {
  return tenthsSection(field.dims, params, [&](int32_t x, int32_t y, int32_t z) {
    return double(field.at(x, y, z)) / field.frame.voxel_size;
  });
}

Result<Image2D<int32_t>> scaledSection(const ScalarField& field, const SectionParams& params, double scale) {
  return tenthsSection(field.dims, params, [&](int32_t x, int32_t y, int32_t z) {
    return double(field.at(x, y, z)) * scale / kThicknessTenths;
  });
}

ScalarMapLegend rayThicknessLegend(const ScalarField& field, const SectionParams& params, const std::string& units,
                                   double min, double max, double mean) {
  ScalarMapLegend l;
  l.title = std::string("Ray thickness, section ") + axisName(params.axis) + " = " + std::to_string(params.index);
  l.value_name = "voxels";
  l.units_per_value = field.frame.voxel_size;
  l.value_divisor = kThicknessTenths;
  l.units = units.empty() || units == "model" ? "model units" : units;
  l.right_axis = axisName(imageRightAxis(params.axis));
  l.up_axis = axisName(imageUpAxis(params.axis));
  char buf[200];
  std::snprintf(buf, sizeof buf, "whole part: min %.4g, max %.4g, mean %.4g %s (voxel size %.4g %s)", min, max, mean,
                l.units.c_str(), field.frame.voxel_size, l.units.c_str());
  l.notes.push_back(buf);
  l.notes.push_back("ray thickness: along the inward normal to the opposite wall facing back; blank: no wall");
  return l;
}

ScalarMapLegend thicknessLegend(const Thickness& thickness, const SectionParams& params, const std::string& units) {
  const double h = thickness.radius.voxelSize();
  ScalarMapLegend l;
  l.title = std::string("Local thickness, section ") + axisName(params.axis) + " = " + std::to_string(params.index);
  l.value_name = "voxels";
  l.units_per_value = h;
  l.value_divisor = kThicknessTenths;
  l.units = units.empty() || units == "model" ? "model units" : units;
  l.right_axis = axisName(imageRightAxis(params.axis));
  l.up_axis = axisName(imageUpAxis(params.axis));
  const ThicknessStats& s = thickness.stats;
  char buf[200];
  if (s.voxels == 0) {
    l.notes.push_back("The model is empty.");
    return l;
  }
  std::snprintf(buf, sizeof buf, "whole part: min %.4g, max %.4g, mean %.4g %s (voxel size %.4g %s)", s.min, s.max,
                s.mean, l.units.c_str(), h, l.units.c_str());
  l.notes.push_back(buf);
  l.notes.push_back("thickness: diameter of the largest inscribed ball containing the voxel");
  return l;
}

ScalarField thicknessField(const Thickness& thickness) {
  const DistanceField& r = thickness.radius;
  ScalarField f(r.gridDims(), r.frame(), 0.0f);
  const glm::ivec3 b = r.boxMin();
  const Dims& bd = r.boxDims();
  for (int32_t z = 0; z < bd.nz; ++z) {
    for (int32_t y = 0; y < bd.ny; ++y) {
      for (int32_t x = 0; x < bd.nx; ++x) {
        f.at(b.x + x, b.y + y, b.z + z) = float(thickness.model(b.x + x, b.y + y, b.z + z));
      }
    }
  }
  return f;
}

ScalarField distanceField(const DistanceField& distance, const DistanceField* clearance) {
  const Dims& d = distance.gridDims();
  ScalarField f(d, distance.frame(), 0.0f);
  for (int32_t z = 0; z < d.nz; ++z) {
    for (int32_t y = 0; y < d.ny; ++y) {
      for (int32_t x = 0; x < d.nx; ++x) {
        const double in = distance.model(x, y, z);
        if (in > 0.0) {
          f.at(x, y, z) = float(in);
        } else if (clearance) {
          const double out = clearance->model(x, y, z);
          f.at(x, y, z) = std::isfinite(out) ? -float(out) : 0.0f;
        }
      }
    }
  }
  return f;
}

}  // namespace vox
