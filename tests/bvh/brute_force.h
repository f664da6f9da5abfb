// The reference the BVH is checked against: every primitive of every instance, in input order.
// The ray enters object space through the builder's worldToObject rows, rounded the way the
// traversal rounds (one float rounding of a double product): a short hit seen from a far origin
// has t only as precise as the object-space origin, so an independently rounded inverse could not
// be held to 1e-6 relative. The rows themselves are checked against the input transforms in
// structure_test.cpp.
#pragma once

#include <cstdint>

#include "scene_gen.h"

namespace vkrt::bvh::test {

struct BruteHit {
    float t = 0.0f;
    std::uint32_t instance = 0;
    std::uint32_t sourcePrim = 0;  // index in the instance's group input list
};

using Rows = std::vector<gpu::Instance>;  // SceneBvh::instances (only worldToObject is read)

// Per group, a primitive's input index -> its index in SceneBvh::prims, by which the closest-hit
// rule breaks ties of distance (shaders/shared/hit_order.h).
using FlatIndex = std::vector<std::vector<std::uint32_t>>;
FlatIndex flatIndexOf(const SceneBvh& bvh);

// The closest hit by the traversal's rule: the least (256-ulp bucket of t, instance, flat primitive).
bool bruteClosest(const TestScene& scene, const Rows& rows, const FlatIndex& flat, const Ray& ray, BruteHit& hit);
bool bruteAny(const TestScene& scene, const Rows& rows, const Ray& ray);
// t of one primitive of one instance against the ray (to judge ties), or false.
bool bruteOne(const TestScene& scene, const Rows& rows, std::uint32_t instance, std::uint32_t sourcePrim,
              const Ray& ray, float& t);

}  // namespace vkrt::bvh::test
