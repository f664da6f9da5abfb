// The kernel's BVH traversal stack has TRAVERSAL_STACK_SIZE entries (device_host.h). The host
// measures the stack a scene's BVH can need and refuses a scene that could overflow it, so a
// STATUS_RAY_STACK_OVERFLOW never happens in a render that was allowed to start.
#pragma once

#include <cstdint>
#include <vector>

#include "bvh.h"

namespace vkrt {

// Inner nodes on the longest path from `root` to a leaf (a root whose children are leaves: 1).
std::uint32_t innerDepth(const std::vector<bvh::BinaryNode>& nodes, std::uint32_t root);

// The most stack entries traverse.glsl can hold: one per inner node on the path (the far child)
// in the top level, then one per inner node of the deepest bottom level. Without instancing only
// instance 0's bottom level is traversed.
std::uint32_t traversalStackNeed(const bvh::SceneBvh& bvh, bool instancing);

// Throws DeviceLimitExceeded naming the leaf when a bottom-level leaf cannot be packed into one
// stack entry (more than LEAF_ENTRY_MAX_COUNT primitives, or a first primitive beyond
// LEAF_ENTRY_MAX_FIRST; device_host.h).
void checkLeafEntries(const bvh::SceneBvh& bvh);

// Throws DeviceLimitExceeded naming both numbers when traversalStackNeed > capacity; then
// checkLeafEntries.
void checkTraversalStack(const bvh::SceneBvh& bvh, bool instancing, std::uint32_t capacity = gpu::TRAVERSAL_STACK_SIZE);

}  // namespace vkrt
