// bvh_builder: a two-level SAH BVH over spheres, boxes and triangles, flattened into binary nodes
// (node_layout.h; host/gpu/node_packing makes the kernels' layout from them) beside the primitive
// and instance records the GLSL kernels read as they are (shaders/shared/device_host.h), plus the
// CPU traversal that the reference renderer and the benchmarks use. No Vulkan and no scene-format
// dependency.
//
// Bottom level: one BVH per geometry group (a mesh, a prototype, or the scene's loose shapes).
// Top level: one BVH over instances = (group, object-to-world affine transform).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "../shaders/shared/device_host.h"
#include "node_layout.h"
#include "wide_bvh.h"

namespace vkrt::bvh {

// One primitive of a geometry group, in the group's object space.
//   PRIM_KIND_TRIANGLE: a, b, c = v0, v1, v2
//   PRIM_KIND_SPHERE:   a = centre, b.x = radius
//   PRIM_KIND_BOX:      a = min corner, b = max corner
struct PrimitiveInput {
    std::uint32_t kind = gpu::PRIM_KIND_TRIANGLE;
    glm::vec3 a{0.0f}, b{0.0f}, c{0.0f};
};

struct InstanceInput {
    std::uint32_t group = 0;
    glm::mat4 objectToWorld{1.0f};
    std::uint32_t materialOverride = gpu::MATERIAL_NONE;  // Instance::info (instanceMaterialOverride)
    // Motion blur: the pose at motion time 1 (objectToWorld is time 0's); instance_motion.h.
    bool moving = false;
    glm::mat4 objectToWorldEnd{1.0f};
};

struct BuildOptions {
    int threads = 0;             // 0: all hardware threads; the result never depends on it
    int bins = 16;               // SAH bins per axis
    int maxLeafSize = 8;         // a leaf is forced to split above this many primitives
    float traversalCost = 1.0f;  // SAH cost of visiting an inner node, relative to...
    float intersectionCost = 1.0f;  // ...intersecting one primitive (see docs/BVH.md for the measurement)
    int maxBottomDepth = 36;     // node levels of a bottom-level tree (deeper SAH splits become median splits);
                                 // a group whose median splits need more levels, ceil(log2(n / maxLeafSize)),
                                 // gets that many
    // Also build SceneBvh::cpu, the 8-wide copy that only the CPU traversal (intersectClosest /
    // intersectAny) reads: ~25% of the build on dragon (100K triangles), ~35% at 1M (docs/BVH.md §4),
    // most of it the triangle groups. A caller that only uploads
    // the BVH to the GPU sets this to false; the GPU arrays are the same either way.
    bool cpuTraversal = true;
};

struct GroupRange {
    std::uint32_t rootNode = 0;   // index into SceneBvh::nodes
    std::uint32_t firstPrim = 0;  // this group's primitives are prims[firstPrim, firstPrim + primCount)
    std::uint32_t primCount = 0;
    glm::vec3 lo{0.0f}, hi{0.0f}; // object-space bounds
};

struct BuildStats {
    double buildSeconds = 0.0;
    double cpuCopySeconds = 0.0;  // the part of buildSeconds spent on the CPU's 8-wide copy (0 without it)
    double sahCost = 0.0;         // SAH cost of the bottom levels, summed over groups
    std::size_t nodeCount = 0;
    std::size_t leafCount = 0;
    std::size_t bytes = 0;        // nodes + primitives + instances as uploaded
    int bottomDepth = 0;          // nodes on the longest root-to-leaf path of any bottom level
    int topDepth = 0;             // the same for the top level; the kernel's traversal stack needs at
                                  // most topDepth + bottomDepth entries (host/gpu/traversal_stack.h)
};

// The flattened two-level BVH: prims and instances are uploaded as they are, nodes after packing
// (host/gpu/node_packing).
struct SceneBvh {
    std::vector<BinaryNode> nodes;            // every bottom level (depth-first), then the top level
    std::vector<gpu::Primitive> prims;        // leaf-contiguous, group after group
    std::vector<std::uint32_t> primSource;    // flat primitive -> its index in the group's input list
    std::vector<GroupRange> groups;           // per input group
    std::vector<gpu::Instance> instances;     // same order as the input instances
    std::vector<gpu::InstanceMotion> motions; // the moving instances' poses, in instance order; the
                                              // kernels read them after the instances in one table
                                              // (Instance::info.w: motionTexel)
    std::uint32_t topRoot = 0;                // root node of the top level (over instances)
    BuildStats stats;
    WideBvh cpu;                              // the same trees, 8-wide, for the CPU traversal only;
                                              // empty if built with BuildOptions::cpuTraversal = false
};

// Throws std::invalid_argument (one line naming the group/instance, the primitive and the value) on
// bad input: a non-finite coordinate, a negative radius, an inverted box, an unknown group index, or
// a transform that is singular, non-finite or not affine.
SceneBvh buildSceneBvh(const std::vector<std::vector<PrimitiveInput>>& groups,
                       const std::vector<InstanceInput>& instances, const BuildOptions& options = {});

// ---------------------------------------------------------------------------------------------
// CPU traversal (the reference renderer's and the benchmarks').
struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 dir{0.0f, 0.0f, -1.0f};  // need not be unit length; t is measured in units of |dir|
    float tmax = 3.402823466e38f;      // hits need 0 < t < tmax
    float time = 0.0f;                 // where moving instances are (0: their transform, 1: the end one)
};

// Instance i as a ray at `time` sees it: the record itself, or a moving instance's pose then
// (shaders/shared/motion.h, the kernels' arithmetic) written into `posed`. Only a moving instance
// is copied: the traversal and the hit description call this for every instance they meet.
const gpu::Instance& instanceAtTime(const SceneBvh& bvh, std::uint32_t i, float time, gpu::Instance& posed);

struct Hit {
    float t = 0.0f;
    std::uint32_t instance = 0;  // index into SceneBvh::instances
    std::uint32_t prim = 0;      // index into SceneBvh::prims (primSource maps it back)
    float u = 0.0f, v = 0.0f;    // triangle: barycentric weights of v1 and v2
    int face = -1;               // box: face hit, 0..5 = -x, +x, -y, +y, -z, +z (see intersect.h)
};

// Closest hit with 0 < t < ray.tmax; false if none. Both throw std::logic_error on a BVH built
// with BuildOptions::cpuTraversal = false (it has no 8-wide copy to traverse).
bool intersectClosest(const SceneBvh& bvh, const Ray& ray, Hit& hit);
// Any hit with 0 < t < ray.tmax (shadow rays).
bool intersectAny(const SceneBvh& bvh, const Ray& ray);

}  // namespace vkrt::bvh
