#include "types/mesh_file.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

namespace brick_stack_sim {

namespace {

bool isDirectory(const std::string& path) {
  std::ifstream probe(path + "/.");
  return static_cast<bool>(probe);
}

bool fileExists(const std::string& path) { return static_cast<bool>(std::ifstream(path)); }

/// Whether `directory` is the package `name`: its package.xml names it.
bool isPackage(const std::string& directory, const std::string& name) {
  std::ifstream manifest(directory + "/package.xml");
  if (!manifest) return false;
  std::ostringstream text;
  text << manifest.rdbuf();
  return text.str().find("<name>" + name + "</name>") != std::string::npos;
}

/// The directory of package `name` on ROS_PACKAGE_PATH, one level deep.
bool findPackage(const std::string& name, std::string* directory) {
  const char* search = std::getenv("ROS_PACKAGE_PATH");
  std::istringstream roots(search ? search : "");
  for (std::string root; std::getline(roots, root, ':');) {
    if (root.empty()) continue;
    for (const std::string& candidate : {root, root + "/" + name}) {
      if (isPackage(candidate, name)) {
        *directory = candidate;
        return true;
      }
    }
  }
  return false;
}

}  // namespace

Status resolveMeshPath(const std::string& filename, const std::string& base_directory,
                       std::string* path) {
  const std::string kFile = "file://", kPackage = "package://";
  if (filename.rfind(kFile, 0) == 0) {
    *path = filename.substr(kFile.size());
  } else if (filename.rfind(kPackage, 0) == 0) {
    const std::string rest = filename.substr(kPackage.size());
    const std::size_t slash = rest.find('/');
    const std::string name = rest.substr(0, slash);
    std::string directory;
    if (name.empty() || slash == std::string::npos || !findPackage(name, &directory))
      return Status::error("mesh '" + filename + "': no package '" + name +
                           "' on ROS_PACKAGE_PATH");
    *path = directory + rest.substr(slash);
  } else if (!filename.empty() && filename[0] == '/') {
    *path = filename;
  } else {
    *path = base_directory.empty() ? filename : base_directory + "/" + filename;
  }
  if (isDirectory(*path) || !fileExists(*path))
    return Status::error("mesh '" + filename + "': no file '" + *path + "'");
  return Status::success();
}

Status readMeshVertices(const std::string& path, const Eigen::Vector3d& scale,
                        std::vector<Eigen::Vector3d>* vertices) {
  Assimp::Importer importer;
  // Pre-transforming bakes every node's transform into its meshes' vertices.
  const aiScene* scene = importer.ReadFile(path, aiProcess_PreTransformVertices);
  if (!scene || !scene->mRootNode)
    return Status::error("mesh '" + path + "' does not load: " + importer.GetErrorString());
  std::size_t count = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) count += scene->mMeshes[m]->mNumVertices;
  if (count == 0) return Status::error("mesh '" + path + "' has no vertices");
  if (count > kMaxMeshVertices)
    return Status::error("mesh '" + path + "' has " + std::to_string(count) +
                         " vertices, more than " + std::to_string(kMaxMeshVertices) +
                         ": give a simplified collision mesh");
  vertices->clear();
  vertices->reserve(count);
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& mesh = *scene->mMeshes[m];
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D& p = mesh.mVertices[v];
      const Eigen::Vector3d vertex = scale.cwiseProduct(Eigen::Vector3d(p.x, p.y, p.z));
      if (!vertex.allFinite())
        return Status::error("mesh '" + path + "' has a vertex that is not finite");
      vertices->push_back(vertex);
    }
  }
  return Status::success();
}

}  // namespace brick_stack_sim
