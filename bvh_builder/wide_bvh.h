// The CPU traversal's own layout: the same trees as SceneBvh::nodes, collapsed to 8 children per
// node (each node absorbs the largest inner children of its two-child node until it has 8), with
// the 8 boxes stored as rows of 8 floats so one AVX instruction per plane tests all children (two
// SSE instructions in a build without AVX).
// The GPU's nodes are made from the two-child BinaryNode instead (node_layout.h,
// host/gpu/node_packing); this layout never leaves the CPU.
// Measured on this machine: see docs/BVH.md §3 (CPU traversal: 8-wide against 4-wide).
#pragma once

#include <cstdint>
#include <vector>

#include "triangle_groups.h"

namespace vkrt::bvh {

// Children per node.
inline constexpr int kWideWidth = 8;
// Entries of the traversal's stack (traverse.cpp): enough for any tree the builder makes. A node
// pushes at most kWideWidth - 1 entries (its hit inner children but the nearest), only a node's
// ancestors' entries wait on the stack, and an 8-wide tree is never deeper than the two-child
// tree it collapses (every slot is a strictly deeper node of it), which is at most 64 levels deep
// (scene_bvh.cpp, kMaxTreeDepth). tests/bvh/structure_test.cpp checks trees against it.
inline constexpr int kWideStackSize = (kWideWidth - 1) * 64 + 1;

struct alignas(64) WideNode {
    // rows: lo.x, hi.x, lo.y, hi.y, lo.z, hi.z; column k = child k. An empty slot has
    // lo = +FLT_MAX, hi = -FLT_MAX, link = NODE_NONE, count = 0.
    float bounds[6][kWideWidth];
    std::uint32_t link[kWideWidth];   // count == 0: index of an inner WideNode; count > 0: first primitive
    std::uint32_t count[kWideWidth];  // (bottom level) or instance (top level), as in BinaryNode
};
static_assert(sizeof(WideNode) == 256);

struct WideBvh {
    std::vector<WideNode> nodes;
    std::vector<std::uint32_t> groupRoots;  // per geometry group
    std::uint32_t topRoot = 0;
    // Per instance: its transform is exactly the identity and it does not move, so rays enter its
    // group unchanged (saves the ray transform, which a single-mesh scene would otherwise pay on
    // every ray, and the pose lookup).
    std::vector<std::uint8_t> identity;
    // The leaves of two or more triangles, four triangles per SSE test.
    TriangleGroups triangles;
    // Built at all (BuildOptions::cpuTraversal): a scene without instances has no nodes either way,
    // and traversing a BVH built for the GPU only must fail loudly, not report no hits.
    bool built = false;
};

}  // namespace vkrt::bvh
