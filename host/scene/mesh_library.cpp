#include "mesh_library.h"

#include <filesystem>

#include "obj_mesh.h"

namespace vkrt {

int MeshLibrary::meshFor(const std::string& path) {
    const std::string key = std::filesystem::absolute(path).lexically_normal().string();
    if (const auto found = indexOfPath_.find(key); found != indexOfPath_.end()) return found->second;
    meshes_.push_back(loadObjMesh(path));
    const int index = static_cast<int>(meshes_.size()) - 1;
    indexOfPath_.emplace(key, index);
    return index;
}

}  // namespace vkrt
