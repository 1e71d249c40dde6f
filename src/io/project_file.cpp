// voxmod projects (.vxp): a zip of project.json (what the document holds besides voxels) and one .vxm file per grid
// (docs/file-format.md, "Projects").
#include "vox/io/project_file.h"

#include <array>
#include <cmath>
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
    list.push_back({{"name", p.name},
                    {"colour", triple(p.colour)},
                    {"visible", p.visible},
                    {"first", triple(p.voxels.first)},
                    {"translation", triple(p.placement.translation)},
                    {"quarter_turns", triple(p.placement.quarter_turns)},
                    {"voxels", partEntry(i)}});
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

struct Reader {
  const std::vector<ZipEntry>& entries;
  const std::string& name;
  uint64_t memory_limit;

  Error bad(const std::string& what) const { return makeError(ErrorCode::kParse, name + ": " + what); }

  const ZipEntry* entry(const std::string& path) const {
    for (const ZipEntry& e : entries) {
      if (e.name == path) return &e;
    }
    return nullptr;
  }

  Result<VoxelGrid> grid(const std::string& path) const {
    const ZipEntry* e = entry(path);
    if (!e) return bad("the project names " + quoteBytes(path) + " but does not hold it");
    auto g = decodeVxm(e->bytes, name + " (" + path + ")", memory_limit);
    if (!g) return g.error();
    return std::move(g).value();
  }
};

// A value of the manifest of the type asked for, or an error naming the key.
template <class T>
Result<T> field(const Reader& r, const json& j, const char* key) {
  const auto it = j.find(key);
  if (it == j.end()) return r.bad(std::string("the manifest has no '") + key + "'");
  try {
    return it->get<T>();
  } catch (const json::exception&) {
    return r.bad(std::string("the manifest's '") + key + "' is not " +
                 (std::is_same_v<T, std::string> ? "text" : "a value of the right kind"));
  }
}

template <class V>
Result<V> tripleField(const Reader& r, const json& j, const char* key) {
  auto a = field<std::array<typename V::value_type, 3>>(r, j, key);
  if (!a) return a.error();
  return V((*a)[0], (*a)[1], (*a)[2]);
}

Result<Part> readPart(const Reader& r, const json& j, const Lattice& lattice) {
  Part p;
  auto name = field<std::string>(r, j, "name");
  if (!name) return name.error();
  auto colour = tripleField<glm::vec3>(r, j, "colour");
  if (!colour) return colour.error();
  auto visible = field<bool>(r, j, "visible");
  if (!visible) return visible.error();
  auto first = tripleField<glm::ivec3>(r, j, "first");
  if (!first) return first.error();
  auto translation = tripleField<glm::ivec3>(r, j, "translation");
  if (!translation) return translation.error();
  auto turns = tripleField<glm::ivec3>(r, j, "quarter_turns");
  if (!turns) return turns.error();
  auto voxels = field<std::string>(r, j, "voxels");
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
  return p;
}

Result<Assembly> readParts(const Reader& r, const json& j) {
  auto lattice_json = field<json>(r, j, "lattice");
  if (!lattice_json) return lattice_json.error();
  Lattice lattice;
  auto origin = tripleField<glm::dvec3>(r, *lattice_json, "origin");
  auto h = field<double>(r, *lattice_json, "voxel_size");
  auto units = field<std::string>(r, *lattice_json, "units");
  if (!origin) return origin.error();
  if (!h) return h.error();
  if (!units) return units.error();
  if (!(*h > 0.0) || !std::isfinite(*h)) return r.bad("the parts' voxel size is not a positive number");
  lattice = Lattice{*origin, *h, *units};
  auto list = field<json>(r, j, "list");
  if (!list) return list.error();
  if (!list->is_array() || list->empty()) return r.bad("the project's parts are not a list of parts");
  Assembly parts(lattice);
  for (const json& pj : *list) {
    auto p = readPart(r, pj, lattice);
    if (!p) return p.error();
    const size_t k = parts.addPart(std::move(p->voxels), p->name);
    parts.part(k).colour = p->colour;
    parts.part(k).visible = p->visible;
    parts.setPlacement(k, p->placement);
  }
  return parts;
}

