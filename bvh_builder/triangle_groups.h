// The CPU traversal's triangles four at a time: every bottom-level leaf of two or more triangles
// (and nothing else) also has its corners stored lane by lane, so one SSE instruction computes a
// step of the watertight test for four triangles (traverse.cpp). SceneBvh::prims stays what
// every other reader (the GPU upload, spheres, boxes, single-triangle leaves) uses.
// Why and what it gains: docs/BVH.md §3.
#pragma once

#include <cstdint>
#include <vector>

#include "device_host.h"
#include "thread_pool.h"

namespace vkrt::bvh {

struct WideNode;

struct alignas(16) TriangleGroup {
    // [corner][axis][lane]: corner v0, v1, v2 of the lane's triangle, which is SceneBvh::prims
    // [first + 4 g + lane] for the leaf's first primitive `first` and the group's place g in the leaf.
    float corner[3][3][4];
    std::uint32_t lanes = 0;   // bit k: lane k holds a triangle that can be hit (not padding, and not
                               // collinear: the scalar test never reports such a triangle's hit)
};
static_assert(sizeof(TriangleGroup) == 160);  // 148 bytes of members, padded to 16 (docs/BVH.md §3)

struct TriangleGroups {
    std::vector<TriangleGroup> groups;  // each leaf's groups are contiguous, ceil(count / 4) of them
    // Per primitive: where it begins a leaf of two or more triangles, that leaf's first group;
    // kNone everywhere else (the leaf is tested one primitive at a time).
    std::vector<std::uint32_t> leafGroup;
    static constexpr std::uint32_t kNone = 0xffffffffu;
};

// From the bottom levels' 8-wide nodes (nodes[0, bottomNodes); the top level's leaves hold
// instances, not primitives).
TriangleGroups buildTriangleGroups(const std::vector<gpu::Primitive>& prims, const WideNode* nodes,
                                   std::uint32_t bottomNodes, ThreadPool& pool);

}  // namespace vkrt::bvh
