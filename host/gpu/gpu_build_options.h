// The BVH build a GPU render uploads: the SAH constants measured for the lavapipe kernel, which
// differ from the CPU traversal's (bvh::BuildOptions' defaults).
//
// The kernel walks a binary tree in 8-lane lockstep and tests a leaf's primitives in a loop of
// its own (shaders/traverse.glsl), so a node visited costs the group a walk pass (~330
// instructions) while a primitive costs a leaf pass that only the lanes in that leaf need.
// Charging a node twice a primitive (C_trav = 2) gives fewer, larger leaves and a shallower tree,
// which traces shadow rays faster and the others no slower (docs/BVH.md §4, "SAH constants":
// `vkrt-bench gpu rays SOURCE --ctrav C`). The CPU's wide traversal is slower on that tree, so
// the CPU keeps C_trav = 1.
#pragma once

#include "bvh.h"

namespace vkrt {

inline constexpr float kGpuTraversalCost = 2.0f;

inline bvh::BuildOptions gpuBuildOptions() {
    bvh::BuildOptions options;
    options.traversalCost = kGpuTraversalCost;
    options.cpuTraversal = false;  // the kernels never read the CPU's 8-wide copy
    return options;
}

}  // namespace vkrt