Status readView(const Reader& r, const json& j, ProjectFile& p) {
  auto panel = field<std::string>(r, j, "panel");
  auto axis = field<std::string>(r, j, "section_axis");
  auto index = field<int32_t>(r, j, "section_index");
  auto selected = field<std::vector<size_t>>(r, j, "selected_parts");
  if (!panel) return panel.error();
  if (!axis) return axis.error();
  if (!index) return index.error();
  if (!selected) return selected.error();
  p.panel = *panel;
  p.section_axis = *axis;
  p.section_index = *index;
  const size_t n = p.parts ? p.parts->size() : 0;
  for (size_t i : *selected) {
    if (i >= 1 && i <= n) p.selected.push_back(i - 1);
  }
  return Ok{};
}

Status readModel(const Reader& r, const json& j, ProjectFile& p) {
  auto peeled = field<int32_t>(r, j, "peeled");
  auto round_peels = field<std::string>(r, j, "round_peels");
  if (!peeled) return peeled.error();
  if (!round_peels) return round_peels.error();
  if (*peeled < 0) return r.bad("the model's peeled layers are negative");
  p.peeled = *peeled;
  p.round_peels = *round_peels;
  if (j.contains("base")) {
    auto path = field<std::string>(r, j, "base");
    if (!path) return path.error();
    auto g = r.grid(*path);
    if (!g) return g.error();
    p.base = std::move(g).value();
  } else if (!p.parts) {
    return r.bad("the project holds neither a model nor parts");
  }
  if (j.contains("shown")) {
    auto path = field<std::string>(r, j, "shown");
    if (!path) return path.error();
    auto g = r.grid(*path);
    if (!g) return g.error();
    p.shown = std::move(g).value();
  } else {
    p.shown = p.base;
  }
  return Ok{};
}

Result<ProjectFile> readManifest(const Reader& r, const json& j) {
  auto format = field<std::string>(r, j, "format");
  if (!format || *format != kFormat) return r.bad("not a voxmod project (its manifest names no such format)");
  auto version = field<int>(r, j, "version");
  if (!version) return version.error();
  if (*version > kVersion) {
    return makeError(ErrorCode::kUnsupported, r.name + ": a voxmod project of version " + std::to_string(*version) +
                                                  "; this voxmod reads version " + std::to_string(kVersion) +
                                                  " (a newer voxmod wrote it)");
  }
  ProjectFile p;
  auto source = field<std::string>(r, j, "source");
  auto origin = field<std::string>(r, j, "origin");
  auto resolution = field<int64_t>(r, j, "resolution");
  auto units = field<std::string>(r, j, "units");
  auto model = field<json>(r, j, "model");
  auto view = field<json>(r, j, "view");
  if (!source) return source.error();
  if (!origin) return origin.error();
  if (!resolution) return resolution.error();
  if (!units) return units.error();
  if (!model) return model.error();
  if (!view) return view.error();
  p.source = *source;
  p.origin = *origin;
  p.resolution = *resolution;
  p.units = *units;
  if (j.contains("parts")) {
    auto parts = readParts(r, j["parts"]);
    if (!parts) return parts.error();
    p.parts = std::move(parts).value();
  }
  if (Status s = readModel(r, *model, p); !s) return s.error();
  if (Status s = readView(r, *view, p); !s) return s.error();
  return p;
}

}  // namespace

Result<std::vector<uint8_t>> encodeProject(const ProjectFile& p, const std::string& name) {
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
  auto entries = readZip(bytes, name, kWhat, limit);
  if (!entries) return entries.error();
  const Reader r{*entries, name, limit};
  const ZipEntry* m = r.entry("project.json");
  if (!m) return r.bad("not a voxmod project: the zip holds no project.json");
  json j;
  try {
    j = json::parse(m->bytes.begin(), m->bytes.end());
  } catch (const json::parse_error& e) {
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
