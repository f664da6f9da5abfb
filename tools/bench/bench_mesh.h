// The benchmark's input mesh, made exactly as the Embree peer makes it (../shared/peer/README.md),
// so both trace the same triangles with the same camera.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "bvh.h"

namespace vkrt::bench {

struct BenchMesh {
    std::vector<glm::vec3> positions;  // every vertex (unused ones too: they count for the camera bounds)
    std::vector<glm::uvec3> triangles;
    glm::vec3 lo{0.0f}, hi{0.0f};      // bounds of positions
};

// "sphere:N": a UV sphere of N x 2N quads (2 triangles each); otherwise an OBJ file, faces
// fan-triangulated. Throws std::runtime_error naming the source on failure.
BenchMesh loadBenchMesh(const std::string& source);

std::vector<bvh::PrimitiveInput> toPrimitives(const BenchMesh& mesh);

}  // namespace vkrt::bench
