#pragma once
// What the action table's entries run (actions.cpp): small functions over the operations (operations.h), one per
// entry, with and without values. Only the action table calls these; everything else dispatches. No ImGui here.
#include "app/actions.h"

namespace vox::app::actions {

// Shows panel p (the tab switches on the next frame).
void showPanel(AppState& s, Panel p);
// A usage error of an action's values, saying what it takes.
Error badValues(std::string message);
// Row N (counted from 1, as panels show their lists) of a list of `count` rows, as an index from 0; a usage error
// naming the action `what` and the panel's list, or `none` when the list is empty.
Result<size_t> listRow(const ActionArgs& a, size_t count, const std::string& what, const std::string& panel,
                       const std::string& none);

// ---- Conditions ----
bool hasModel(const AppState& s);
bool hasOrphanAutosave(const AppState& s);    // a window that is gone left unsaved work (autosave.h)
bool skinLayersComputing(const AppState& s);  // the model's skin layers are being computed
bool skinLayersCancelled(const AppState& s);  // the user cancelled them (Compute the skin layers asks again)
bool thicknessComputing(const AppState& s);
bool thicknessCancelled(const AppState& s);
bool hasMesh(const AppState& s);
bool hasSection(const AppState& s);
bool hasXray(const AppState& s);
bool hasMeasure(const AppState& s);
bool canPeel(const AppState& s);
bool canPeelBack(const AppState& s);
bool hasDisputed(const AppState& s);
bool canCancel(const AppState& s);     // voxelizing, loading, the thickness or a volume export runs
bool hasThickness(const AppState& s);  // the Thickness panel's result for the model shown
bool hasDepth(const AppState& s);      // the Skin panel's skin layers (the depth map) of the model

// ---- File ----
void open(AppState& s);
Status openPath(AppState& s, const ActionArgs& a);
void save(AppState& s);
void saveAs(AppState& s);
Status savePath(AppState& s, const ActionArgs& a);
void exportBinvox(AppState& s);
Status exportBinvoxPath(AppState& s, const ActionArgs& a);
void exportSurface(AppState& s);
Status exportSurfacePath(AppState& s, const ActionArgs& a);
void exportSmoothSurface(AppState& s);
Status exportSmoothSurfacePath(AppState& s, const ActionArgs& a);
void exportView(AppState& s);
Status exportViewPath(AppState& s, const ActionArgs& a);
void exportSection(AppState& s);
Status exportSectionPath(AppState& s, const ActionArgs& a);
void exportXray(AppState& s);
Status exportXrayPath(AppState& s, const ActionArgs& a);
void exportCsv(AppState& s);
Status exportCsvPath(AppState& s, const ActionArgs& a);
void exportVolume(AppState& s);
Status exportVolumePath(AppState& s, const ActionArgs& a);
void exportReport(AppState& s);
Status exportReportPath(AppState& s, const ActionArgs& a);
void exportThickness(AppState& s);
Status exportThicknessPath(AppState& s, const ActionArgs& a);
void exportDepth(AppState& s);
Status exportDepthPath(AppState& s, const ActionArgs& a);
void exportXrayVolume(AppState& s);
Status exportXrayVolumePath(AppState& s, const ActionArgs& a);
Status exportSize(AppState& s, const ActionArgs& a);

// ---- Edit ----
void measureClear(AppState& s);
Status measureAt(AppState& s, const ActionArgs& a);

// ---- Model ----
void voxelizeDialog(AppState& s);
Status voxelizeAt(AppState& s, const ActionArgs& a);
Status modelUnitsAt(AppState& s, const ActionArgs& a);  // U: what the model's coordinates are in (units.h)
void cancelAll(AppState& s);

// ---- View ----
void fit(AppState& s);
void viewIso(AppState& s);
void viewPosX(AppState& s);
void viewNegX(AppState& s);
void viewPosY(AppState& s);
void viewNegY(AppState& s);
void viewPosZ(AppState& s);
void viewNegZ(AppState& s);
Status viewAngles(AppState& s, const ActionArgs& a);
void zoomIn(AppState& s);
void zoomOut(AppState& s);
Status zoomBy(AppState& s, const ActionArgs& a);
void toggleLit(AppState& s);
bool isLit(const AppState& s);
void toggleOrtho(AppState& s);  // the 3D view's projection: orthographic or perspective
bool isOrthographic(const AppState& s);
void toggleRound(AppState& s);
bool isRound(const AppState& s);
void toggleLod(AppState& s);
bool isLod(const AppState& s);
void toggleCut(AppState& s);
bool isCut(const AppState& s);
void toggleDisputed(AppState& s);
bool isDisputed(const AppState& s);
void panelModel(AppState& s);
bool onModel(const AppState& s);
void panelSection(AppState& s);
bool onSection(const AppState& s);
void panelSkin(AppState& s);
bool onSkin(const AppState& s);
void panelXray(AppState& s);
bool onXray(const AppState& s);
void panelMass(AppState& s);
bool onMass(const AppState& s);
void panelThickness(AppState& s);
bool onThickness(const AppState& s);
Status minWallAt(AppState& s, const ActionArgs& a);
Status minAreaAt(AppState& s, const ActionArgs& a);  // AREA model units^2: smaller walls are specks; < 0: W^2
Status thicknessMethodAt(AppState& s, const ActionArgs& a);
void cancelRaysNow(AppState& s);  // the rays being cast for the Thickness panel
bool raysComputingNow(const AppState& s);
// N: the Thickness panel's thin-wall region N or hot spot N (1: the first of its list), selected and shown: the
// section through it, the 3D view turned about it.
Status thinRegionAt(AppState& s, const ActionArgs& a);
Status hotSpotAt(AppState& s, const ActionArgs& a);

// ---- Section ----
void sectionPrev(AppState& s);
void sectionNext(AppState& s);
void sectionPlay(AppState& s);
bool isPlaying(const AppState& s);
Status sectionAt(AppState& s, const ActionArgs& a);
// Z [U V]: the axis section's picture zoomed Z times (1: whole, at most kMaxSectionZoom), about the voxel (U, V) of
// the picture (along its right and up axes; default: where it is now), kept within the picture.
Status sectionZoom(AppState& s, const ActionArgs& a);
void sectionWhole(AppState& s);                                // zoom 1
Status sectionPlane(AppState& s, const ActionArgs& a);         // NX NY NZ [OFFSET]: a section at any angle
Status sectionPlaneThrough(AppState& s, const ActionArgs& a);  // I J K [x 3]: through picked voxels (section_plane.cpp)

// ---- Skin ----
void peelOne(AppState& s);
void peelN(AppState& s);
Status peelCount(AppState& s, const ActionArgs& a);
void peelBack(AppState& s);
void peelCore(AppState& s);
void peelReset(AppState& s);
void peelDistanceN(AppState& s);
Status peelDistanceAt(AppState& s, const ActionArgs& a);

// ---- X-ray ----
Status xrayAlong(AppState& s, const ActionArgs& a);

// ---- Parts (part_actions.cpp) ----
bool hasParts(const AppState& s);
bool canSplit(const AppState& s);
bool canAddPart(const AppState& s);
bool hasInterference(const AppState& s);
void panelParts(AppState& s);
bool onParts(const AppState& s);
void splitBodies(AppState& s);
Status splitBodiesWith(AppState& s, const ActionArgs& a);  // 6 | 26 (a voxel model's connectivity)
void addPartDialog(AppState& s);
Status addPartPath(AppState& s, const ActionArgs& a);
void booleanSelected(AppState& s);
Status booleanWith(AppState& s, const ActionArgs& a);  // OP [A B]: part numbers from 1; none: the selected two
void removeSelected(AppState& s);
Status removeAt(AppState& s, const ActionArgs& a);  // N, from 1
void findInterferenceNow(AppState& s);
Status showPairAt(AppState& s, const ActionArgs& a);     // N: the list's row from 1; 0 clears
Status contactAt(AppState& s, const ActionArgs& a);      // T: overlaps at most T thick (model units) are contact
Status selectPartsAt(AppState& s, const ActionArgs& a);  // N...: part numbers from 1
Status partVisibleAt(AppState& s, const ActionArgs& a);  // N on|off
Status partsScopeAt(AppState& s, const ActionArgs& a);   // union | selected
Status placePartAt(AppState& s, const ActionArgs& a);    // N TX TY TZ [QX QY QZ]: model units, quarter turns
Status turnPartAt(AppState& s, const ActionArgs& a);     // N x|y|z: one more quarter turn (+90 degrees)
Status partColourAt(AppState& s, const ActionArgs& a);   // N R G B (0 to 1) or N #rrggbb
bool hasPartsNow(const AppState& s);                     // a scene of parts (busy or not): save-parts
void savePartsDialog(AppState& s);
Status savePartsPath(AppState& s, const ActionArgs& a);  // DIR: each part as DIR/NN_name.vxm
void clearanceSelected(AppState& s);                     // the two selected parts
Status clearanceAt(AppState& s, const ActionArgs& a);    // A B: part numbers from 1
bool interferenceRunning(const AppState& s);
void cancelInterferenceNow(AppState& s);

// ---- Casting (casting_actions.cpp) ----
void panelCasting(AppState& s);
bool onCasting(const AppState& s);
bool hasCasting(const AppState& s);  // a run for the model shown (perhaps with other settings)
bool canSimulateCasting(const AppState& s);
bool castingComputingNow(const AppState& s);
bool isCastingPlaying(const AppState& s);
Status castingAlloyAt(AppState& s, const ActionArgs& a);             // aluminium, a356, grey-iron, carbon-steel
Status castingMouldAt(AppState& s, const ActionArgs& a);             // silica-sand, steel
Status castingSuperheatAt(AppState& s, const ActionArgs& a);         // K above the liquidus, 0..1000
Status castingMouldTemperatureAt(AppState& s, const ActionArgs& a);  // C, or "default" (the mould's own)
Status castingFeederAt(AppState& s, const ActionArgs& a);            // X Y Z D H, model units
void castingPlaceFeederMode(AppState& s);                            // the next click on the 3D view places one
Status castingPlaceFeederAt(AppState& s, const ActionArgs& a);       // I J K: a surface voxel of the part
Status castingDeleteFeederAt(AppState& s, const ActionArgs& a);      // N: the feeders list's row from 1
void simulateCastingNow(AppState& s);
void cancelCastingNow(AppState& s);
Status castingFieldChoice(AppState& s, const ActionArgs& a);  // time, niyama or modulus
Status castingTimeAt(AppState& s, const ActionArgs& a);       // seconds from pouring, or "end"
void castingPlay(AppState& s);
Status castingHotSpotAt(AppState& s, const ActionArgs& a);  // N: the hot spots list's row from 1

// ---- Print (print_actions.cpp) ----
void panelPrint(AppState& s);
bool onPrint(const AppState& s);
bool printComputingNow(const AppState& s);
bool printCancelledNow(const AppState& s);
bool hasPrint(const AppState& s);                             // the Print panel's result for the model and choices
Status printDirectionAt(AppState& s, const ActionArgs& a);    // +z|-z|+x|-x|+y|-y or X,Y,Z (or X Y Z)
Status overhangAngleAt(AppState& s, const ActionArgs& a);     // DEG in [0, 90)
void printOrient(AppState& s);                                // search the build directions
Status printOrientationAt(AppState& s, const ActionArgs& a);  // N: the directions list's row from 1, applied
Status printCavityAt(AppState& s, const ActionArgs& a);       // N: the cavities list's row from 1
void printLayFaceMode(AppState& s);                           // the next click on the 3D view lays a face down
Status printLayFaceAt(AppState& s, const ActionArgs& a);      // I J K: the surface voxel whose face goes down
void computePrint(AppState& s);
void cancelPrintNow(AppState& s);

// ---- Help and dialogs ----
void controls(AppState& s);
void about(AppState& s);
void terms(AppState& s);                           // Help > Terms, from the top
Status termsAt(AppState& s, const ActionArgs& a);  // TERM: Help > Terms at that term (glossary.h)
void closeDialogs(AppState& s);

}  // namespace vox::app::actions
