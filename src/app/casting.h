#pragma once
// The Casting panel's simulation (vox/workflow/casting_run.h): the model poured in the chosen alloy into the chosen
// mould with its feeders, run in the background when the user asks (it takes seconds to a minute) and keyed by the
// model version and every setting. The views' colours for a field and a freezing front are made here. No ImGui and
// no GL.
#include <string>
#include <vector>

#include "app/app_state.h"

namespace vox::app {

// Each frame (updateDocument): starts the run the user asked for while the Casting panel is open.
void requestCasting(AppState& state);
// The settings in the panel, for the model shown.
CastingKey wantedCastingKey(const AppState& state);
// The last run for the model shown (the settings may have changed since: castingStale), or null.
const CastingOutcome* currentCasting(const AppState& state);
bool castingStale(const AppState& state);  // the result shown was run with other settings
bool castingComputing(const AppState& state);
const Error* castingError(const AppState& state);
void simulateCasting(AppState& state);  // runs the settings in the panel
void cancelCasting(AppState& state);
Status setCastingAlloy(AppState& state, const std::string& name);
Status setCastingMould(AppState& state, const std::string& name);
// A feeder standing on the top face of surface voxel `voxel`, sized for the hot spot it should feed: the isolated
// hot spot nearest it of the last run (its modulus times 1.2; D = 5.6 M, H = 1.5 D gives D H / (4 H + D) = 1.2 M).
Status placeFeederAt(AppState& state, glm::ivec3 voxel);
// The hot spot last clicked in the list, or null.
const CastingHotSpot* selectedCastingSpot(const AppState& state);
// The field shown at each voxel of `r`'s grid (model units or seconds), and its largest value.
float castingFieldAt(const CastingOutcome& r, CastingField field, glm::ivec3 voxel);
double castingFieldMax(const CastingOutcome& r, CastingField field);
double niyamaScale(const ScalarField& niyama);
// The front's time: ui.time_shown, or the end.
double castingTimeShown(const AppState& state, const CastingOutcome& r);
// 1..255 along the colour ramp for a voxel of the metal (0: none); at the front, metal still liquid is 1 (under the
// renderer's red threshold).
uint8_t castingColourValue(const CastingOutcome& r, CastingField field, double front_s, glm::ivec3 voxel);
// The front's time as a byte of CastingOutcome::time_bytes: bytes above it are still liquid.
uint8_t castingFrontByte(const CastingOutcome& r, double front_s);
// The field's name and unit for legends: "solidification time", "s".
const char* castingFieldName(CastingField field);
std::string castingFieldUnit(CastingField field, const std::string& units);
// Advances the front while playing (frame_s of wall time: the whole freezing in 8 s); stops at the end.
void advanceCastingPlay(AppState& state, double frame_s);

}  // namespace vox::app
