// Test scenes for the BVH: random soups, upstream meshes, instanced scenes, and random rays.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "aabb.h"
#include "bvh.h"

namespace vkrt::bvh::test {

struct TestScene {
    std::vector<std::vector<PrimitiveInput>> groups;
    std::vector<InstanceInput> instances;
};

// Triangles with corners in a cube of side `extent`, each of size about `size`.
std::vector<PrimitiveInput> randomTriangles(std::mt19937& rng, std::size_t count, float extent, float size);
// Spheres and boxes mixed, like spheres_1K.xml and boxSphereTest.xml.
std::vector<PrimitiveInput> randomSpheresAndBoxes(std::mt19937& rng, std::size_t count, float extent, float size);
// Triangulated OBJ (fan triangulation), loaded with tinyobjloader. Throws on failure.
std::vector<PrimitiveInput> loadObjTriangles(const std::string& path);

// One group placed by one identity instance.
TestScene singleGroup(std::vector<PrimitiveInput> prims);

// Random affine transform: rotation, non-uniform scale (optionally with a mirroring negative
// factor) and translation within `extent`.
glm::mat4 randomTransform(std::mt19937& rng, float extent, bool mirror);

// World bounds of a scene, computed from every primitive's transformed box corners.
Aabb sceneBounds(const TestScene& scene);

// Rays for a scene: half aimed at random points of random primitives (so most of them hit), half
// between random points of the enlarged bounds; directions are not normalised (random length), so
// t's units are exercised.
std::vector<Ray> randomRays(std::mt19937& rng, const TestScene& scene, std::size_t count);

}  // namespace vkrt::bvh::test
