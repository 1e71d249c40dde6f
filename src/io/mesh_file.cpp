// One entry point for mesh and CAD files (vox/io/mesh_file.h): the extension says which reader, the content must
// agree, and every reader's result is finished the same way (topology, warnings, notes, units).
#include "vox/io/mesh_file.h"

#include <cstring>
#include <fstream>

#include "io/glb_check.h"
#include "io/mesh_assimp.h"
#include "io/mesh_findings.h"
#include "io/mesh_sniff.h"
#include "io/off_check.h"
#include "io/ply_check.h"
#include "io/zip_package.h"
#include "vox/core/text.h"
#include "vox/core/units.h"
#include "vox/io/cad.h"
#include "vox/io/file_util.h"
#include "vox/io/stl.h"

namespace vox::io {
namespace {

struct FormatRow {
  MeshFormat format;
  const char* name;
  std::vector<const char*> extensions;
  const char* signature;  // what its files start with, for messages; nullptr: none
};

const std::vector<FormatRow>& formatTable() {
  static const std::vector<FormatRow> rows = {
      {MeshFormat::kStl, "STL", {".stl"}, nullptr},
      {MeshFormat::kObj, "OBJ", {".obj"}, nullptr},
      {MeshFormat::kPly, "PLY", {".ply"}, "a first line 'ply'"},
      {MeshFormat::k3mf, "3MF", {".3mf"}, "a zip signature ('PK')"},
      {MeshFormat::kGltf, "glTF", {".gltf"}, "a JSON object ('{')"},
      {MeshFormat::kGlb, "GLB", {".glb"}, "'glTF'"},
      {MeshFormat::kOff, "OFF", {".off"}, "'OFF'"},
      {MeshFormat::kStep, "STEP", {".step", ".stp"}, "'ISO-10303-21;'"},
      {MeshFormat::kIges, "IGES", {".iges", ".igs"}, "a Start record ('S' in column 73)"},
  };
  return rows;
}

const FormatRow* rowOf(MeshFormat format) {
  for (const FormatRow& r : formatTable()) {
    if (r.format == format) return &r;
  }
  return nullptr;
}

// The format to read `name` as: its extension's, once the content agrees; the content's for an unknown extension;
// STL when neither says (binary STL has no signature, and voxmod always read such files as STL).
Result<MeshFormat> chooseFormat(std::span<const uint8_t> head, const std::string& name) {
  const MeshFormat by_name = meshFormatFromExtension(name);
  const ContentKind found = sniffContent(head);
  if (by_name == MeshFormat::kUnknown) return found.format == MeshFormat::kUnknown ? MeshFormat::kStl : found.format;
  if (found.format == by_name) return by_name;
  if (by_name == MeshFormat::kGltf && found.format == MeshFormat::kGlb) return found.format;  // glTF's binary form
  if (head.empty()) return makeError(ErrorCode::kParse, name + ": file is empty");
  if (found.what != nullptr) return makeError(ErrorCode::kParse, notWhatItSays(name, by_name, found));
  if (const char* signature = rowOf(by_name)->signature) {
    return makeError(ErrorCode::kParse,
                     name + ": not " + withArticle(by_name) + " file: it does not start with " + signature);
  }
  if (by_name == MeshFormat::kObj && std::memchr(head.data(), 0, head.size()) != nullptr) {
    return makeError(ErrorCode::kParse, name + ": not an OBJ file: it holds binary data (OBJ is text)");
  }
  return by_name;
}

MeshFileLoad fromStl(StlLoad&& stl) {
  MeshFileLoad out;
  out.mesh = std::move(stl.mesh);
  out.topology = stl.topology;
  out.format = MeshFormat::kStl;
  out.format_detail = stl.ascii ? "ASCII STL" : "binary STL";
  out.bodies.push_back({stl.header.empty() ? "body 1" : stl.header, 0, out.mesh.triangles.size()});
  out.warnings = std::move(stl.warnings);
  out.notes = std::move(stl.notes);
  return out;
}

// The caller's unit must be one voxmod knows ("model" means none).
Status checkUnits(const std::string& units, const std::string& name) {
  if (units.empty() || units == "model" || metresPerUnit(units) > 0.0) return Ok{};
  return makeError(ErrorCode::kInvalidArgument, name + ": unknown unit '" + units + "' (use mm, cm, m or in)");
}

// A mesh file's unit, as the file names it (3MF's unit attribute; glTF is in metres by its specification): kept as
// the mesh's units where voxmod has the unit, converted to millimetres where it does not (micron, foot).
void applyMeshUnits(const std::string& file_unit, const MeshFileOptions& options, MeshFileLoad& out) {
  const std::string& name = out.mesh.name;
  out.file_units = file_unit;
  if (!options.units.empty()) {
    out.units = options.units;
    if (!file_unit.empty()) {
      out.notes.push_back(name + ": coordinates taken as " + unitsLabel(options.units) + " (the file says " +
                          file_unit + ")");
    }
    return;
  }
  if (file_unit.empty()) return;
  static const struct {
    const char* file;
    const char* units;
    double to_mm;  // > 0: converted to millimetres by this factor
  } kUnits[] = {{"millimeter", "mm", 0}, {"centimeter", "cm", 0}, {"meter", "m", 0},
                {"inch", "in", 0},       {"micron", "mm", 0.001}, {"foot", "mm", 304.8}};
  for (const auto& u : kUnits) {
    if (file_unit != u.file) continue;
    out.units = u.units;
    if (u.to_mm > 0) {
      for (Triangle& t : out.mesh.triangles) {
        for (glm::vec3& v : t.v) v = glm::vec3(glm::dvec3(v) * u.to_mm);
      }
      out.notes.push_back(name + ": unit " + file_unit + " (from the file), converted to millimetres");
    } else if (out.format != MeshFormat::kGltf && out.format != MeshFormat::kGlb) {
      out.notes.push_back(name + ": unit " + file_unit + " (from the file)");
    }
    return;
  }
  out.warnings.push_back(name + ": unknown unit " + quoteBytes(file_unit) +
                         " in the file; coordinates kept as "
                         "model units");
}

Status finishMesh(MeshFileLoad& out) {
  try {
    out.topology = analyzeTopology(out.mesh);
  } catch (const std::length_error&) {
    return makeError(ErrorCode::kLimit, out.mesh.name + ": " + std::to_string(out.mesh.triangles.size()) +
                                            " triangles; voxmod reads at most " + std::to_string(UINT32_MAX / 3));
  }
  addTopologyFindings(out.mesh.name, out.topology, out.warnings, out.notes);
  return Ok{};
}

uint64_t memoryLimit(const MeshFileOptions& options) {
  if (options.memory_limit_bytes > 0) return options.memory_limit_bytes;
  const uint64_t physical = physicalMemoryBytes();
  return physical > 0 ? physical : UINT64_MAX;
}

Result<MeshFileLoad> readWithAssimp(std::span<const uint8_t> bytes, const std::string& name, MeshFormat format,
                                    const std::filesystem::path* directory, const MeshFileOptions& options) {
  std::string file_unit;
  std::vector<uint8_t> package;
  if (format == MeshFormat::kPly) {
    if (auto facts = checkPly(bytes, name); !facts) return facts.error();
  } else if (format == MeshFormat::kOff) {
    if (Status s = checkOff(bytes, name); !s.ok()) return s.error();
  } else if (format == MeshFormat::k3mf) {
    auto p = read3mfPackage(bytes, name, memoryLimit(options));
    if (!p) return p.error();
    file_unit = p->unit;
    package = std::move(p->zip);
    bytes = package;
  } else if (format == MeshFormat::kGltf || format == MeshFormat::kGlb) {
    if (format == MeshFormat::kGlb) {
      if (Status s = checkGlb(bytes, name); !s.ok()) return s.error();
    }
    file_unit = "meter";  // glTF 2.0, "Coordinate System and Units"
  }
  auto out = importWithAssimp(bytes, name, format, directory);
  if (!out) return out.error();
  applyMeshUnits(file_unit, options, *out);
  if (Status s = finishMesh(*out); !s.ok()) return s.error();
  return out;
}

// Reads the CAD file, then tessellates it for the grid the options describe; progress 0.4 / 0.6 between the two.
Result<MeshFileLoad> readCad(std::span<const uint8_t> bytes, const std::filesystem::path* path, const std::string& name,
                             MeshFormat format, const MeshFileOptions& options) {
  const ProgressFn& p = options.progress;
  CadReadOptions read;
  read.units = options.units == "model" ? std::string() : options.units;
  if (p) read.progress = [&p](double f) { return p(0.4 * f); };
  auto model = path ? readCadFile(*path, read) : readCadBytes(bytes, name, format, read);
  if (!model) return model.error();
  auto deflection = cadDeflectionFor(model->bounds(), options.resolution, options.voxel_size);
  if (!deflection) return makeError(deflection.error().code, name + ": " + deflection.error().message);
  ProgressFn tessellating;
  if (p) tessellating = [&p](double f) { return p(0.4 + 0.6 * f); };
  auto out = tessellateCad(*model, *deflection, tessellating);
  if (!out) return out.error();
  out->cad = std::make_shared<const CadModel>(std::move(model).value());
  return out;
}

Result<MeshFileLoad> read(std::span<const uint8_t> bytes, const std::filesystem::path* path, const std::string& name,
                          const MeshFileOptions& options) {
  if (Status s = checkUnits(options.units, name); !s.ok()) return s.error();
  auto format = chooseFormat(bytes, name);
  if (!format) return format.error();
  if (isCadFormat(*format)) return readCad(bytes, path, name, *format, options);
  if (*format == MeshFormat::kStl) {
    auto stl = parseStl(bytes, name);
    if (!stl) return stl.error();
    MeshFileLoad out = fromStl(std::move(stl).value());
    if (!options.units.empty()) out.units = options.units;
    return out;
  }
  const std::filesystem::path directory = path ? path->parent_path() : std::filesystem::path();
  return readWithAssimp(bytes, name, *format, path ? &directory : nullptr, options);
}

}  // namespace

const char* meshFormatName(MeshFormat format) {
  const FormatRow* r = rowOf(format);
  return r ? r->name : "unknown";
}

MeshFormat meshFormatFromExtension(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  for (const FormatRow& r : formatTable()) {
    for (const char* e : r.extensions) {
      if (ext == e) return r.format;
    }
  }
  return MeshFormat::kUnknown;
}

MeshFormat meshFormatFromContent(std::span<const uint8_t> bytes) { return sniffContent(bytes).format; }

bool isCadFormat(MeshFormat format) { return format == MeshFormat::kStep || format == MeshFormat::kIges; }

const std::vector<std::string>& meshFileExtensions() {
  static const std::vector<std::string> all = [] {
    std::vector<std::string> v;
    for (const FormatRow& r : formatTable()) v.insert(v.end(), r.extensions.begin(), r.extensions.end());
    return v;
  }();
  return all;
}

Result<MeshFileLoad> loadMeshFile(const std::filesystem::path& path, const MeshFileOptions& options) {
  // STL through its own loader, which releases the file's bytes before the topology pass allocates.
  if (meshFormatFromExtension(path) == MeshFormat::kStl) {
    std::vector<uint8_t> head(4096);
    std::ifstream f(path, std::ios::binary);
    f.read(reinterpret_cast<char*>(head.data()), std::streamsize(head.size()));
    head.resize(size_t(std::max<std::streamsize>(f.gcount(), 0)));
    const ContentKind kind = sniffContent(head);
    if (f.bad() || !f.is_open() || head.empty() || (kind.what != nullptr && kind.format != MeshFormat::kStl)) {
      // Errors (missing file, empty, another format) are named by the general path below.
    } else if (Status s = checkUnits(options.units, path.string()); !s.ok()) {
      return s.error();
    } else {
      auto stl = loadStl(path);
      if (!stl) return stl.error();
      MeshFileLoad out = fromStl(std::move(stl).value());
      if (!options.units.empty()) out.units = options.units;
      return out;
    }
  }
  auto bytes = readFileBytes(path);
  if (!bytes) return bytes.error();
  return read(*bytes, &path, path.string(), options);
}

Result<MeshFileLoad> parseMeshFile(std::span<const uint8_t> bytes, const std::string& name,
                                   const MeshFileOptions& options) {
  return read(bytes, nullptr, name, options);
}

std::optional<FileBodies> fileBodies(std::span<const MeshBody> bodies, size_t triangle_count, bool cad) {
  if (!cad && bodies.size() < 2) return std::nullopt;
  FileBodies out;
  out.bodies.body_of.resize(triangle_count);
  uint64_t next = 0;
  for (const MeshBody& b : bodies) {
    if (b.first_triangle != next || b.triangle_count > triangle_count - next) return std::nullopt;
    next += b.triangle_count;
    if (b.triangle_count == 0) continue;
    const auto index = uint32_t(out.bodies.triangles.size());
    std::vector<uint32_t>& tris = out.bodies.triangles.emplace_back(b.triangle_count);
    for (uint64_t t = 0; t < b.triangle_count; ++t) {
      tris[t] = uint32_t(b.first_triangle + t);
      out.bodies.body_of[b.first_triangle + t] = index;
    }
    out.names.push_back(b.name);
  }
  if (next != triangle_count || out.bodies.count() == 0) return std::nullopt;
  return out;
}

}  // namespace vox::io
