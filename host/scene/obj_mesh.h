// Wavefront OBJ -> Mesh (tinyobjloader, polygons triangulated).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "scene.h"

namespace vkrt {

// Loads every face of the file as one triangle mesh; `usemtl`/`mtllib` are ignored (the scene's
// shader wins), as are unknown keywords such as al.obj's `group`. Vertex normals come from `vn`
// when every face corner has one, else they are generated (mesh_normals.h); uvs are kept when
// every corner has a `vt`. Throws std::runtime_error (a short reason, without the path) when the
// file cannot be read, is larger than the mesh-bytes input limit (input_limits.h;
// checked before a byte is read: the text, tinyobjloader's arrays and the mesh take several times
// the file's size), has no faces, or indexes a vertex that does not exist.
Mesh loadObjMesh(const std::string& path);

}  // namespace vkrt
