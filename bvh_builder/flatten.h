// BuildTree -> BinaryNode array: depth-first (a node's first inner child follows it directly),
// one 64-byte node per inner node of the build tree holding both children's boxes, leaves folded
// into their parent's child slot. A tree that is a single leaf (or empty) still gets one node, whose
// second slot is empty, so every group and the top level have a root node to start from.
// The subtrees the builder made as separate jobs are flattened in parallel, each into a block
// that is contiguous in the output (depth-first order keeps every subtree contiguous).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "node_layout.h"
#include "sah_builder.h"

namespace vkrt::bvh {

struct FlattenResult {
    std::uint32_t root = 0;     // index of the root node in the output array
    int depth = 0;              // nodes on the longest root-to-leaf path (>= 1)
    std::size_t leafCount = 0;
    // SAH cost relative to the root box: sum over inner nodes of C_trav * A/A_root plus sum over
    // leaves of C_isect * N * A/A_root (summed per block, then in block order: the same for any
    // thread count).
    double sahCost = 0.0;
    std::vector<std::uint32_t> blockRoots;  // output nodes rooting the blocks flattened in parallel
};

// leafLink(buildLeaf) gives the link written for a leaf slot (its count is the leaf's count).
using LeafLink = std::function<std::uint32_t(const BuildNode&)>;

FlattenResult flatten(const BuildTree& tree, const LeafLink& leafLink, const SahParams& params, ThreadPool& pool,
                      std::vector<BinaryNode>& out);

}  // namespace vkrt::bvh
