// Two-child trees (SceneBvh::nodes) -> the CPU's 4-wide layout (wide_bvh.h).
#pragma once

#include <cstdint>
#include <vector>

#include "bvh.h"
#include "thread_pool.h"

namespace vkrt::bvh {

// Collapsing runs in two passes, so that every tree's 4-wide nodes can be counted before the one
// allocation that holds them all (growing the array tree by tree reallocated and copied it: 40 of
// the 54 ms the collapse took at 1M triangles).
// planCollapse counts the 4-wide nodes the two-child tree rooted at `root` becomes. The subtrees
// rooted at blockRoots (FlattenResult::blockRoots) are counted and later written in parallel,
// after the nodes of the part above them, which never opens a block's root.
struct CollapsePlan {
    std::uint32_t root = 0;
    bool rootIsBlock = false;
    std::vector<std::uint32_t> blocks;      // block roots, sorted
    std::vector<std::uint32_t> blockSizes;  // 4-wide nodes per block
    std::uint32_t topCount = 0;             // 4-wide nodes above the blocks
    std::uint32_t total = 0;                // all of them
};
CollapsePlan planCollapse(const std::vector<gpu::BvhNode>& nodes, std::uint32_t root,
                          const std::vector<std::uint32_t>& blockRoots, ThreadPool& pool);

// Writes the planned tree into out[first, first + plan.total) (links are indices into the whole
// array out belongs to); returns the wide root's index.
std::uint32_t writeCollapse(const std::vector<gpu::BvhNode>& nodes, const CollapsePlan& plan, ThreadPool& pool,
                            WideNode* out, std::uint32_t first);

}  // namespace vkrt::bvh
