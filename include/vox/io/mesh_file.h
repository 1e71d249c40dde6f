#pragma once
// Mesh and CAD files through one entry point (docs/file-format.md, "Mesh and CAD input"). The reader is chosen by
// the file's extension and confirmed by its content: a .ply that holds a STEP file is refused with a message that
// says so. STL goes to voxmod's own reader (vox/io/stl.h); OBJ, PLY, 3MF, glTF/GLB and OFF to assimp; STEP and
// IGES to Open CASCADE, which tessellates them for the grid they will be voxelized on (vox/io/cad.h). Every format
// gives the same TriangleMesh, topology report, warnings and notes as an STL file, plus the file's bodies and its
// length unit.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "vox/core/mesh.h"
#include "vox/core/mesh_bodies.h"
#include "vox/core/progress.h"
#include "vox/core/result.h"

namespace vox::io {

class CadModel;  // vox/io/cad.h

enum class MeshFormat { kUnknown, kStl, kObj, kPly, k3mf, kGltf, kGlb, kOff, kStep, kIges };

// "STL", "OBJ", "PLY", "3MF", "glTF", "GLB", "OFF", "STEP", "IGES"; "unknown".
const char* meshFormatName(MeshFormat format);
// By extension, case-insensitive: .stl .obj .ply .3mf .gltf .glb .off .step .stp .iges .igs; kUnknown otherwise.
MeshFormat meshFormatFromExtension(const std::filesystem::path& path);
// By content: the format whose signature the first bytes carry (PLY "ply", 3MF a zip, GLB "glTF", STEP
// "ISO-10303-21;", IGES a Start record, OFF "OFF", glTF a JSON object with "asset", ASCII STL "solid ... facet").
// kUnknown when none matches: OBJ and binary STL carry no signature.
MeshFormat meshFormatFromContent(std::span<const uint8_t> bytes);
// STEP and IGES: exact geometry that is tessellated on reading (model units are millimetres).
bool isCadFormat(MeshFormat format);
// The extensions loadMeshFile reads, in the order file dialogs list them: {".stl", ".obj", ...}.
const std::vector<std::string>& meshFileExtensions();

struct MeshFileOptions {
  // The grid the mesh is for. CAD files are tessellated so that the mesh lies within kCadDeflectionVoxels of a
  // voxel of the exact surface (docs/accuracy.md), the voxel being the one this resolution (voxels along the
  // longest axis of the shape's bounding box) or voxel size gives. Ignored by mesh formats.
  int64_t resolution = 200;
  double voxel_size = 0.0;  // model units (mm for CAD files); > 0 overrides resolution
  // The length unit of the file's coordinates when the file's own is missing or wrong ("mm", "cm", "m", "in"); empty:
  // the file's. Mesh coordinates are kept as they are and labelled with it; CAD coordinates are converted from it to
  // millimetres.
  std::string units;
  uint64_t memory_limit_bytes = 0;  // refuse (kLimit) files whose content would need more; 0: physical memory
  ProgressFn progress;              // reading, healing and tessellating a CAD file; false from it cancels (kCancelled)
};

// A body of the file: a STEP / IGES solid (each placed instance of an assembly's part), a 3MF build item's object,
// a glTF / OBJ mesh as the scene places it. Its triangles are mesh.triangles[first_triangle, + triangle_count).
struct MeshBody {
  std::string name;  // as the file names it; "body N" (from 1) when it names none
  uint64_t first_triangle = 0;
  uint64_t triangle_count = 0;
};

// The bodies a file names, as vox/core/mesh_bodies.h's MeshBodies (for voxelizeBodies) with their names: a CAD
// file's solids, or the objects / meshes of a file that has several. Solids that touch stay apart, where splitting
// by welded shells would join them. Bodies without triangles are left out.
struct FileBodies {
  MeshBodies bodies;
  std::vector<std::string> names;  // per body of `bodies`
};

// The file's own bodies when `cad` or there are several of them; nullopt for a file that is one mesh (every STL, a
// one-object OBJ), whose bodies are its shells (splitBodies), and when the ranges do not tile
// [0, triangle_count) in order.
std::optional<FileBodies> fileBodies(std::span<const MeshBody> bodies, size_t triangle_count, bool cad);

struct MeshFileLoad {
  TriangleMesh mesh;             // every body, in file order; mesh.name is the file name as given
  std::vector<MeshBody> bodies;  // at least one
  MeshTopology topology;         // of the whole mesh, welded by exact position, as for STL
  MeshFormat format = MeshFormat::kUnknown;
  std::string format_detail;  // e.g. "binary STL", "ASCII PLY", "STEP (AUTOMOTIVE_DESIGN)", "IGES 5.1"
  // What the mesh's coordinates are in: "mm", "cm", "m", "in", or "model" when neither the file nor the caller
  // says. CAD files: always "mm".
  std::string units = "model";
  std::string file_units;   // the unit as the file declares it ("INCH", "millimeter"); empty when it declares none
  double deflection = 0.0;  // CAD files: the chordal deflection the tessellation was made with (model units)
  // CAD files: the exact geometry, to tessellate again for a finer grid (tessellateCad in vox/io/cad.h).
  std::shared_ptr<const CadModel> cad;
  std::vector<std::string> warnings;  // e.g. "part.ply: not watertight: ...", "part.iges: open surface ..."
  std::vector<std::string> notes;     // e.g. "part.3mf: unit inch (from the file)"
};

// Reads a mesh or CAD file. Fails (kParse) on a file whose content is not what its extension says, a malformed or
// truncated file, a file without triangles or with non-finite coordinates; kIo when it cannot be read; kLimit past
// the memory limit; kCancelled when progress says so. An unknown extension is read by its content (and as STL when
// it has no signature, as voxmod always did). Messages name the file as given.
Result<MeshFileLoad> loadMeshFile(const std::filesystem::path& path, const MeshFileOptions& options = {});
// The same from bytes in memory; `name`'s extension picks the reader and names the file in messages. Files that
// refer to others (a .gltf's buffers, an .obj's materials) get none of them.
Result<MeshFileLoad> parseMeshFile(std::span<const uint8_t> bytes, const std::string& name,
                                   const MeshFileOptions& options = {});

}  // namespace vox::io
