#pragma once
// STEP (AP203 / AP214 / AP242) and IGES through Open CASCADE, in two steps so that the tessellation can be made for
// the grid it will be voxelized on: readCadFile reads and heals the exact geometry and gives its bounding box (from
// which the grid's voxel size follows, docs/conventions.md "Grid placement"); tessellateCad then meshes every solid
// with a chordal deflection of kCadDeflectionVoxels of that voxel (docs/accuracy.md, "CAD tessellation").
// loadMeshFile (vox/io/mesh_file.h) does both for a resolution or voxel size given up front.
//
// Model units are millimetres: Open CASCADE converts the file's length unit, which is reported as the file names it.
// Each solid, and each placed instance of an assembly's part, is a body. Faces outside any solid (IGES surface
// models) are sewn at tessellation; a shell that closes becomes a solid, one that stays open is kept with a warning
// when the file has nothing closed, dropped with a warning otherwise.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "vox/core/mesh.h"
#include "vox/core/progress.h"
#include "vox/core/result.h"
#include "vox/io/mesh_file.h"

namespace vox::io {

// The tessellation's chordal deflection as a fraction of the voxel size. Open CASCADE's mesher (BRepMesh) keeps
// edges within the deflection of the exact curves but not every triangle's interior: on the parameter grids it lays
// over spheres, triangle centres were measured up to 2.08 deflections from the surface. voxmod states 0.1 voxel
// (docs/accuracy.md, "CAD tessellation"), so it asks for 0.04.
inline constexpr double kCadDeflectionVoxels = 0.04;
// The distance, in voxels, within which the tessellation lies of the exact surface (checked by the tests).
inline constexpr double kCadSurfaceBoundVoxels = 0.1;

// The exact geometry of a CAD file, read and healed. Copies share it (and are safe to hand to another thread; the
// tessellation is made on a private copy).
class CadModel {
 public:
  // Tight bounding box of the exact geometry in millimetres (before tessellation; the mesh's lies inside it, within
  // the deflection).
  const Box3d& bounds() const;
  int64_t solids() const;      // solids in the file (placed instances counted), before sewing loose faces
  int64_t looseFaces() const;  // faces outside any solid (an IGES surface model has only these)
  MeshFormat format() const;
  const std::string& formatDetail() const;  // e.g. "STEP (AUTOMOTIVE_DESIGN)", "IGES 5.1"
  const std::string& fileUnits() const;     // as the file names it: "INCH", "millimetre", "MM"; empty when unknown
  const std::string& name() const;          // the file, as given
  const std::vector<std::string>& warnings() const;  // from reading and healing
  const std::vector<std::string>& notes() const;

  // Open CASCADE's shape and what was read with it (src/io/cad_model_impl.h): io's own.
  struct Impl;
  explicit CadModel(std::shared_ptr<const Impl> impl);
  const Impl& impl() const;

 private:
  std::shared_ptr<const Impl> impl_;
};

struct CadReadOptions {
  // The unit of the file's coordinates when its header is wrong ("mm", "cm", "m", "in"); empty: the file's.
  std::string units;
  ProgressFn progress;  // fraction of reading + healing; false cancels (kCancelled)
};

// Reads and heals (ShapeFix) a STEP or IGES file. Fails (kParse) on a file Open CASCADE cannot read, a truncated
// file (a STEP file without END-ISO-10303-21, an IGES file without its Terminate record) and a file with no faces.
Result<CadModel> readCadFile(const std::filesystem::path& path, const CadReadOptions& options = {});
// The same from bytes; `format` is kStep or kIges, `name` names the file in messages.
Result<CadModel> readCadBytes(std::span<const uint8_t> bytes, const std::string& name, MeshFormat format,
                              const CadReadOptions& options = {});

// The deflection for a grid of this resolution (voxels along the longest axis of `bounds`) or voxel size (> 0 wins):
// kCadDeflectionVoxels times its voxel size. Fails like placeGridByResolution / placeGridByVoxelSize.
Result<double> cadDeflectionFor(const Box3d& bounds, int64_t resolution, double voxel_size);

// Sews loose faces (tolerance: the deflection), then meshes every body with the given chordal deflection (mm; the
// angular deflection is 0.5 rad) and gathers the triangles, outward facing, in one mesh with the bodies, topology,
// warnings and notes of a MeshFileLoad. Progress covers sewing and meshing; false cancels (kCancelled).
Result<MeshFileLoad> tessellateCad(const CadModel& model, double deflection, const ProgressFn& progress = {});

}  // namespace vox::io
