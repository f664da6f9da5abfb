// The builder's BVH nodes (bvh::BinaryNode: exact boxes, explicit link and count) -> the 48-byte
// nodes the kernels read (gpu::GpuBvhNode: each child's stack entry in the low bits of its box
// floats, the boxes rounded outward to make room; shaders/shared/device_host.h).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "aabb.h"
#include "bvh.h"

namespace vkrt {

// The largest float <= value whose low `bits` bits are `payload` (as a bit pattern); the
// smallest float >= value with them. Throws std::invalid_argument when there is none (value
// within 2^bits ulp of the largest float, or infinite).
std::uint32_t roundDownWithLowBits(float value, std::uint32_t payload, unsigned bits);
std::uint32_t roundUpWithLowBits(float value, std::uint32_t payload, unsigned bits);

// Which nodes belong to the top level (reachable from bvh.topRoot): their leaves are instances.
// Every other node is bottom-level.
std::vector<bool> topLevelNodes(const bvh::SceneBvh& bvh);

// Throws std::logic_error unless the top level's nodes are exactly the last ones, from bvh.topRoot
// on (SceneBvh::nodes promises it): the kernel tells a top-level node by its index alone
// (traverse.glsl, topLevelNode). gpuNodes checks it.
void checkTopLevelLast(const bvh::SceneBvh& bvh);

// The world group (the scene's loose shapes: instance 0, identity transform) walked as part of the
// top level: its top-level leaf becomes an entry of its root node, so a ray reaches the loose
// shapes without the main-loop round that entering an instance costs (traverse.glsl). Chosen when
// the scene has a top level, instance 0 is the identity, no other instance shares its group, and
// the group's nodes are contiguous (the kernel tells them by their index range).
struct InlinedWorld {
    bool inlined = false;
    std::uint32_t rootNode = 0;
    std::uint32_t firstNode = 0, nodeCount = 0;  // the group's nodes: [firstNode, firstNode + nodeCount)
    std::uint32_t firstPrim = 0, primCount = 0;
};
InlinedWorld inlinedWorld(const bvh::SceneBvh& bvh);
// FrameParams::world for the layout with nodeTexels texels per node (zero counts when not inlined).
glm::uvec4 inlinedWorldParams(const InlinedWorld& world, std::uint32_t nodeTexels);

// The kernel's stack entry for child k of bvh.nodes[index], where `topLevel` says whether the
// node belongs to the top level (whose leaves are instances) or to a bottom level. An inner
// child's entry is its node's first texel (link * nodeTexels, the layout's texels per node), so
// the walk fetches without a multiply (traverse.glsl). The inlined world's instance (instance 0)
// is the entry of the world group's root node.
std::uint32_t childStackEntry(const bvh::BinaryNode& node, int k, bool topLevel, std::uint32_t nodeTexels,
                              const InlinedWorld& world = {});

// Every node of bvh.nodes, in the same order (indices stay valid). Leaf entries must fit
// (checkLeafEntries, traversal_stack.h, refuses a scene whose leaves do not): one that does not
// is a std::logic_error here.
std::vector<gpu::GpuBvhNode> packNodes(const bvh::SceneBvh& bvh, const InlinedWorld& world = {});

// The node texels to upload, and which layout they are in (device_host.h, SPEC_PACKED_NODES).
struct GpuNodes {
    std::vector<glm::uvec4> texels;  // GPU_NODE_TEXELS per node if packed, else GPU_EXACT_NODE_TEXELS
    bool packed = true;
    double areaGrowth = 1.0;  // the packed child boxes' total surface area over the builder's, in the
                              // tree (a bottom level or the top level) where it grows most
    glm::uvec4 world{0u};     // FrameParams::world (inlinedWorldParams)
};
// Packing pays while it adds few node visits; the expected visits of a child are proportional to
// its box's surface area (the SAH's assumption), so the boxes' total area is the measure, per tree
// because a ray that reaches a mesh walks that mesh's tree.
constexpr double kMaxPackedAreaGrowth = 1.01;

// The packed nodes if their areaGrowth is at most kMaxPackedAreaGrowth, else the exact layout
// (also when a bound cannot be rounded outward: areaGrowth is then infinite). Leaf entries must
// fit, as for packNodes.
GpuNodes gpuNodes(const bvh::SceneBvh& bvh);
// The bytes to upload (at least one texel: an empty binding still needs a buffer).
inline std::uint64_t nodeBytes(const GpuNodes& nodes) { return std::max<std::uint64_t>(1, nodes.texels.size()) * sizeof(glm::uvec4); }

// The box of child k as the kernel reads it from a packed node (what packNodes rounded outward).
bvh::Aabb packedChildBox(const gpu::GpuBvhNode& node, int k);
// The stack entry of child k as the kernel decodes it (traverse.glsl, nodeChildEntry).
std::uint32_t packedChildEntry(const gpu::GpuBvhNode& node, int k);

}  // namespace vkrt
