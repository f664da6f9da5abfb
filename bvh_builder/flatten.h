// BuildTree -> gpu::BvhNode array: depth-first (a node's first inner child follows it directly),
// one 64-byte node per inner node of the build tree holding both children's boxes, leaves folded
// into their parent's child slot. A tree that is a single leaf (or empty) still gets one node, whose
// second slot is empty, so every group and the top level have a root node to start from.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "../shaders/shared/device_host.h"
#include "sah_builder.h"

namespace vkrt::bvh {

struct FlattenResult {
    std::uint32_t root = 0;     // index of the root node in the output array
    int depth = 0;              // nodes on the longest root-to-leaf path (>= 1)
    std::size_t leafCount = 0;
};

// leafLink(buildLeaf) gives the link written for a leaf slot (its count is the leaf's count).
FlattenResult flatten(const BuildTree& tree, const std::function<std::uint32_t(const BuildNode&)>& leafLink,
                      std::vector<gpu::BvhNode>& out);

}  // namespace vkrt::bvh
