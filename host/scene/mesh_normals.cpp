#include "mesh_normals.h"

#include <cmath>

namespace vkrt {

std::vector<glm::vec3> angleWeightedVertexNormals(const std::vector<glm::vec3>& positions,
                                                  const std::vector<glm::uvec3>& triangles) {
    std::vector<glm::vec3> normals(positions.size(), glm::vec3(0.0f));
    for (const glm::uvec3& t : triangles) {
        // In double, where the differences and products of float coordinates are exact: the cross
        // product of a zero-area face (a repeated vertex, collinear corners) is then exactly zero.
        // In float, -march=native contracts a*b - c*d into an FMA whose rounding leaves a garbage
        // vector of length ~1e-8 that the angle weight (up to pi) turned into a wrong normal.
        const glm::dvec3 p0(positions[t.x]), p1(positions[t.y]), p2(positions[t.z]);
        const glm::dvec3 e01 = p1 - p0, e02 = p2 - p0, e12 = p2 - p1;
        const glm::dvec3 n = glm::cross(e01, e02);
        const double twiceArea = glm::length(n);
        if (!(twiceArea > 0.0) || !std::isfinite(twiceArea)) continue;
        const glm::dvec3 unit = n / twiceArea;
        // atan2(|a x b|, a.b) is the angle between a and b, accurate also near 0 and pi where
        // acos of a normalised dot product loses precision; |a x b| is the same at every corner.
        normals[t.x] += glm::vec3(unit * std::atan2(twiceArea, glm::dot(e01, e02)));
        normals[t.y] += glm::vec3(unit * std::atan2(twiceArea, -glm::dot(e01, e12)));
        normals[t.z] += glm::vec3(unit * std::atan2(twiceArea, glm::dot(e02, e12)));
    }
    for (glm::vec3& n : normals) {
        const float length = glm::length(n);
        // Opposite faces can cancel exactly (a vertex on a zero-thickness fold): leave zero then.
        n = length > 0.0f && std::isfinite(length) ? n / length : glm::vec3(0.0f);
    }
    return normals;
}

}  // namespace vkrt
