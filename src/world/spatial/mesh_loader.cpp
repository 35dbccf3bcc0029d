#include "amp/world/mesh_loader.hpp"

#include <cctype>
#include <fstream>
#include <sstream>

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "amp/core/error.hpp"

namespace amp::world {

namespace {

// FBX-style scene metadata: "UpAxis" = 0 (x), 1 (y), 2 (z).
constexpr int kMetadataUpY = 1;

bool collada_declares_y_up(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const auto pos = s.find("<up_axis>");
  if (pos == std::string::npos) return true;  // COLLADA 1.4: Y_UP is the default
  return s.compare(pos + 9, 4, "Y_UP") == 0 || s.compare(pos + 9, 5, " Y_UP") == 0;
}

bool file_is_y_up(const aiScene& scene, const std::filesystem::path& file) {
  if (scene.mMetaData != nullptr) {
    int axis = 0;
    if (scene.mMetaData->Get("UpAxis", axis)) return axis == kMetadataUpY;
  }
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".dae" && collada_declares_y_up(file);
}

void collect(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, TriangleMesh& out) {
  const aiMatrix4x4 transform = parent * node.mTransformation;
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const int base = static_cast<int>(out.vertices.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D p = transform * mesh.mVertices[v];
      out.vertices.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines left by SortByPType
      out.triangles.emplace_back(base + static_cast<int>(face.mIndices[0]), base + static_cast<int>(face.mIndices[1]),
                                 base + static_cast<int>(face.mIndices[2]));
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) collect(scene, *node.mChildren[c], transform, out);
}

}  // namespace

UpAxis parse_up_axis(const std::string& text) {
  if (text == "y" || text == "Y") return UpAxis::kY;
  if (text == "z" || text == "Z") return UpAxis::kZ;
  throw ParameterError("up axis: expected 'y' or 'z', got '" + text + "'");
}

TriangleMesh load_mesh(const std::filesystem::path& file, UpAxis up) {
  Assimp::Importer importer;
  // We convert the up axis ourselves, after the node transforms, so that all formats agree.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene =
      importer.ReadFile(file.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    throw FileError(file.string() + ": cannot read mesh: " + importer.GetErrorString());
  }
  TriangleMesh mesh;
  collect(*scene, *scene->mRootNode, aiMatrix4x4(), mesh);
  if (mesh.triangles.empty()) throw FileError(file.string() + ": mesh has no triangles");

  const bool y_up = up == UpAxis::kY || (up == UpAxis::kAuto && file_is_y_up(*scene, file));
  if (y_up) {
    for (Eigen::Vector3d& v : mesh.vertices) v = Eigen::Vector3d(v.x(), -v.z(), v.y());  // +90 deg about x
  }
  return mesh;
}

Eigen::AlignedBox3d mesh_bounds(const TriangleMesh& mesh) {
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& v : mesh.vertices) box.extend(v);
  return box;
}

Eigen::Vector3d vertex_mean(const TriangleMesh& mesh) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : mesh.vertices) sum += v;
  return mesh.vertices.empty() ? sum : Eigen::Vector3d(sum / static_cast<double>(mesh.vertices.size()));
}

}  // namespace amp::world
