// Surface meshes out: STL through io/stl.cpp, PLY, OBJ and 3MF through assimp's exporters (docs/dependencies.md).
#include "vox/io/mesh_export.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include <assimp/Exporter.hpp>
#include <assimp/scene.h>

#include "vox/io/file_util.h"
#include "vox/io/stl.h"

namespace vox::io {
namespace {

// assimp's id of the exporter for an extension, or nullptr.
const char* exporterFor(const std::string& ext) {
  if (ext == ".ply") return "plyb";
  if (ext == ".obj") return "objnomtl";
  if (ext == ".3mf") return "3mf";
  return nullptr;
}

// One mesh in a child of the root node (the 3MF exporter writes the root's children only), with the one default
// material the exporters expect. The scene owns what it points to (aiScene's destructor frees it).
std::unique_ptr<aiScene> sceneOf(const IndexedMesh& mesh) {
  auto scene = std::make_unique<aiScene>();
  scene->mRootNode = new aiNode("voxmod");
  auto* node = new aiNode(mesh.name.empty() ? std::string("surface") : mesh.name);
  scene->mRootNode->addChildren(1, &node);
  node->mNumMeshes = 1;
  node->mMeshes = new unsigned[1]{0};
  scene->mNumMaterials = 1;
  scene->mMaterials = new aiMaterial* [1] { new aiMaterial() };
  auto* m = new aiMesh();
  scene->mNumMeshes = 1;
  scene->mMeshes = new aiMesh* [1] { m };
  m->mName = aiString(mesh.name.empty() ? std::string("surface") : mesh.name);
  m->mMaterialIndex = 0;
  m->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  m->mNumVertices = unsigned(mesh.vertices.size());
  m->mVertices = new aiVector3D[mesh.vertices.size()];
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const glm::dvec3& v = mesh.vertices[i];
    m->mVertices[i] = aiVector3D(ai_real(v.x), ai_real(v.y), ai_real(v.z));
  }
  m->mNumFaces = unsigned(mesh.triangles.size());
  m->mFaces = new aiFace[mesh.triangles.size()];
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    aiFace& f = m->mFaces[i];
    f.mNumIndices = 3;
    f.mIndices = new unsigned[3]{mesh.triangles[i][0], mesh.triangles[i][1], mesh.triangles[i][2]};
  }
  return scene;
}

// assimp's 3MF exporter writes its zip straight to a file name (it ignores the export-to-memory I/O system): it
// writes into a private temporary directory, and the bytes are then saved atomically like every other format.
Status export3mf(Assimp::Exporter& exporter, const aiScene& scene, const std::filesystem::path& path) {
  std::error_code ec;
  const auto dir = std::filesystem::temp_directory_path(ec) /
                   ("voxmod-3mf-" + std::to_string(::getpid()) + "-" + std::to_string(std::rand()));
  if (ec || !std::filesystem::create_directory(dir, ec)) {
    return makeError(ErrorCode::kIo, path.string() + ": cannot make a temporary directory for the 3MF exporter");
  }
  const auto tmp = dir / "model.3mf";
  Status result = Ok{};
  if (exporter.Export(&scene, "3mf", tmp.string()) != AI_SUCCESS) {
    result = makeError(ErrorCode::kIo, path.string() + ": " + exporter.GetErrorString());
  } else if (auto bytes = readFileBytes(tmp); !bytes) {
    result =
        makeError(ErrorCode::kIo, path.string() + ": the 3MF exporter wrote nothing (" + bytes.error().message + ")");
  } else {
    result = writeFileAtomic(path, *bytes);
  }
  std::filesystem::remove_all(dir, ec);
  return result;
}

}  // namespace

bool isMeshExportFile(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  return ext == ".stl" || exporterFor(ext) != nullptr;
}

std::string meshExportExtensions() { return "stl, ply, obj, 3mf"; }

Status saveMesh(const IndexedMesh& mesh, const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".stl") return saveStlBinary(mesh, path);
  const char* id = exporterFor(ext);
  if (!id) {
    return makeError(ErrorCode::kInvalidArgument,
                     path.string() + ": not a mesh format voxmod writes (" + meshExportExtensions() + ")");
  }
  if (mesh.vertices.size() > UINT32_MAX || mesh.triangles.size() > UINT32_MAX) {
    return makeError(ErrorCode::kLimit, path.string() + ": the mesh has more than 2^32 vertices or triangles");
  }
  const std::unique_ptr<aiScene> scene = sceneOf(mesh);
  Assimp::Exporter exporter;
  if (ext == ".3mf") return export3mf(exporter, *scene, path);
  const aiExportDataBlob* blob = exporter.ExportToBlob(scene.get(), id);
  if (!blob) return makeError(ErrorCode::kIo, path.string() + ": " + exporter.GetErrorString());
  if (blob->next) {
    return makeError(ErrorCode::kIo, path.string() + ": the " + std::string(id) + " exporter made more than one file");
  }
  return writeFileAtomic(path, std::span<const uint8_t>(static_cast<const uint8_t*>(blob->data), blob->size));
}

}  // namespace vox::io
