#include "app/glossary.h"

#include <cctype>

namespace vox::app {
namespace {

constexpr Term kTerms[] = {
    {"voxel", "Voxel",
     "A cube of the grid, filled when its centre lies inside the part. Every length voxmod reports is measured "
     "between voxel centres or along voxel faces, so results are exact to the grid and within a voxel of the part."},
    {"suspect-voxels", "Suspect voxels",
     "Filled voxels with four or five of their six faces open: lone voxels, lines one voxel thick and their ends. "
     "A few follow sharp edges thinner than a voxel; many mean the mesh has holes or the resolution is too coarse "
     "for its thin features. Voxelize finer or repair the mesh."},
    {"skin-layer", "Skin layer",
     "The filled voxels with an open face, peeled off one layer at a time: layer 1 is the outer skin, layer 2 what "
     "the first peel uncovers, and so on. The layer number is the depth below the surface in face steps."},
    {"core", "Core",
     "The last skin layer before nothing is left: the thickest region of the part, found without choosing a "
     "direction. Peel to core shows it."},
    {"local-thickness", "Local thickness",
     "At a voxel, the diameter of the largest ball that fits inside the part and holds the voxel. Exact on the "
     "grid. Convex edges and corners read thin under this definition, which is no fault of the part: see Wall."},
    {"wall", "Wall",
     "Material between two opposite surfaces. Its thickness is read across it, not at its edges: a convex edge or "
     "corner is never a thin wall. The thinnest wall is the part's smallest such thickness."},
    {"ray-thickness", "Ray thickness",
     "Measured on the surface, along the inward normal to the opposite wall, counted only where the two sides face "
     "each other within the ray angle. Reads a plate's thickness at any angle; the rays' ends colour the voxels "
     "they cross."},
    {"speck", "Speck",
     "A thin region smaller than the minimum area: left out of the list of thin walls so that a few stray voxels "
     "do not hide the walls that matter."},
    {"hot-spot", "Hot spot",
     "A centre of a thick region: a point deeper below the surface than everything about it. In a casting these "
     "freeze last; each needs metal fed to it while it shrinks."},
    {"modulus", "Modulus",
     "Volume over cooling area (V/A, Chvorinov's modulus) of the region a hot spot or feeder stands for. Freezing "
     "time grows with its square: a feeder must have a larger modulus (about 1.2 times) than the region it feeds."},
    {"isolated", "Isolated",
     "A hot spot every path from which to a thicker region passes through a clearly thinner neck. The neck freezes "
     "first and cuts it off: without its own feeder it shrinks into porosity."},
    {"niyama", "Niyama",
     "The temperature gradient over the square root of the cooling rate as the metal freezes ((K s)^1/2 / mm). Low "
     "values, under about 1 for steel, mark where shrinkage porosity forms though the region was fed."},
    {"interference", "Interference",
     "Two parts sharing voxels: material of one inside the other. An overlap no thicker than the contact tolerance "
     "is contact (parts that touch overlap by a voxel or two), not interference."},
    {"clearance", "Clearance",
     "The gap between two parts: the distance between their closest voxels' centres less one voxel. Zero when they "
     "touch."},
    {"overhang", "Overhang",
     "Downward-facing surface steeper than the overhang angle from the build direction: a printer needs support "
     "under it."},
    {"trapped-cavity", "Trapped cavity",
     "A closed void inside the part. Powder or resin left in it cannot get out; the shortest drain says how far a "
     "hole must go to empty it."},
};

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

std::span<const Term> glossary() { return kTerms; }

const Term* findTerm(std::string_view key) {
  const std::string k = lower(key);
  for (const Term& t : kTerms)
    if (k == t.key || k == lower(t.name)) return &t;
  return nullptr;
}

std::string termKeys() {
  std::string out;
  for (const Term& t : kTerms) out += (out.empty() ? "" : ", ") + std::string(t.key);
  return out;
}

}  // namespace vox::app
