// assimp's importers, run so that the geometry voxmod voxelizes is the file's: the only post-processing steps are
// ValidateDataStructure (refuses out-of-range indices and the like) and Triangulate (n-gons are ear-clipped into
// triangles over the polygon's own corners, so the surface stays the same; the slivers ear-clipping leaves at
// collinear corners are then split away, src/io/polygon_slivers.h). Steps that would change what the
// voxelizer and the topology report see are left out: JoinIdenticalVertices (welds vertices; the report welds by
// exact position itself, so it would change nothing but the time), FindDegenerates and FindInvalidData (remove
// triangles, hiding degenerate ones from the report), PreTransformVertices (applies the scene's transforms but
// merges meshes, losing the bodies) and every smoothing or optimising step.
//
// The scene's node transforms (3MF build items and components, glTF nodes) are applied here, in double, to each
// mesh instance; an identity transform leaves the float32 coordinates bit for bit as stored, so a mesh written as
// OBJ, PLY or 3MF voxelizes exactly as the same triangles in an STL file do. A transform that mirrors (negative
// determinant) also reverses the triangles' order, keeping their outward orientation.
#include "io/mesh_assimp.h"

#include <cmath>
#include <memory>
#include <set>

#include <assimp/DefaultIOSystem.h>
#include <assimp/BaseImporter.h>
#include <assimp/Importer.hpp>
#include <assimp/IOSystem.hpp>
#include <assimp/MemoryIOWrapper.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "io/polygon_slivers.h"
#include "vox/io/file_util.h"

namespace vox::io {
namespace {

// The file in memory under `main_name`; other names (a .gltf's buffers) from `directory`, if any, never outside it.
class BytesIOSystem : public Assimp::IOSystem {
 public:
  BytesIOSystem(std::span<const uint8_t> bytes, std::string main_name, const std::filesystem::path* directory)
      : bytes_(bytes),
        main_(std::move(main_name)),
        directory_(directory ? *directory : std::filesystem::path()),
        has_directory_(directory != nullptr) {}

  bool Exists(const char* file) const override {
    if (isMain(file)) return true;
    std::error_code ec;
    const auto p = sibling(file);
    return !p.empty() && std::filesystem::is_regular_file(p, ec);
  }
  char getOsSeparator() const override { return '/'; }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    if (mode == nullptr || mode[0] != 'r') return nullptr;  // importers only read
    if (isMain(file)) return new Assimp::MemoryIOStream(bytes_.data(), bytes_.size(), false);
    const auto p = sibling(file);
    return p.empty() ? nullptr : files_.Open(p.c_str(), "rb");
  }
  void Close(Assimp::IOStream* stream) override { delete stream; }

 private:
  bool isMain(const char* file) const {
    std::string_view f(file);
    while (f.substr(0, 2) == "./") f.remove_prefix(2);
    return f == main_;
  }
  // A relative name inside the directory, or empty.
  std::filesystem::path sibling(const char* file) const {
    if (!has_directory_) return {};
    const std::filesystem::path rel = std::filesystem::path(file).lexically_normal();
    if (rel.empty() || rel.is_absolute() || *rel.begin() == "..") return {};
    return directory_ / rel;
  }

