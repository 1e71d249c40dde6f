// Volume export by extension: the content is checked once here, then handed to the format's writer (nrrd.cpp,
// vti.cpp, vdb.cpp, magicavoxel.cpp). Errors are prefixed with the file's name.
#include "vox/io/volume_export.h"

#include <cmath>
#include <set>

#include "vox/io/file_util.h"
#include "vox/io/magicavoxel.h"
#include "vox/io/nrrd.h"
#include "vox/io/vdb.h"
#include "vox/io/vti.h"

namespace vox::io {
namespace {

constexpr VolumeFormat kAll[] = {VolumeFormat::kNrrd, VolumeFormat::kVti, VolumeFormat::kVdb, VolumeFormat::kVox};

const char* formatName(VolumeFormat f) {
  switch (f) {
    case VolumeFormat::kNrrd:
      return "NRRD";
    case VolumeFormat::kVti:
      return "VTK image data (.vti)";
    case VolumeFormat::kVdb:
      return "OpenVDB (.vdb)";
    case VolumeFormat::kVox:
      return "MagicaVoxel (.vox)";
  }
  return "";
}

// The same lattice: dims, voxel size and origin (to a millionth of a voxel: fields copy the grid's frame, but a
// field read back from a file may differ in the last bits).
bool sameLattice(const Dims& da, const GridFrame& a, const Dims& db, const GridFrame& b) {
  const double tol = 1e-6 * a.voxel_size;
  return da == db && std::abs(a.voxel_size - b.voxel_size) <= tol && std::abs(a.origin.x - b.origin.x) <= tol &&
         std::abs(a.origin.y - b.origin.y) <= tol && std::abs(a.origin.z - b.origin.z) <= tol;
}

std::string latticeProblem(const VolumeContent& c) {
  const Dims d = c.dims();
  if (d.count() == 0) return "the volume is empty (no voxels)";
  if (c.voxels && c.voxels->empty()) return "the volume is empty (no voxels)";
  std::set<std::string> names;
  if (c.voxels) names.insert("voxels");
  for (const NamedField& f : c.fields) {
    if (!f.field) return "field '" + f.name + "' is missing";
    if (f.name.empty()) return "a field has no name";
    if (!names.insert(f.name).second) return "two volumes are named '" + f.name + "'";
    if (int64_t(f.field->values.size()) != f.field->dims.count()) {
      return "field '" + f.name + "' has " + std::to_string(f.field->values.size()) + " values for " +
             std::to_string(f.field->dims.count()) + " voxels";
    }
    if (!sameLattice(d, c.frame(), f.field->dims, f.field->frame)) {
      return "field '" + f.name + "' does not lie on the same voxels as the rest of the volume";
    }
  }
  return {};
}

Result<std::vector<uint8_t>> encodeNrrdContent(const VolumeContent& c) {
  if (c.voxels) return encodeNrrd(*c.voxels);
  return encodeNrrd(*c.fields.front().field);
}

}  // namespace

Dims VolumeContent::dims() const {
  if (voxels) return voxels->dims();
  return fields.empty() || !fields.front().field ? Dims{} : fields.front().field->dims;
}

const GridFrame& VolumeContent::frame() const {
  static const GridFrame kNone{};
  if (voxels) return voxels->frame();
  return fields.empty() || !fields.front().field ? kNone : fields.front().field->frame;
}

std::optional<VolumeFormat> volumeFormatOf(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  for (VolumeFormat f : kAll) {
    if (ext == volumeExtension(f)) return f;
  }
  return std::nullopt;
}

bool isVolumeFile(const std::filesystem::path& path) { return volumeFormatOf(path).has_value(); }

const char* volumeExtension(VolumeFormat format) {
  switch (format) {
    case VolumeFormat::kNrrd:
      return ".nrrd";
    case VolumeFormat::kVti:
      return ".vti";
    case VolumeFormat::kVdb:
      return ".vdb";
    case VolumeFormat::kVox:
      return ".vox";
  }
  return "";
}

std::vector<std::string> volumeExtensions(bool fields_only) {
  std::vector<std::string> out;
  for (VolumeFormat f : kAll) {
    if (!fields_only || holdsFields(f)) out.emplace_back(volumeExtension(f));
  }
  return out;
}

std::string volumeExtensionList(bool fields_only) {
  const std::vector<std::string> e = volumeExtensions(fields_only);
  std::string s;
  for (size_t i = 0; i < e.size(); ++i) s += (i == 0 ? "" : i + 1 == e.size() ? " or " : ", ") + e[i];
  return s;
}

bool holdsFields(VolumeFormat format) { return format != VolumeFormat::kVox; }
bool holdsSeveralVolumes(VolumeFormat format) { return format == VolumeFormat::kVti || format == VolumeFormat::kVdb; }

std::string volumeContentProblem(const VolumeContent& content, VolumeFormat format) {
  const size_t volumes = (content.voxels ? 1 : 0) + content.fields.size();
  if (volumes == 0) return "nothing to write";
  if (!content.fields.empty() && !holdsFields(format)) {
    return std::string(formatName(format)) + " holds voxels only, not scalar fields (use " + volumeExtensionList(true) +
           ")";
  }
  if (volumes > 1 && !holdsSeveralVolumes(format)) {
    return std::string(formatName(format)) + " holds one volume per file (.vti and .vdb hold several)";
  }
  return latticeProblem(content);
}

Result<std::vector<uint8_t>> encodeVolume(const VolumeContent& content, VolumeFormat format, const std::string& name,
                                          const ProgressFn& progress) {
  auto named = [&](Result<std::vector<uint8_t>> r) -> Result<std::vector<uint8_t>> {
    if (r.ok() || r.error().code == ErrorCode::kCancelled) return r;
    return makeError(r.error().code, name + ": " + r.error().message);
  };
  if (const std::string why = volumeContentProblem(content, format); !why.empty()) {
    return makeError(ErrorCode::kInvalidArgument, name + ": " + why);
  }
  switch (format) {
    case VolumeFormat::kNrrd:
      return named(encodeNrrdContent(content));
    case VolumeFormat::kVti:
      return named(encodeVti(content, progress));
    case VolumeFormat::kVdb:
      return named(encodeVdb(content, progress));
    case VolumeFormat::kVox:
      return named(encodeMagicaVoxel(*content.voxels, progress));
  }
  return makeError(ErrorCode::kInvalidArgument, name + ": unknown volume format");
}

Status saveVolume(const VolumeContent& content, const std::filesystem::path& path, const ProgressFn& progress) {
  const std::string name = path.string();
  const auto format = volumeFormatOf(path);
  if (!format) {
    return makeError(ErrorCode::kUnsupported, name + ": unknown volume file type '" + path.extension().string() +
                                                  "' (supported: " + volumeExtensionList() + ")");
  }
  if (const std::string why = volumeContentProblem(content, *format); !why.empty()) {
    return makeError(ErrorCode::kInvalidArgument, name + ": " + why);
  }
  if (*format == VolumeFormat::kVox) {  // streamed: a .vox file is 4 bytes per filled voxel, uncompressed
    return writeFileAtomic(path, [&](ByteSink& sink) -> Status {
      if (Status s = writeMagicaVoxel(*content.voxels, sink, progress); !s) {
        if (s.error().code == ErrorCode::kCancelled || s.error().message.rfind(name, 0) == 0) return s;
        return makeError(s.error().code, name + ": " + s.error().message);
      }
      return Ok{};
    });
  }
  auto bytes = encodeVolume(content, *format, name, progress);
  if (!bytes) return bytes.error();
  return writeFileAtomic(path, *bytes);
}

}  // namespace vox::io
