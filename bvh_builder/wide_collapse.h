// Two-child trees (SceneBvh::nodes) -> the CPU's 4-wide layout (wide_bvh.h).
#pragma once

#include <cstdint>
#include <vector>

#include "bvh.h"
#include "thread_pool.h"

namespace vkrt::bvh {

// Collapses the two-child tree rooted at `root` into `out`; returns the wide root. The subtrees
// rooted at blockRoots (FlattenResult::blockRoots) are collapsed in parallel and appended after
// the nodes of the part above them, which never opens a block's root.
std::uint32_t collapseTree(const std::vector<gpu::BvhNode>& nodes, std::uint32_t root,
                           const std::vector<std::uint32_t>& blockRoots, ThreadPool& pool, std::vector<WideNode>& out);

}  // namespace vkrt::bvh
