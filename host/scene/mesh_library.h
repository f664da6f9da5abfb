// Loads each distinct OBJ file of a scene once, however many shapes and prototypes use it.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "scene.h"

namespace vkrt {

class MeshLibrary {
public:
    explicit MeshLibrary(std::vector<Mesh>& meshes) : meshes_(meshes) {}
    // Index into the scene's meshes for `path` (already resolved against the scene file). Throws
    // std::runtime_error with loadObjMesh's short reason for a missing or unusable file; the
    // loader reports it at the element or key that names the file.
    int meshFor(const std::string& path);

private:
    std::vector<Mesh>& meshes_;
    std::map<std::string, int> indexOfPath_;  // key: the absolute, normalised path
};

}  // namespace vkrt
