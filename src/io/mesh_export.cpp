// Surface meshes out: STL through io/stl.cpp, PLY and OBJ through assimp's exporters, 3MF written here and zipped
// with minizip (docs/dependencies.md).
#include "vox/io/mesh_export.h"

#include "vox/io/html.h"

#include <charconv>
#include <filesystem>
#include <memory>
#include <string>

#include <assimp/Exporter.hpp>
#include <assimp/scene.h>

#include "io/zip_package.h"
#include "vox/io/file_util.h"
#include "vox/io/stl.h"

namespace vox::io {
namespace {

// assimp's id of the exporter for an extension, or nullptr.
const char* exporterFor(const std::string& ext) {
  if (ext == ".ply") return "plyb";
  if (ext == ".obj") return "objnomtl";
  return nullptr;
}

// One mesh in a child of the root node, with the one default material the exporters expect. The scene owns what it
// points to (aiScene's destructor frees it).
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

// 3MF's name for voxmod's unit; millimeter (3MF's default) for a model without a unit, its numbers unchanged.
const char* threeMfUnit(const std::string& units) {
  if (units == "cm") return "centimeter";
  if (units == "m") return "meter";
  if (units == "in" || units == "inch") return "inch";
  return "millimeter";
}

void appendNumber(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);  // the shortest text that reads back as this double
  out.append(buf, r.ptr);
}

std::vector<uint8_t> bytesOf(const std::string& text) { return std::vector<uint8_t>(text.begin(), text.end()); }

// The 3MF core model: one object, one build item. assimp's 3MF exporter prints 6 significant digits (which moves
// vertices split 1/256 of a voxel apart onto each other on large coordinates) and always says millimeter, so the
// model part is written here (docs/dependencies.md).
std::string threeMfModel(const IndexedMesh& mesh, const std::string& units) {
  std::string out;
  out.reserve(64 + mesh.vertices.size() * 64 + mesh.triangles.size() * 40);
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<model unit=\"";
  out += threeMfUnit(units);
  out += "\" xml:lang=\"en-US\" xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\">\n";
  out += " <resources>\n  <object id=\"1\" type=\"model\" name=\"";
  out += escapeHtml(mesh.name.empty() ? std::string("surface") : mesh.name);  // XML's entities too
  out += "\">\n   <mesh>\n    <vertices>\n";
  for (const glm::dvec3& v : mesh.vertices) {
    out += "     <vertex x=\"";
    appendNumber(out, v.x);
    out += "\" y=\"";
    appendNumber(out, v.y);
    out += "\" z=\"";
    appendNumber(out, v.z);
    out += "\"/>\n";
  }
  out += "    </vertices>\n    <triangles>\n";
  for (const auto& t : mesh.triangles) {
    out += "     <triangle v1=\"" + std::to_string(t[0]) + "\" v2=\"" + std::to_string(t[1]) + "\" v3=\"" +
           std::to_string(t[2]) + "\"/>\n";
  }
  out += "    </triangles>\n   </mesh>\n  </object>\n </resources>\n <build>\n  <item objectid=\"1\"/>\n </build>\n";
  out += "</model>\n";
  return out;
}

// A 3MF package (3MF Core Specification 1.2): content types, the root relationship, the model part; deflated.
Status save3mf(const IndexedMesh& mesh, const std::filesystem::path& path, const std::string& units) {
  std::vector<ZipEntry> entries;
  entries.push_back(
      {"[Content_Types].xml", bytesOf("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                                      "<Types xmlns=\"http://schemas.openxmlformats.org/package/2006/content-types\">\n"
                                      " <Default Extension=\"rels\" "
                                      "ContentType=\"application/vnd.openxmlformats-package.relationships+xml\"/>\n"
                                      " <Default Extension=\"model\" "
                                      "ContentType=\"application/vnd.ms-package.3dmanufacturing-3dmodel+xml\"/>\n"
                                      "</Types>\n")});
  entries.push_back(
      {"_rels/.rels", bytesOf("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                              "<Relationships xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\">\n"
                              " <Relationship Target=\"/3D/3dmodel.model\" Id=\"rel0\" "
                              "Type=\"http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel\"/>\n"
                              "</Relationships>\n")});
  entries.push_back({"3D/3dmodel.model", bytesOf(threeMfModel(mesh, units))});
  auto zip = writeZip(entries, path.string(), true);
  if (!zip) return zip.error();
  return writeFileAtomic(path, *zip);
}

}  // namespace

bool isMeshExportFile(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  return ext == ".stl" || ext == ".3mf" || exporterFor(ext) != nullptr;
}

std::string meshExportExtensions() { return "stl, ply, obj, 3mf"; }

Status saveMesh(const IndexedMesh& mesh, const std::filesystem::path& path, const std::string& units) {
  const std::string ext = lowerExtension(path);
  if (ext == ".stl") return saveStlBinary(mesh, path);
  if (ext == ".3mf") return save3mf(mesh, path, units);
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
  const aiExportDataBlob* blob = exporter.ExportToBlob(scene.get(), id);
  if (!blob) return makeError(ErrorCode::kIo, path.string() + ": " + exporter.GetErrorString());
  if (blob->next) {
    return makeError(ErrorCode::kIo, path.string() + ": the " + std::string(id) + " exporter made more than one file");
  }
  return writeFileAtomic(path, std::span<const uint8_t>(static_cast<const uint8_t*>(blob->data), blob->size));
}

}  // namespace vox::io
