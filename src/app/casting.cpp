#include "app/casting.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include <glm/geometric.hpp>

#include "app/document.h"
#include "app/parts.h"

namespace vox::app {

CastingKey wantedCastingKey(const AppState& state) {
  CastingKey key = state.casting_ui.chosen;
  key.model_version = state.model_version;
  key.units = state.model.frame().units;
  key.feeders = placedFeeders(state);
  return key;
}

namespace {

// The solidification times as bytes over the model's grid (CastingOutcome::time_bytes).
void timeBytes(CastingOutcome& out, const Dims& dims) {
  const CastingResult& c = out.run.result;
  float first = 0.0f;
  for (const float t : c.time.values)
    if (t > 0.0f && (first == 0.0f || t < first)) first = t;
  out.first_solid_s = first;
  const double span = std::max(c.last_metal_s - double(first), 1e-30);
  out.time_bytes.assign(size_t(dims.count()), 0);
  size_t i = 0;
  for (int32_t z = 0; z < dims.nz; ++z)
    for (int32_t y = 0; y < dims.ny; ++y)
      for (int32_t x = 0; x < dims.nx; ++x, ++i) {
        const glm::ivec3 q = glm::ivec3(x, y, z) + c.part_offset;
        const float t = c.time.at(q.x, q.y, q.z);
        if (t > 0.0f) out.time_bytes[i] = uint8_t(2 + std::lround(253.0 * std::clamp((t - first) / span, 0.0, 1.0)));
      }
}

}  // namespace

void requestCasting(AppState& state) {
  state.casting.poll();
  CastingUi& ui = state.casting_ui;
  if (const CastingOutcome* r = currentCasting(state); r && r->id != ui.seen_result) {
    ui.seen_result = r->id;  // a new run: its front starts at its end
    ui.time_shown = -1.0;
    ui.playing = false;
  }
  if (!ui.asked || state.model.empty() || ui.asked_key.model_version != state.model_version) return;
  const CastingKey key = ui.asked_key;
  if (!state.casting.wants(key)) return;
  ui.asked = false;  // once: a failure or a cancel is not run again until asked
  CastingParams params;
  const Alloy* alloy = findAlloy(key.alloy);
  const MouldMaterial* mould = findMould(key.mould);
  if (!alloy || !mould) return;
  params.alloy = *alloy;
  params.mould = *mould;
  if (key.mould_temperature_c > -273.0) params.mould.temperature_c = key.mould_temperature_c;
  params.superheat_k = key.superheat_k;
  params.feeders = key.feeders;
  // the metal without its feeders (parts of the scene): the parts that are not feeders, or the selected one
  VoxelGrid model = state.model;
  std::shared_ptr<const Assembly> scene = key.feeders.empty() ? nullptr : state.doc.model->parts;
  const std::vector<size_t>& selected = state.parts_ui.selected;
  const size_t only = scene && state.parts_ui.scope_selected && !selected.empty() && selected.front() < scene->size() &&
                              !scene->part(selected.front()).feeder
                          ? selected.front()
                          : SIZE_MAX;
  const uint64_t id = takeId(state);
  state.casting.request(
      key, "Simulating the casting", [model, scene, only, id, key, params](const ProgressFn& progress) {
        using R = Result<std::shared_ptr<const CastingOutcome>>;
        const VoxelGrid grid = scene ? castPart(*scene, only) : model;
        if (grid.filledCount() == 0) {
          return R(makeError(ErrorCode::kInvalidArgument, "there is no metal to cast: every part is a feeder"));
        }
        // the modulus 0..10% of the bar, the simulation the rest
        const workflow::CastingProgress bar = [&progress](workflow::CastingStage stage, double f) {
          return !progress || progress(stage == workflow::CastingStage::kModulus ? 0.1 * f : 0.1 + 0.9 * f);
        };
        auto run = workflow::runCasting(grid, params, bar);
        if (!run) return R(run.error());
        auto out = std::make_shared<CastingOutcome>();
        out->id = id;
        out->key = key;
        out->run = std::move(run).value();
        out->seconds = out->run.modulus_s + out->run.result.simulate_s;
        out->niyama_scale = niyamaScale(out->run.result.niyama);
        timeBytes(*out, grid.dims());
        return R(std::shared_ptr<const CastingOutcome>(std::move(out)));
      });
}

const CastingOutcome* currentCasting(const AppState& state) {
  const auto* held = state.casting.held();
  if (!held || !*held || (*held)->key.model_version != state.model_version) return nullptr;
  return held->get();
}

bool castingStale(const AppState& state) {
  const CastingOutcome* r = currentCasting(state);
  return r && !(r->key == wantedCastingKey(state));
}

bool castingComputing(const AppState& state) { return state.casting.busy(); }

const Error* castingError(const AppState& state) { return state.casting.error(state.casting_ui.asked_key); }

void simulateCasting(AppState& state) {
  CastingUi& ui = state.casting_ui;
  // a run that failed for these settings (no units then, too little memory) is tried again when asked: its error
  // goes (an error held means no result is)
  if (!state.casting.busy() && state.casting.error(wantedCastingKey(state))) state.casting.clear();
  ui.asked_key = wantedCastingKey(state);
  ui.asked = true;
  if (const CastingOutcome* r = currentCasting(state); r && r->key == ui.asked_key) ui.asked = false;
}

void cancelCasting(AppState& state) {
  if (!state.casting.busy()) return;
  // the last result stays shown (the run under way is abandoned): the cancelled run leaves nothing
  const auto* held = state.casting.held();
  if (held && *held) {
    state.casting.rekey((*held)->key);
  } else {
    state.casting.clear();
  }
  state.casting_ui.asked = false;
}

Status setCastingAlloy(AppState& state, const std::string& name) {
  if (!findAlloy(name))
    return makeError(ErrorCode::kInvalidArgument, "unknown alloy '" + name + "'; known: " + alloyNames());
  state.casting_ui.chosen.alloy = name;
  return Ok{};
}

Status setCastingMould(AppState& state, const std::string& name) {
  if (!findMould(name))
    return makeError(ErrorCode::kInvalidArgument, "unknown mould '" + name + "'; known: " + mouldNames());
  state.casting_ui.chosen.mould = name;
  return Ok{};
}

Status placeFeederAt(AppState& state, glm::ivec3 voxel) {
  const VoxelGrid& g = state.model;
  if (!g.inBounds(voxel.x, voxel.y, voxel.z) || !g.get(voxel.x, voxel.y, voxel.z)) {
    return makeError(ErrorCode::kInvalidArgument, "place-feeder: no part at that voxel");
  }
  // sized from the last run, even when the parts have changed since (the hot spots lie where they were)
  const auto* held = state.casting.held();
  const CastingOutcome* r = held && *held ? held->get() : nullptr;
  if (!r) {
    return makeError(ErrorCode::kInvalidArgument,
                     "place-feeder: simulate first, so that the feeder can be sized for the hot spot it should feed");
  }
  const glm::dvec3 at = g.frame().voxelCentre(voxel.x, voxel.y, voxel.z);
  const CastingHotSpot* nearest = nullptr;
  double best = std::numeric_limits<double>::infinity();
  for (const CastingHotSpot& s : r->run.result.hot_spots) {
    if (s.in_feeder || !s.isolated || s.modulus <= 0.0) continue;
    const double d = glm::distance(s.centre, at);
    if (d < best) {
      best = d;
      nearest = &s;
    }
  }
  const double m = nearest ? nearest->modulus : r->run.modulus_max;
  if (!(m > 0.0)) return makeError(ErrorCode::kInvalidArgument, "place-feeder: the part has no modulus to feed");
  Feeder f;
  f.diameter = 5.6 * m;
  f.height = 1.5 * f.diameter;
  // standing on the top of the column of part above the voxel clicked
  int32_t top = voxel.z;
  while (top + 1 < g.nz() && g.get(voxel.x, voxel.y, top + 1)) ++top;
  f.base = glm::dvec3(at.x, at.y, g.frame().origin.z + double(top + 1) * g.voxelSize());
  if (Status s = addFeederPart(state, f); !s) return s;
  state.casting_ui.placing_feeder = false;
  return Ok{};
}

const CastingHotSpot* selectedCastingSpot(const AppState& state) {
  const CastingOutcome* r = currentCasting(state);
  const CastingUi& ui = state.casting_ui;
  if (!r || ui.selected_result != r->id || ui.selected_spot < 0 ||
      size_t(ui.selected_spot) >= r->run.result.hot_spots.size())
    return nullptr;
  return &r->run.result.hot_spots[size_t(ui.selected_spot)];
}

float castingFieldAt(const CastingOutcome& r, CastingField field, glm::ivec3 v) {
  const CastingResult& c = r.run.result;
  if (field == CastingField::kModulus) {
    const ScalarField& m = r.run.modulus;
    if (v.x < 0 || v.y < 0 || v.z < 0 || v.x >= m.dims.nx || v.y >= m.dims.ny || v.z >= m.dims.nz) return 0.0f;
    return m.at(v.x, v.y, v.z);
  }
  const glm::ivec3 q = v + c.part_offset;
  if (q.x < 0 || q.y < 0 || q.z < 0 || q.x >= c.dims.nx || q.y >= c.dims.ny || q.z >= c.dims.nz) return 0.0f;
  return field == CastingField::kTime ? c.time.at(q.x, q.y, q.z) : c.niyama.at(q.x, q.y, q.z);
}

double castingFieldMax(const CastingOutcome& r, CastingField field) {
  if (field == CastingField::kTime) return r.run.result.last_metal_s;
  if (field == CastingField::kModulus) return r.run.modulus_max;
  return r.niyama_scale;
}

double niyamaScale(const ScalarField& niyama) {
  std::vector<float> v;
  for (const float x : niyama.values)
    if (x > 0.0f) v.push_back(x);
  if (v.empty()) return 1.0;
  const size_t k = v.size() * 95 / 100;
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
  return std::max(double(v[k]), 1e-6);
}

double castingTimeShown(const AppState& state, const CastingOutcome& r) {
  const double end = r.run.result.last_metal_s;
  return state.casting_ui.time_shown < 0.0 ? end : std::min(state.casting_ui.time_shown, end);
}

uint8_t castingFrontByte(const CastingOutcome& r, double front_s) {
  const double span = std::max(r.run.result.last_metal_s - r.first_solid_s, 1e-30);
  return uint8_t(2 + std::lround(253.0 * std::clamp((front_s - r.first_solid_s) / span, 0.0, 1.0)));
}

uint8_t castingColourValue(const CastingOutcome& r, CastingField field, double front_s, glm::ivec3 voxel) {
  const double max = castingFieldMax(r, field);
  const float t = castingFieldAt(r, CastingField::kTime, voxel);
  if (t <= 0.0f) return 0;
  if (field == CastingField::kTime && t > front_s) return 1;  // still liquid at the front
  // times from the first voxel solid to the last; the other fields from 0
  const double from = field == CastingField::kTime ? r.first_solid_s : 0.0;
  const double v = field == CastingField::kTime ? t : castingFieldAt(r, field, voxel);
  return uint8_t(2 + std::lround(253.0 * std::clamp((v - from) / std::max(max - from, 1e-30), 0.0, 1.0)));
}

const char* castingFieldName(CastingField field) {
  switch (field) {
    case CastingField::kNiyama:
      return "Niyama criterion";
    case CastingField::kModulus:
      return "geometric modulus";
    case CastingField::kTime:
      break;
  }
  return "solidification time";
}

std::string castingFieldUnit(CastingField field, const std::string& units) {
  if (field == CastingField::kTime) return "s";
  if (field == CastingField::kNiyama) return "(K s)^0.5/mm";
  return units.empty() || units == "model" ? "model units" : units;
}

void advanceCastingPlay(AppState& state, double frame_s) {
  CastingUi& ui = state.casting_ui;
  const CastingOutcome* r = currentCasting(state);
  if (!ui.playing || !r || state.panel != Panel::kCasting || ui.field != CastingField::kTime) {
    ui.playing = false;
    return;
  }
  const double end = r->run.result.last_metal_s, start = r->first_solid_s;
  const double now = ui.time_shown < 0.0 || ui.time_shown >= end ? start : std::max(ui.time_shown, start);
  const double next = now + (end - start) * std::clamp(frame_s, 0.0, 0.2) / 8.0;
  if (next >= end) {
    ui.time_shown = -1.0;
    ui.playing = false;
  } else {
    ui.time_shown = next;
  }
  state.redraw_frames = std::max(state.redraw_frames, 2);
}

}  // namespace vox::app