  std::span<const uint8_t> bytes_;
  std::string main_;
  std::filesystem::path directory_;
  bool has_directory_;
  Assimp::DefaultIOSystem files_;
};

const char* extensionFor(MeshFormat format) {
  switch (format) {
    case MeshFormat::kObj:
      return "obj";
    case MeshFormat::kPly:
      return "ply";
    case MeshFormat::k3mf:
      return "3mf";
    case MeshFormat::kGltf:
      return "gltf";
    case MeshFormat::kGlb:
      return "glb";
    case MeshFormat::kOff:
      return "off";
    default:
      return nullptr;
  }
}

using Matrix = aiMatrix4x4t<double>;

Matrix toDouble(const aiMatrix4x4& m) {
  return Matrix(m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4);
}

// Each mesh's triangles as index triples, after Triangulate; points and lines left out.
struct MeshTriangles {
  std::vector<TriangleIndices> triangles;
  int64_t other_primitives = 0;
};

struct Walk {
  const aiScene* scene;
  const std::vector<MeshTriangles>& meshes;
  const std::string& name;
  MeshFileLoad& out;
  int depth = 0;
};

Status addInstance(Walk& w, unsigned mesh_index, const Matrix& m, const std::string& node_name) {
  const aiMesh& mesh = *w.scene->mMeshes[mesh_index];
  const bool mirrored = m.Determinant() < 0.0;
  MeshBody body;
  body.first_triangle = w.out.mesh.triangles.size();
  body.name = !node_name.empty() ? node_name : mesh.mName.length > 0 ? std::string(mesh.mName.C_Str()) : "";
  for (const TriangleIndices& face : w.meshes[mesh_index].triangles) {
    Triangle t;
    for (int c = 0; c < 3; ++c) {
      const unsigned index = face[size_t(mirrored && c > 0 ? 3 - c : c)];
      if (index >= mesh.mNumVertices) {
        return makeError(ErrorCode::kParse, w.name + ": a face refers to vertex " + std::to_string(index) +
                                                " of a mesh with " + std::to_string(mesh.mNumVertices));
      }
      const aiVector3D& v = mesh.mVertices[index];
      const double x = m.a1 * v.x + m.a2 * v.y + m.a3 * v.z + m.a4;
      const double y = m.b1 * v.x + m.b2 * v.y + m.b3 * v.z + m.b4;
      const double z = m.c1 * v.x + m.c2 * v.y + m.c3 * v.z + m.c4;
      t.v[c] = glm::vec3(float(x), float(y), float(z));
      if (!std::isfinite(t.v[c].x) || !std::isfinite(t.v[c].y) || !std::isfinite(t.v[c].z)) {
        return makeError(ErrorCode::kParse, w.name + ": vertex " + std::to_string(index) + " of mesh " +
                                                quoteBytes(mesh.mName.C_Str()) +
                                                " has a non-finite coordinate (NaN or infinity)");
      }
    }
    w.out.mesh.triangles.push_back(t);
  }
  body.triangle_count = w.out.mesh.triangles.size() - body.first_triangle;
  if (body.triangle_count > 0) w.out.bodies.push_back(std::move(body));
  return Ok{};
}

Status walkNode(Walk& w, const aiNode* node, const Matrix& parent) {
  if (node == nullptr) return makeError(ErrorCode::kParse, w.name + ": the scene has an empty node");
  if (++w.depth > 1000) return makeError(ErrorCode::kParse, w.name + ": the scene's nodes nest too deeply");
  const Matrix m = parent * toDouble(node->mTransformation);
  for (unsigned i = 0; i < node->mNumMeshes; ++i) {
    const unsigned k = node->mMeshes[i];
    if (k >= w.scene->mNumMeshes || w.scene->mMeshes[k] == nullptr) {
      return makeError(ErrorCode::kParse, w.name + ": a node refers to a missing mesh");
    }
    if (Status s = addInstance(w, k, m, node->mName.C_Str()); !s.ok()) return s;
  }
  for (unsigned i = 0; i < node->mNumChildren; ++i) {
    if (Status s = walkNode(w, node->mChildren[i], m); !s.ok()) return s;
  }
  --w.depth;
  return Ok{};
}

// The number of corners of every face of the meshes that hold polygons (empty for the others), before Triangulate.
std::vector<std::vector<unsigned>> polygonCorners(const aiScene& scene) {
  std::vector<std::vector<unsigned>> out(scene.mNumMeshes);
  for (unsigned k = 0; k < scene.mNumMeshes; ++k) {
    const aiMesh* mesh = scene.mMeshes[k];
    if (mesh == nullptr || !(mesh->mPrimitiveTypes & aiPrimitiveType_POLYGON)) continue;
    out[k].reserve(mesh->mNumFaces);
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) out[k].push_back(mesh->mFaces[f].mNumIndices);
  }
  return out;
}

// The triangles of every mesh. Triangulate turns a face of n corners into n - 2 consecutive triangles in face order;
// where the counts agree, each polygon's triangles lose their slivers.
std::vector<MeshTriangles> meshTriangles(const aiScene& scene, const std::vector<std::vector<unsigned>>& corners) {
  std::vector<MeshTriangles> out(scene.mNumMeshes);
  for (unsigned k = 0; k < scene.mNumMeshes; ++k) {
    const aiMesh* mesh = scene.mMeshes[k];
    if (mesh == nullptr) continue;
    MeshTriangles& m = out[k];
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices == 3) {
        m.triangles.push_back({face.mIndices[0], face.mIndices[1], face.mIndices[2]});
      } else {
        ++m.other_primitives;
      }
    }
    uint64_t expected = 0;
    for (unsigned n : corners[k]) expected += n >= 3 ? n - 2 : 0;
    if (corners[k].empty() || m.other_primitives > 0 || expected != m.triangles.size()) continue;
    std::vector<glm::dvec3> positions(mesh->mNumVertices);
    for (unsigned i = 0; i < mesh->mNumVertices; ++i) {
      positions[i] = glm::dvec3(mesh->mVertices[i].x, mesh->mVertices[i].y, mesh->mVertices[i].z);
    }
    size_t at = 0;
    for (unsigned n : corners[k]) {
      if (n > 3) removePolygonSlivers(std::span(m.triangles).subspan(at, n - 2), positions);
      at += n >= 3 ? n - 2 : 0;
    }
  }
  return out;
}

