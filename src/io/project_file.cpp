// voxmod projects (.vxp): a zip of project.json (what the document holds besides voxels) and one .vxm file per grid
// (docs/file-format.md, "Projects").
#include "vox/io/project_file.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <utility>

#include <glm/common.hpp>

#include <nlohmann/json.hpp>

#include "io/zip_package.h"
#include "vox/core/text.h"
#include "vox/io/file_util.h"
#include "vox/io/voxel_file.h"

namespace vox::io {
namespace {

using nlohmann::json;

constexpr const char* kFormat = "voxmod project";
constexpr int kVersion = 1;
constexpr const char* kWhat = "voxmod project";

template <class V>
json triple(const V& v) {
  return json::array({v.x, v.y, v.z});
}

std::string partEntry(size_t i) {
  std::string n = std::to_string(i + 1);
  while (n.size() < 3) n.insert(n.begin(), '0');
  return "parts/" + n + ".vxm";
}

json partsJson(const Assembly& parts) {
  const Lattice& l = parts.lattice();
  json list = json::array();
  for (size_t i = 0; i < parts.size(); ++i) {
    const Part& p = parts.part(i);
    json entry = {{"name", p.name},
                  {"colour", triple(p.colour)},
                  {"visible", p.visible},
                  {"first", triple(p.voxels.first)},
                  {"translation", triple(p.placement.translation)},
                  {"quarter_turns", triple(p.placement.quarter_turns)},
                  {"voxels", partEntry(i)}};
    if (p.feeder) {
      entry["feeder"] = {
          {"base", triple(p.feeder->base)}, {"diameter", p.feeder->diameter}, {"height", p.feeder->height}};
    }
    list.push_back(std::move(entry));
  }
  return {{"lattice", {{"origin", triple(l.origin)}, {"voxel_size", l.voxel_size}, {"units", l.units}}},
          {"list", std::move(list)}};
}

// The grids are stored once (project_file.h): which ones this project writes.
bool storesBase(const ProjectFile& p) { return !p.parts || p.peeled > 0 || !p.round_peels.empty(); }
bool storesShown(const ProjectFile& p) { return p.peeled > 0; }

json manifest(const ProjectFile& p) {
  json model = {{"peeled", p.peeled}, {"round_peels", p.round_peels}};
  if (storesBase(p)) model["base"] = "model/base.vxm";
  if (storesShown(p)) model["shown"] = "model/shown.vxm";
  json view = {{"panel", p.panel}, {"section_axis", p.section_axis}, {"section_index", p.section_index}};
  view["selected_parts"] = json::array();
  for (size_t i : p.selected) view["selected_parts"].push_back(i + 1);
  json j = {{"format", kFormat},         {"version", kVersion},        {"source", p.source},
            {"origin", p.origin},        {"resolution", p.resolution}, {"units", p.units},
            {"model", std::move(model)}, {"view", std::move(view)}};
  if (p.parts) j["parts"] = partsJson(*p.parts);
  return j;
}

// ---- Reading ----

// The memory the grid of a .vxm file's bytes takes (docs/file-format.md: dims at offset 16); 0 when the header is
// not there or out of range (decodeVxm then says why).
uint64_t vxmGridBytes(const std::vector<uint8_t>& b) {
  if (b.size() < 28) return 0;
  int32_t d[3];
  for (int i = 0; i < 3; ++i) {
    uint32_t v = 0;
    for (int k = 0; k < 4; ++k) v |= uint32_t(b[size_t(16 + 4 * i + k)]) << (8 * k);
    if (v == 0 || v > uint32_t(VoxelGrid::kMaxDim)) return 0;
    d[i] = int32_t(v);
  }
  return estimateGridBytes(Dims{d[0], d[1], d[2]});
}

struct Reader {
  const std::vector<ZipEntry>& entries;
  const std::string& name;
  uint64_t memory_left;  // what the project's grids may still take, all together

  // Takes `bytes` from what is left, or fails (kLimit) naming what needed them.
  Status spend(uint64_t bytes, const std::string& what) {
    if (bytes > memory_left) {
      return makeError(ErrorCode::kLimit, name + ": " + what + " would need " + formatBytes(bytes) +
                                              " of memory, more than the " + formatBytes(memory_left) + " left");
    }
    memory_left -= bytes;
    return Ok{};
  }

