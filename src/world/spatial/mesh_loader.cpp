#include "amp/world/mesh_loader.hpp"

#include <cctype>
#include <limits>
#include <fstream>
#include <sstream>
#include <string>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "amp/core/error.hpp"
#include "collada_screen.hpp"

namespace amp::world {

namespace {

// FBX-style scene metadata: "UpAxis" = 0 (x), 1 (y), 2 (z).
constexpr int kMetadataUpY = 1;

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

bool collada_declares_y_up(const std::string& s) {
  const auto pos = s.find("<up_axis>");
  if (pos == std::string::npos) return true;  // COLLADA 1.4: Y_UP is the default
  return s.compare(pos + 9, 4, "Y_UP") == 0 || s.compare(pos + 9, 5, " Y_UP") == 0;
}

// `collada` is the document text of a .dae file, and empty for every other format.
bool file_is_y_up(const aiScene& scene, const std::string& collada) {
  if (scene.mMetaData != nullptr) {
    int axis = 0;
    if (scene.mMetaData->Get("UpAxis", axis)) return axis == kMetadataUpY;
  }
  return !collada.empty() && collada_declares_y_up(collada);
}

// Every vertex of every mesh the node tree instances (points and lines included, as OMPL.app's
// scene centre counts them), with the triangles among the faces.
void collect(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, TriangleMesh& out) {
  const aiMatrix4x4 transform = parent * node.mTransformation;
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const int base = static_cast<int>(out.vertices.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D p = transform * mesh.mVertices[v];
      out.vertices.emplace_back(p.x, p.y, p.z);
    }
    if (mesh.mNumVertices > static_cast<unsigned>(std::numeric_limits<int>::max() - base)) {
      throw FileError("mesh has more vertices than a mesh index can address");
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines: no surface
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
  // assimp's own importer settings, as OMPL.app reads meshes: a COLLADA file's <up_axis> is applied
  // by assimp (with 5.2 a Z_UP file comes back in its own Z-up frame, a Y_UP file unrotated), and
  // every node transform down from the root. Primitives are not filtered, so that the vertex mean
  // is OMPL.app's.
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::string collada = ext == ".dae" ? read_text(file) : std::string();
  if (const std::string refusal = collada_refusal(collada); !refusal.empty()) {
    throw FileError(file.string() + ": cannot read mesh: " + refusal);
  }
  Assimp::Importer importer;
  // Normalised first: assimp 5.2 fails with "File read error" on an OBJ path holding "../" after
  // a folder ("a/b/../../../x.obj"), as an experiment file beside the repository names the shared data.
  const aiScene* scene =
      importer.ReadFile(file.lexically_normal().string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    throw FileError(file.string() + ": cannot read mesh: " + importer.GetErrorString());
  }
  TriangleMesh mesh;
  try {
    collect(*scene, *scene->mRootNode, aiMatrix4x4(), mesh);
  } catch (const FileError& e) {
    throw FileError(file.string() + ": " + e.what());
  }
  if (mesh.triangles.empty()) throw FileError(file.string() + ": mesh has no triangles");

  const bool y_up = up == UpAxis::kY || (up == UpAxis::kAuto && file_is_y_up(*scene, collada));
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
