#include "flatten.h"

#include <algorithm>

#include "node_layout.h"

namespace vkrt::bvh {

namespace {

struct Flattener {
    const BuildTree& tree;
    const std::function<std::uint32_t(const BuildNode&)>& leafLink;
    std::vector<gpu::BvhNode>& out;
    FlattenResult& result;

    // Pre-order: the node, then its left subtree, then its right subtree. Recursion depth is the
    // tree's depth, which the builder bounds (SahParams::maxDepth).
    std::uint32_t emit(std::uint32_t buildIndex, int depth) {
        result.depth = std::max(result.depth, depth);
        const auto index = static_cast<std::uint32_t>(out.size());
        out.emplace_back();
        const BuildNode& node = tree[buildIndex];
        const std::uint32_t children[2] = {node.left(), node.right()};
        for (int k = 0; k < 2; ++k) {
            const BuildNode& child = tree[children[k]];
            if (child.leaf()) {
                ++result.leafCount;
                setChild(out[index], k, child.box(), leafLink(child), child.count());
            } else {
                const std::uint32_t c = emit(children[k], depth + 1);
                setChild(out[index], k, child.box(), c, 0);
            }
        }
        return index;
    }
};

}  // namespace

FlattenResult flatten(const BuildTree& tree, const std::function<std::uint32_t(const BuildNode&)>& leafLink,
                      std::vector<gpu::BvhNode>& out) {
    FlattenResult result;
    result.root = static_cast<std::uint32_t>(out.size());
    result.depth = 1;
    if (tree.empty() || tree[tree.root].leaf()) {
        gpu::BvhNode node{};
        setEmptyChild(node, 0);
        setEmptyChild(node, 1);
        if (!tree.empty()) {
            const BuildNode& leaf = tree[tree.root];
            setChild(node, 0, leaf.box(), leafLink(leaf), leaf.count());
            result.leafCount = 1;
        }
        out.push_back(node);
        return result;
    }
    Flattener{tree, leafLink, out, result}.emit(tree.root, 1);
    return result;
}

}  // namespace vkrt::bvh