  Error bad(const std::string& what) const { return makeError(ErrorCode::kParse, name + ": " + what); }

  const ZipEntry* entry(const std::string& path) const {
    for (const ZipEntry& e : entries) {
      if (e.name == path) return &e;
    }
    return nullptr;
  }

  Result<VoxelGrid> grid(const std::string& path) {
    const ZipEntry* e = entry(path);
    if (!e) return bad("the project names " + quoteBytes(path) + " but does not hold it");
    const std::string what = name + " (" + path + ")";
    const uint64_t bytes = vxmGridBytes(e->bytes);
    if (Status s = spend(bytes, path); !s) return s.error();
    auto g = decodeVxm(e->bytes, what, memory_left + bytes);
    if (!g) return g.error();
    return std::move(g).value();
  }
};

// The manifest's value under `key` (no copy), or an error naming the key.
Result<const json*> member(const Reader& r, const json& j, const char* key) {
  const auto it = j.find(key);
  if (it == j.end()) return r.bad(std::string("the manifest has no '") + key + "'");
  return &*it;
}

// A value of the kind asked for: text, a flag, or a whole number within [lo, hi] (never a float cast to an integer).
Result<std::string> text(const Reader& r, const json& j, const char* key) {
  auto v = member(r, j, key);
  if (!v) return v.error();
  if (!(*v)->is_string()) return r.bad(std::string("the manifest's '") + key + "' is not text");
  return (*v)->get<std::string>();
}

Result<bool> flag(const Reader& r, const json& j, const char* key) {
  auto v = member(r, j, key);
  if (!v) return v.error();
  if (!(*v)->is_boolean()) return r.bad(std::string("the manifest's '") + key + "' is not true or false");
  return (*v)->get<bool>();
}

Result<int64_t> wholeNumber(const Reader& r, const json& v, const std::string& what, int64_t lo, int64_t hi) {
  if (!v.is_number_integer()) return r.bad("the manifest's " + what + " is not a whole number");
  const int64_t n = v.is_number_unsigned() && v.get<uint64_t>() > uint64_t(INT64_MAX) ? INT64_MAX : v.get<int64_t>();
  if (n < lo || n > hi) {
    return r.bad("the manifest's " + what + " is " + std::to_string(n) + ", outside " + std::to_string(lo) + ".." +
                 std::to_string(hi));
  }
  return n;
}

Result<int64_t> integer(const Reader& r, const json& j, const char* key, int64_t lo, int64_t hi) {
  auto v = member(r, j, key);
  if (!v) return v.error();
  return wholeNumber(r, **v, std::string("'") + key + "'", lo, hi);
}

Result<double> real(const Reader& r, const json& v, const std::string& what) {
  if (!v.is_number()) return r.bad("the manifest's " + what + " is not a number");
  const double d = v.get<double>();
  if (!std::isfinite(d)) return r.bad("the manifest's " + what + " is not finite");
  return d;
}

// Three whole numbers within +-VoxelGrid::kMaxDim (a lattice position or a move a grid can hold).
Result<glm::ivec3> lattice3(const Reader& r, const json& j, const char* key) {
  auto v = member(r, j, key);
  if (!v) return v.error();
  if (!(*v)->is_array() || (*v)->size() != 3)
    return r.bad(std::string("the manifest's '") + key + "' is not 3 numbers");
  glm::ivec3 out(0);
  for (int i = 0; i < 3; ++i) {
    auto n = wholeNumber(r, (**v)[size_t(i)], std::string("'") + key + "'", -VoxelGrid::kMaxDim, VoxelGrid::kMaxDim);
    if (!n) return n.error();
    out[i] = int32_t(*n);
  }
  return out;
}

template <class V>
Result<V> real3(const Reader& r, const json& j, const char* key) {
  auto v = member(r, j, key);
  if (!v) return v.error();
  if (!(*v)->is_array() || (*v)->size() != 3)
    return r.bad(std::string("the manifest's '") + key + "' is not 3 numbers");
  V out(0);
  for (int i = 0; i < 3; ++i) {
    auto d = real(r, (**v)[size_t(i)], std::string("'") + key + "'");
    if (!d) return d.error();
    out[i] = typename V::value_type(*d);
  }
  return out;
}

// A part's optional "feeder": the cylinder a feeder part was made from (model units, before the placement).
Result<std::optional<Feeder>> readFeeder(const Reader& r, const json& j) {
  if (!j.contains("feeder")) return std::optional<Feeder>();
  const json& fj = j["feeder"];
  if (!fj.is_object()) return r.bad("a part's 'feeder' is not a JSON object");
  auto base = real3<glm::dvec3>(r, fj, "base");
  if (!base) return base.error();
  Feeder f;
  f.base = *base;
  for (const auto& [key, value] : {std::pair("diameter", &f.diameter), std::pair("height", &f.height)}) {
    auto m = member(r, fj, key);
    if (!m) return m.error();
    auto d = real(r, **m, std::string("the feeder's '") + key + "'");
    if (!d) return d.error();
    if (!(*d > 0.0)) return r.bad(std::string("a feeder's '") + key + "' is not a positive number");
    *value = *d;
  }
  return std::optional<Feeder>(f);
}

Result<Part> readPart(Reader& r, const json& j, const Lattice& lattice) {
  Part p;
  if (!j.is_object()) return r.bad("a part in the manifest is not a JSON object");
  auto name = text(r, j, "name");
  if (!name) return name.error();
  auto colour = real3<glm::vec3>(r, j, "colour");
  if (!colour) return colour.error();
  auto visible = flag(r, j, "visible");
  if (!visible) return visible.error();
  auto first = lattice3(r, j, "first");
  if (!first) return first.error();
  auto translation = lattice3(r, j, "translation");
  if (!translation) return translation.error();
  auto turns = lattice3(r, j, "quarter_turns");
  if (!turns) return turns.error();
  auto feeder = readFeeder(r, j);
  if (!feeder) return feeder.error();
  auto voxels = text(r, j, "voxels");
  if (!voxels) return voxels.error();
  auto grid = r.grid(*voxels);
  if (!grid) return grid.error();
  if (grid->frame().voxel_size != lattice.voxel_size || grid->frame().units != lattice.units) {
    return r.bad("part " + quoteBytes(*name) + " is not on the project's lattice");
  }
  p.name = *name;
  p.colour = glm::clamp(*colour, glm::vec3(0.0f), glm::vec3(1.0f));
  p.visible = *visible;
  p.voxels = LatticeGrid{std::move(grid).value(), *first};
  p.voxels.grid.frame() = lattice.frameAt(*first, p.voxels.grid.frame().source);
  p.placement.translation = *translation;
  p.placement.quarter_turns = *turns & 3;
  p.feeder = *feeder;
  if (p.feeder && p.placement.quarter_turns != glm::ivec3(0)) {
    return r.bad("feeder part " + quoteBytes(*name) + " is turned; a feeder stands upright");
  }
  return p;
}

// The parts' placed boxes together, refused when they would not fit a grid or the memory left for it: the union is
// made from them when the project is opened.
Status checkExtent(Reader& r, const Assembly& parts) {
  for (size_t i = 0; i < parts.size(); ++i) {
    const Box3i b = parts.placedVoxels(i).box();
    for (int a = 0; a < 3; ++a) {
      if (int64_t(b.min[a]) < -2 * int64_t(VoxelGrid::kMaxDim) || int64_t(b.max[a]) > 2 * int64_t(VoxelGrid::kMaxDim)) {
        return r.bad("part " + quoteBytes(parts.part(i).name) + " lies further out than a grid holds");
      }
    }
  }
  const glm::ivec3 n = parts.extent().size();
  if (n.x > VoxelGrid::kMaxDim || n.y > VoxelGrid::kMaxDim || n.z > VoxelGrid::kMaxDim) {
    return makeError(ErrorCode::kLimit, r.name + ": the parts span " + std::to_string(n.x) + " x " +
                                            std::to_string(n.y) + " x " + std::to_string(n.z) +
                                            " voxels, more than a grid holds");
  }
  return r.spend(estimateGridBytes(Dims{n.x, n.y, n.z}), "the union of the parts");
}

Result<Assembly> readParts(Reader& r, const json& j) {
  if (!j.is_object()) return r.bad("the manifest's 'parts' is not a JSON object");
  auto lattice_json = member(r, j, "lattice");
  if (!lattice_json) return lattice_json.error();
  const json& lj = **lattice_json;
  if (!lj.is_object()) return r.bad("the manifest's 'lattice' is not a JSON object");
  auto origin = real3<glm::dvec3>(r, lj, "origin");
  if (!origin) return origin.error();
  auto h_json = member(r, lj, "voxel_size");
  if (!h_json) return h_json.error();
  auto h = real(r, **h_json, "'voxel_size'");
  if (!h) return h.error();
  auto units = text(r, lj, "units");
  if (!units) return units.error();
  if (!(*h > 0.0)) return r.bad("the parts' voxel size is not a positive number");
  const Lattice lattice{*origin, *h, *units};
  auto list = member(r, j, "list");
  if (!list) return list.error();
  if (!(*list)->is_array() || (*list)->empty()) return r.bad("the project's parts are not a list of parts");
  Assembly parts(lattice);
  for (const json& pj : **list) {
    auto p = readPart(r, pj, lattice);
    if (!p) return p.error();
    const size_t k = parts.addPart(std::move(p->voxels), p->name);
    parts.part(k).colour = p->colour;
    parts.part(k).visible = p->visible;
    parts.part(k).feeder = p->feeder;
    parts.setPlacement(k, p->placement);
  }
  if (Status s = checkExtent(r, parts); !s) return s.error();
  return parts;
}

Status readView(const Reader& r, const json& j, ProjectFile& p) {
  if (!j.is_object()) return r.bad("the manifest's 'view' is not a JSON object");
  auto panel = text(r, j, "panel");
  if (!panel) return panel.error();
  auto axis = text(r, j, "section_axis");
  if (!axis) return axis.error();
  auto index = integer(r, j, "section_index", -1, VoxelGrid::kMaxDim);
  if (!index) return index.error();
  auto selected = member(r, j, "selected_parts");
  if (!selected) return selected.error();
  if (!(*selected)->is_array()) return r.bad("the manifest's 'selected_parts' is not a list");
  p.panel = *panel;
  p.section_axis = *axis;
  p.section_index = int32_t(*index);
  const size_t n = p.parts ? p.parts->size() : 0;
  for (const json& v : **selected) {
    auto i = wholeNumber(r, v, "'selected_parts'", 1, int64_t(n));
    if (!i) return i.error();
    p.selected.push_back(size_t(*i - 1));
  }
  return Ok{};
}

Result<VoxelGrid> gridNamed(Reader& r, const json& j, const char* key) {
  auto path = text(r, j, key);
  if (!path) return path.error();
  return r.grid(*path);
}

Status readModel(Reader& r, const json& j, ProjectFile& p) {
  if (!j.is_object()) return r.bad("the manifest's 'model' is not a JSON object");
  auto peeled = integer(r, j, "peeled", 0, VoxelGrid::kMaxDim);
  if (!peeled) return peeled.error();
  auto round_peels = text(r, j, "round_peels");
  if (!round_peels) return round_peels.error();
  p.peeled = int32_t(*peeled);
  p.round_peels = *round_peels;
  const bool base_needed = !p.parts || p.peeled > 0 || !p.round_peels.empty();  // as encodeProject stores it
  if (base_needed != j.contains("base")) {
    return r.bad(base_needed ? "the project's model has no base grid"
                             : "the project's model has a base grid besides "
                               "its parts and nothing peeled");
  }
  if (j.contains("base")) {
    auto g = gridNamed(r, j, "base");
    if (!g) return g.error();
    p.base = std::move(g).value();
  }
  if ((p.peeled > 0) != j.contains("shown")) {
    return r.bad(p.peeled > 0 ? "the project's model is peeled but holds no grid as shown"
                              : "the project's model holds a grid as shown but nothing is peeled");
  }
  if (j.contains("shown")) {
    auto g = gridNamed(r, j, "shown");
    if (!g) return g.error();
    if (g->dims() != p.base.dims()) return r.bad("the model as shown and its base differ in size");
    p.shown = std::move(g).value();
  } else {
    p.shown = p.base;
  }
  return Ok{};
}

Result<ProjectFile> readManifest(Reader& r, const json& j) {
  auto format = text(r, j, "format");
  if (!format || *format != kFormat) return r.bad("not a voxmod project (its manifest names no such format)");
  auto version = integer(r, j, "version", 1, INT32_MAX);
  if (!version) return version.error();
  if (*version > kVersion) {
    return makeError(ErrorCode::kUnsupported, r.name + ": a voxmod project of version " + std::to_string(*version) +
                                                  "; this voxmod reads version " + std::to_string(kVersion) +
                                                  " (a newer voxmod wrote it)");
  }
  ProjectFile p;
  auto source = text(r, j, "source");
  if (!source) return source.error();
  auto origin = text(r, j, "origin");
  if (!origin) return origin.error();
  auto resolution = integer(r, j, "resolution", 0, INT64_MAX);
  if (!resolution) return resolution.error();
  auto units = text(r, j, "units");
  if (!units) return units.error();
  auto model = member(r, j, "model");
  if (!model) return model.error();
  auto view = member(r, j, "view");
  if (!view) return view.error();
  p.source = *source;
  p.origin = *origin;
  p.resolution = *resolution;
  p.units = *units;
  if (const auto it = j.find("parts"); it != j.end()) {
    auto parts = readParts(r, *it);
    if (!parts) return parts.error();
    p.parts = std::move(parts).value();
  }
  if (Status s = readModel(r, **model, p); !s) return s.error();
  if (Status s = readView(r, **view, p); !s) return s.error();
  return p;
}

}  // namespace

Result<std::vector<uint8_t>> encodeProject(const ProjectFile& p, const std::string& name) {
  if ((storesBase(p) && p.base.empty()) || (storesShown(p) && p.shown.empty())) {
    return makeError(ErrorCode::kInvalidArgument, name + ": the project has no model to store");
  }
  std::vector<ZipEntry> entries;
  entries.push_back({"project.json", {}});
  const std::string text = manifest(p).dump(2) + "\n";
  entries.back().bytes.assign(text.begin(), text.end());
  if (storesBase(p)) entries.push_back({"model/base.vxm", encodeVxm(p.base)});
  if (storesShown(p)) entries.push_back({"model/shown.vxm", encodeVxm(p.shown)});
  if (p.parts) {
    for (size_t i = 0; i < p.parts->size(); ++i)
      entries.push_back({partEntry(i), encodeVxm(p.parts->part(i).voxels.grid)});
  }
  // The .vxm files are run-length coded already: stored, not deflated again.
  return writeZip(entries, name, false);
}

Result<ProjectFile> decodeProject(std::span<const uint8_t> bytes, const std::string& name, uint64_t memory_limit) {
  const uint64_t limit = memory_limit > 0 ? memory_limit : defaultMemoryLimitBytes();
  // The zip's entries are .vxm files: run lengths, far smaller than the grids they make (which decodeVxm checks).
  // The entries' bytes are the file's own, stored: they are not held against the grids' memory.
  auto entries = readZip(bytes, name, kWhat, std::max<uint64_t>(limit, uint64_t(bytes.size()) * 2));
  if (!entries) return entries.error();
  Reader r{*entries, name, limit};
  const ZipEntry* m = r.entry("project.json");
  if (!m) return r.bad("not a voxmod project: the zip holds no project.json");
  json j;
  try {
    j = json::parse(m->bytes.begin(), m->bytes.end());
  } catch (const json::exception& e) {  // a parse error, or a number past a double (out_of_range)
    return r.bad(std::string("the manifest project.json is not JSON (") + e.what() + ")");
  }
  if (!j.is_object()) return r.bad("the manifest project.json is not a JSON object");
  return readManifest(r, j);
}

Status saveProject(const ProjectFile& project, const std::filesystem::path& path) {
  auto bytes = encodeProject(project, path.string());
  if (!bytes) return bytes.error();
  return writeFileAtomic(path, std::span<const uint8_t>(*bytes));
}

Result<ProjectFile> loadProject(const std::filesystem::path& path, uint64_t memory_limit_bytes) {
  auto bytes = readFileBytes(path);
  if (!bytes) return bytes.error();
  return decodeProject(*bytes, path.string(), memory_limit_bytes);
}

bool isProjectFile(const std::filesystem::path& path) { return lowerExtension(path) == ".vxp"; }

}  // namespace vox::io

namespace vox::io {

std::string projectSource(const std::filesystem::path& path) {
  auto bytes = readFileBytes(path);
  if (!bytes) return {};
  auto entries = readZip(*bytes, path.string(), kWhat, uint64_t(4) << 30);
  if (!entries) return {};
  for (const ZipEntry& e : *entries) {
    if (e.name != "project.json") continue;
    const json j = json::parse(e.bytes.begin(), e.bytes.end(), nullptr, false);
    const auto it = j.is_object() ? j.find("source") : j.end();
    return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
  }
  return {};
}

}  // namespace vox::io
