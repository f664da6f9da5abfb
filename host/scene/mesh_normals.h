// Per-vertex normals for meshes whose OBJ file has no `vn` lines (none of the course's files do).
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace vkrt {

// Angle-weighted average of the unit normals of the faces around each vertex (Thürmer & Wüthrich
// 1998). Angle weights, rather than area weights or a plain average, make the result depend only on
// the surface's shape and not on how it was cut into triangles: a quad split into two triangles, or
// al.obj's 23-gons fanned into slivers, give the same normal as the unsplit polygon, and one huge
// neighbouring triangle does not outvote the others on scanned meshes.
// Degenerate faces (zero area, or non-finite) contribute nothing. A vertex with no valid face gets
// the zero vector; renderers treat a zero interpolated normal as "use the face normal".
std::vector<glm::vec3> angleWeightedVertexNormals(const std::vector<glm::vec3>& positions,
                                                  const std::vector<glm::uvec3>& triangles);

}  // namespace vkrt
