#include "traversal_stack.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "node_layout.h"
#include "node_packing.h"
#include "vulkan_errors.h"

namespace vkrt {

std::uint32_t innerDepth(const std::vector<bvh::BinaryNode>& nodes, std::uint32_t root) {
    if (root == bvh::NODE_NONE) return 0;
    // Iterative: a degenerate BVH can be thousands of levels deep.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pending{{root, 1}};
    std::uint32_t deepest = 0;
    while (!pending.empty()) {
        const auto [index, depth] = pending.back();
        pending.pop_back();
        if (index >= nodes.size())
            throw std::logic_error("BVH node link " + std::to_string(index) + " is outside the " + std::to_string(nodes.size()) +
                                   " nodes");
        if (depth > nodes.size()) throw std::logic_error("the BVH's node links form a cycle");
        deepest = std::max(deepest, depth);
        const bvh::BinaryNode& node = nodes[index];
        for (int child = 0; child < 2; ++child) {
            if (bvh::childIsInner(node, child)) pending.emplace_back(bvh::childLink(node, child), depth + 1);
        }
    }
    return deepest;
}

std::uint32_t traversalStackNeed(const bvh::SceneBvh& bvh, bool instancing) {
    if (!instancing) return bvh.instances.empty() ? 0 : innerDepth(bvh.nodes, gpu::instanceRootNode(bvh.instances[0].info));
    std::uint32_t deepestBottom = 0;
    for (const gpu::Instance& instance : bvh.instances) deepestBottom = std::max(deepestBottom, innerDepth(bvh.nodes, gpu::instanceRootNode(instance.info)));
    return innerDepth(bvh.nodes, bvh.topRoot) + deepestBottom;
}

void checkLeafEntries(const bvh::SceneBvh& bvh) {
    // Bottom levels only (every node outside the top level, as packNodes classifies them):
    // top-level leaves are instance entries, not leaf entries.
    const std::vector<bool> topLevel = topLevelNodes(bvh);
    for (std::uint32_t index = 0; index < bvh.nodes.size(); ++index) {
        if (topLevel[index]) continue;
        const bvh::BinaryNode& node = bvh.nodes[index];
        for (int child = 0; child < 2; ++child) {
            const std::uint32_t link = bvh::childLink(node, child);
            const std::uint32_t count = bvh::childCount(node, child);
            if (count > 0 && (count > gpu::LEAF_ENTRY_MAX_COUNT || link > gpu::LEAF_ENTRY_MAX_FIRST)) {
                throw DeviceLimitExceeded("BVH node " + std::to_string(index) + " has a leaf of " + std::to_string(count) +
                                          " primitives starting at primitive " + std::to_string(link) +
                                          "; the kernel's traversal stack packs at most " +
                                          std::to_string(gpu::LEAF_ENTRY_MAX_COUNT) + " primitives starting below " +
                                          std::to_string(gpu::LEAF_ENTRY_MAX_FIRST + 1) +
                                          " (shaders/shared/device_host.h): build with smaller leaves");
            }
        }
    }
}

void checkTraversalStack(const bvh::SceneBvh& bvh, bool instancing, std::uint32_t capacity) {
    const std::uint32_t need = traversalStackNeed(bvh, instancing);
    if (need > capacity)
        throw DeviceLimitExceeded("the scene's BVH needs a traversal stack of " + std::to_string(need) +
                                  " entries but the kernel's TRAVERSAL_STACK_SIZE is " + std::to_string(capacity) +
                                  " (shaders/shared/device_host.h); the BVH is unusually deep: check for degenerate geometry");
    checkLeafEntries(bvh);
}

}  // namespace vkrt