// assimp's ReadFile takes the one importer that claims the file's extension; where several do (glTF 1 and 2 both
// claim .gltf and .glb), it asks each to recognise the content, and when none does it goes on to try every other
// importer by signature. assimp 5.2's 3MF importer then aborts the process on a zip without a package relationship
// (found by tests/fuzz/fuzz_mesh_file.cpp: a .glb whose JSON is cut short, followed by a zip). So a file goes to
// ReadFile only when one of the importers of its own extension will read it.
bool ownImporterRecognises(const Assimp::Importer& importer, const std::string& ext, const std::string& file) {
  std::vector<Assimp::BaseImporter*> own;
  for (size_t i = 0; i < importer.GetImporterCount(); ++i) {
    Assimp::BaseImporter* candidate = importer.GetImporter(i);
    if (candidate == nullptr) continue;
    std::set<std::string> extensions;
    candidate->GetExtensionList(extensions);
    if (extensions.count(ext) > 0) own.push_back(candidate);
  }
  if (own.size() == 1) return true;  // ReadFile takes it without asking
  for (Assimp::BaseImporter* candidate : own) {
    try {
      if (candidate->CanRead(file, importer.GetIOHandler(), true)) return true;
    } catch (const std::exception&) {
      // not this one
    }
  }
  return false;
}

}  // namespace

Result<MeshFileLoad> importWithAssimp(std::span<const uint8_t> bytes, const std::string& name, MeshFormat format,
                                      const std::filesystem::path* directory) {
  const char* ext = extensionFor(format);
  if (ext == nullptr) return makeError(ErrorCode::kInvalidArgument, name + ": not a format assimp reads here");
  const std::string main_name = std::string("mesh.") + ext;  // the extension picks assimp's importer
  Assimp::Importer importer;
  importer.SetIOHandler(new BytesIOSystem(bytes, main_name, directory));  // the importer owns it
  const aiScene* scene = nullptr;
  std::vector<MeshTriangles> meshes;
  try {
    if (!ownImporterRecognises(importer, ext, main_name)) {
      return makeError(ErrorCode::kParse, name + ": not a readable " + meshFormatName(format) + " file (assimp's " +
                                              meshFormatName(format) + " importers do not recognise its content)");
    }
    scene = importer.ReadFile(main_name, 0);
    if (scene != nullptr && (scene->mNumMeshes == 0 || scene->mRootNode == nullptr)) {
      return makeError(ErrorCode::kParse, name + ": " + meshFormatName(format) + " file contains no triangles");
    }
    if (scene != nullptr) scene = importer.ApplyPostProcessing(aiProcess_ValidateDataStructure);
    if (scene != nullptr) {
      const std::vector<std::vector<unsigned>> corners = polygonCorners(*scene);
      scene = importer.ApplyPostProcessing(aiProcess_Triangulate);
      if (scene != nullptr) meshes = meshTriangles(*scene, corners);
    }
  } catch (const std::bad_alloc&) {
    return makeError(ErrorCode::kLimit, name + ": not enough memory to read it");
  }
  if (scene == nullptr) {
    return makeError(ErrorCode::kParse, name + ": not a readable " + meshFormatName(format) +
                                            " file (assimp: " + quoteBytes(importer.GetErrorString(), 160) + ")");
  }
  MeshFileLoad out;
  out.mesh.name = name;
  out.format = format;
  out.format_detail = meshFormatName(format);
  Walk w{scene, meshes, name, out};
  if (Status s = walkNode(w, scene->mRootNode, Matrix()); !s.ok()) return s.error();
  if (out.mesh.triangles.empty()) {
    return makeError(ErrorCode::kParse, name + ": " + meshFormatName(format) + " file contains no triangles");
  }
  int64_t other_primitives = 0;
  for (const MeshTriangles& m : meshes) other_primitives += m.other_primitives;
  if (other_primitives > 0) {
    out.notes.push_back(name + ": " + std::to_string(other_primitives) +
                        " points and lines ignored (only faces enclose a solid)");
  }
  for (size_t i = 0; i < out.bodies.size(); ++i) {
    if (out.bodies[i].name.empty()) out.bodies[i].name = "body " + std::to_string(i + 1);
  }
  return out;
}

}  // namespace vox::io
