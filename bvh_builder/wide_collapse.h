// Two-child trees (SceneBvh::nodes) -> the CPU's 8-wide layout (wide_bvh.h).
#pragma once

#include <cstdint>
#include <vector>

#include "bvh.h"
#include "wide_bvh.h"
#include "thread_pool.h"

namespace vkrt::bvh {

// Collapsing runs in two passes, so that every tree's 8-wide nodes can be counted before the one
// allocation that holds them all (growing the array tree by tree reallocated and copied it: 40 of
// the 54 ms the collapse took at 1M triangles).
// planCollapse decides the 8-wide nodes the two-child tree rooted at `root` becomes and records
// them (in output order), so writing them needs no second descent. The subtrees rooted at
// blockRoots (FlattenResult::blockRoots) are planned and later written in parallel, after the
// nodes of the part above them, which never opens a block's root.
// One planned 8-wide node: slot k is child side[k] of two-child node source[k] (NODE_NONE: empty
// slot); its link is link[k], plus the part's first output index if bit k of `relative` is set.
struct PlannedNode {
    std::uint32_t source[kWideWidth];
    std::uint32_t link[kWideWidth];
    std::uint8_t side[kWideWidth];
    std::uint8_t relative;  // bit k: link[k] is relative (a bit per slot)
};
static_assert(kWideWidth <= 8, "PlannedNode::relative holds a bit per slot");
struct CollapsePlan {
    std::uint32_t root = 0;
    bool rootIsBlock = false;
    std::vector<std::uint32_t> blocks;      // block roots, sorted
    std::vector<std::uint32_t> blockSizes;  // 8-wide nodes per block
    std::uint32_t topCount = 0;             // 8-wide nodes above the blocks
    std::uint32_t total = 0;                // all of them
    std::vector<PlannedNode> top;           // the part above the blocks, in output order
    std::vector<std::vector<PlannedNode>> blockNodes;  // each block's, in output order
};
CollapsePlan planCollapse(const std::vector<BinaryNode>& nodes, std::uint32_t root,
                          const std::vector<std::uint32_t>& blockRoots, ThreadPool& pool);

// Writes the planned tree into out[first, first + plan.total) (links are indices into the whole
// array out belongs to); returns the wide root's index.
std::uint32_t writeCollapse(const std::vector<BinaryNode>& nodes, const CollapsePlan& plan, ThreadPool& pool,
                            WideNode* out, std::uint32_t first);

}  // namespace vkrt::bvh
