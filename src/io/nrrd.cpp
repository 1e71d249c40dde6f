// NRRD through Teem (libteem-dev): Teem builds the header (sizes, type, space, directions, origin) and encodes the
// data (raw or gzip); files are written from memory so that a command writing several files writes all or none.
#include "vox/io/nrrd.h"

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include <teem/nrrd.h>

#include "vox/io/file_util.h"

namespace vox::io {
namespace {

struct NrrdDeleter {
  void operator()(Nrrd* n) const { nrrdNix(n); }  // frees the struct, not data we own
};
struct NrrdNuker {
  void operator()(Nrrd* n) const { nrrdNuke(n); }  // frees the struct and the data Teem allocated
};
struct IoDeleter {
  void operator()(NrrdIoState* n) const { nrrdIoStateNix(n); }
};

// Teem's error (biff), taken and cleared: a chain of "[nrrd] function: message" lines from the outermost call to
// the innermost; the innermost says what was wrong ("parsed 2 values, but dimension is 3").
std::string teemError() {
  char* e = biffGetDone(NRRD);
  std::string s = e ? e : "";
  std::free(e);
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  std::string last = s.substr(s.find_last_of('\n') == std::string::npos ? 0 : s.find_last_of('\n') + 1);
  if (const size_t colon = last.find(": "); last.rfind("[", 0) == 0 && colon != std::string::npos) {
    last = last.substr(colon + 2);
  }
  return last.empty() ? "unreadable NRRD" : last;
}

// Header and data of a 3D volume of `type` over `dims` placed by `frame`, encoded into memory.
Result<std::vector<uint8_t>> encode(void* data, int type, const Dims& dims, const GridFrame& frame,
                                    NrrdEncoding encoding) {
  std::unique_ptr<Nrrd, NrrdDeleter> n(nrrdNew());
  if (nrrdWrap_va(n.get(), data, type, 3, size_t(dims.nx), size_t(dims.ny), size_t(dims.nz)) ||
      nrrdSpaceSet(n.get(), nrrdSpace3DRightHanded)) {
    return makeError(ErrorCode::kInvalidArgument, "NRRD: " + teemError());
  }
  const double h = frame.voxel_size;
  double dirs[3][NRRD_SPACE_DIM_MAX] = {{h, 0, 0}, {0, h, 0}, {0, 0, h}};
  nrrdAxisInfoSet_va(n.get(), nrrdAxisInfoSpaceDirection, dirs[0], dirs[1], dirs[2]);
  const glm::dvec3 c = frame.voxelCentre(0, 0, 0);
  const double origin[3] = {c.x, c.y, c.z};
  if (nrrdSpaceOriginSet(n.get(), origin)) return makeError(ErrorCode::kInvalidArgument, "NRRD: " + teemError());
  // The length unit of the space (NRRD's "space units" field; docs/conventions.md, "NRRD"): "mm", ..., "model" when
  // unknown.
  for (unsigned i = 0; i < 3; ++i) n->spaceUnits[i] = airStrdup(frame.units.c_str());
  int centers[3] = {nrrdCenterCell, nrrdCenterCell, nrrdCenterCell};
  nrrdAxisInfoSet_nva(n.get(), nrrdAxisInfoCenter, centers);

  std::unique_ptr<NrrdIoState, IoDeleter> io(nrrdIoStateNew());
  io->encoding = encoding == NrrdEncoding::kGzip ? nrrdEncodingGzip : nrrdEncodingRaw;
  io->zlibLevel = 1;  // fast: fields of hundreds of millions of voxels; distance fields compress well at any level
  io->endian = airEndianLittle;
  char* buffer = nullptr;
  size_t size = 0;
  FILE* out = open_memstream(&buffer, &size);
  if (!out) return makeError(ErrorCode::kIo, "NRRD: cannot allocate memory for the file");
  const int failed = nrrdWrite(out, n.get(), io.get());
  std::fclose(out);
  std::unique_ptr<char, decltype(&std::free)> owned(buffer, &std::free);
  if (failed) return makeError(ErrorCode::kIo, "NRRD: " + teemError());
  return std::vector<uint8_t>(buffer, buffer + size);
}

}  // namespace

Result<std::vector<uint8_t>> encodeNrrd(const VoxelGrid& grid, NrrdEncoding encoding) {
  std::vector<uint8_t> bytes(size_t(grid.dims().count()), 0);
  for (int32_t z = 0; z < grid.nz(); ++z) {
    if (!grid.layerAllocated(z)) continue;
    for (int32_t y = 0; y < grid.ny(); ++y) {
      for (int32_t x = 0; x < grid.nx(); ++x) {
        bytes[size_t(x + int64_t(grid.nx()) * (y + int64_t(grid.ny()) * z))] = grid.get(x, y, z) ? 1 : 0;
      }
    }
  }
  return encode(bytes.data(), nrrdTypeUChar, grid.dims(), grid.frame(), encoding);
}

Result<std::vector<uint8_t>> encodeNrrd(const ScalarField& field, NrrdEncoding encoding) {
  if (int64_t(field.values.size()) != field.dims.count() || field.dims.count() == 0) {
    return makeError(ErrorCode::kInvalidArgument, "NRRD: the field's values do not match its dimensions");
  }
  return encode(const_cast<float*>(field.values.data()), nrrdTypeFloat, field.dims, field.frame, encoding);
}

Status saveNrrd(const VoxelGrid& grid, const std::filesystem::path& path, NrrdEncoding encoding) {
  auto bytes = encodeNrrd(grid, encoding);
  if (!bytes) return makeError(bytes.error().code, path.string() + ": " + bytes.error().message);
  return writeFileAtomic(path, *bytes);
}

Status saveNrrd(const ScalarField& field, const std::filesystem::path& path, NrrdEncoding encoding) {
  auto bytes = encodeNrrd(field, encoding);
  if (!bytes) return makeError(bytes.error().code, path.string() + ": " + bytes.error().message);
  return writeFileAtomic(path, *bytes);
}

Result<ScalarField> loadNrrdField(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::unique_ptr<Nrrd, NrrdNuker> n(nrrdNew());
  if (nrrdLoad(n.get(), name.c_str(), nullptr)) return makeError(ErrorCode::kParse, name + ": " + teemError());
  if (n->dim != 3) return makeError(ErrorCode::kUnsupported, name + ": not a 3D volume");
  std::unique_ptr<Nrrd, NrrdNuker> f(nrrdNew());
  if (nrrdConvert(f.get(), n.get(), nrrdTypeFloat)) return makeError(ErrorCode::kParse, name + ": " + teemError());
  const size_t sx = f->axis[0].size, sy = f->axis[1].size, sz = f->axis[2].size;
  if (sx == 0 || sy == 0 || sz == 0 || sx > size_t(VoxelGrid::kMaxDim) || sy > size_t(VoxelGrid::kMaxDim) ||
      sz > size_t(VoxelGrid::kMaxDim)) {
    return makeError(ErrorCode::kUnsupported, name + ": sizes outside 1.." + std::to_string(VoxelGrid::kMaxDim));
  }
  GridFrame frame;
  frame.source = path.filename().string();
  if (n->spaceDim == 3) {
    const double h = n->axis[0].spaceDirection[0];
    for (unsigned a = 0; a < 3; ++a) {
      for (unsigned b = 0; b < 3; ++b) {
        const double v = n->axis[a].spaceDirection[b];
        if ((a == b && !(v > 0.0 && std::abs(v - h) <= 1e-9 * h)) || (a != b && v != 0.0)) {
          return makeError(ErrorCode::kUnsupported,
                           name + ": space directions are not one voxel size on the diagonal (a voxel lattice)");
        }
      }
    }
    frame.voxel_size = h;
    const glm::dvec3 c0(n->spaceOrigin[0], n->spaceOrigin[1], n->spaceOrigin[2]);
    frame.origin = c0 - glm::dvec3(0.5 * h);
    if (n->spaceUnits[0] && *n->spaceUnits[0]) frame.units = n->spaceUnits[0];
  }
  ScalarField out;
  out.dims = Dims{int32_t(sx), int32_t(sy), int32_t(sz)};
  out.frame = frame;
  const float* v = static_cast<const float*>(f->data);
  out.values.assign(v, v + sx * sy * sz);
  return out;
}

}  // namespace vox::io
