#include "flatten.h"

#include <algorithm>

#include "node_layout.h"
#include "prefault.h"

namespace vkrt::bvh {

namespace {

// Depth-first emission of one part of a tree into out[next...]. In the top part, inner children
// that root a job's subtree are not descended: the subtree's block (whose size is known from the
// build) is reserved at the current position and emitted later, in parallel with the others.
struct Emitter {
    const BuildTree& tree;
    const LeafLink& leafLink;
    const SahParams& params;
    BinaryNode* out;
    std::uint32_t next;                                // next output index
    std::function<int(std::uint32_t)> blockOf;         // top part only: block of a subtree root, or -1
    std::function<void(int block, std::uint32_t offset, int level)> placed;
    std::function<std::uint32_t(int block)> blockSize;
    int depth = 0;
    std::size_t leaves = 0;
    double sahRaw = 0.0;  // not yet divided by the root's area

    // Recursion depth is the tree's depth, which the builder bounds (SahParams::maxDepth).
    std::uint32_t emit(std::uint32_t buildIndex, int level) {
        depth = std::max(depth, level);
        const std::uint32_t index = next++;
        const BuildNode& node = tree[buildIndex];
        sahRaw += params.traversalCost * node.box().halfArea();
        const std::uint32_t children[2] = {node.left(), node.right()};
        for (int k = 0; k < 2; ++k) {
            const BuildNode& child = tree[children[k]];
            if (child.leaf()) {
                ++leaves;
                sahRaw += params.intersectionCost * child.count() * child.box().halfArea();
                setChild(out[index], k, child.box(), leafLink(child), child.count());
                continue;
            }
            const int block = blockOf ? blockOf(children[k]) : -1;
            std::uint32_t c;
            if (block >= 0) {
                c = next;
                next += blockSize(block);
                placed(block, c, level + 1);
            } else {
                c = emit(children[k], level + 1);
            }
            setChild(out[index], k, child.box(), c, 0);
        }
        return index;
    }
};

struct Block {
    std::uint32_t buildRoot = 0, size = 0;  // size: inner nodes
    std::uint32_t offset = 0;               // first output index
    int level = 0;                          // depth of its root in the whole tree
    int depth = 0;
    std::size_t leaves = 0;
    double sahRaw = 0.0;
};

}  // namespace

FlattenResult flatten(const BuildTree& tree, const LeafLink& leafLink, const SahParams& params, ThreadPool& pool,
                      std::vector<BinaryNode>& out) {
    FlattenResult result;
    result.root = static_cast<std::uint32_t>(out.size());
    result.depth = 1;
    if (tree.empty() || tree[tree.root].leaf()) {
        BinaryNode node{};
        setEmptyChild(node, 0);
        setEmptyChild(node, 1);
        if (!tree.empty()) {
            const BuildNode& leaf = tree[tree.root];
            setChild(node, 0, leaf.box(), leafLink(leaf), leaf.count());
            result.leafCount = 1;
            result.sahCost = params.intersectionCost * leaf.count();
        }
        out.push_back(node);
        return result;
    }

    // The jobs' inner subtrees become blocks; the top phase's nodes are laid out around them.
    std::vector<Block> blocks;
    std::size_t total = tree.topCount;
    for (std::size_t i = 0; i < tree.subtreeRoots.size(); ++i)
        if (!tree[tree.subtreeRoots[i]].leaf()) {
            blocks.push_back({tree.subtreeRoots[i], tree.subtreeInnerNodes[i]});
            total += tree.subtreeInnerNodes[i];
        }
    prefaultCapacity(out, out.size() + total, pool);
    out.resize(out.size() + total);
    std::vector<std::pair<std::uint32_t, int>> blockIndex;  // (build root, block), sorted
    for (std::size_t i = 0; i < blocks.size(); ++i) blockIndex.push_back({blocks[i].buildRoot, static_cast<int>(i)});
    std::sort(blockIndex.begin(), blockIndex.end());
    auto blockOf = [&](std::uint32_t buildIndex) {
        const auto it =
            std::lower_bound(blockIndex.begin(), blockIndex.end(), std::pair<std::uint32_t, int>{buildIndex, -1});
        return it != blockIndex.end() && it->first == buildIndex ? it->second : -1;
    };
    auto placed = [&](int block, std::uint32_t offset, int level) {
        blocks[block].offset = offset;
        blocks[block].level = level;
    };
    auto blockSize = [&](int block) { return blocks[block].size; };

    // 1. The top part, depth-first, reserving each block where it is met.
    Emitter top{tree, leafLink, params, out.data(), result.root, blockOf, placed, blockSize};
    if (const int rootBlock = blockOf(tree.root); rootBlock >= 0) placed(rootBlock, result.root, 1);
    else top.emit(tree.root, 1);

    // 2. The blocks, in parallel, each into its reserved range.
    pool.parallelFor(blocks.size(), [&](std::size_t i) {
        Block& b = blocks[i];
        Emitter e{tree, leafLink, params, out.data(), b.offset, {}, {}, {}};
        e.emit(b.buildRoot, 1);
        b.depth = e.depth;
        b.leaves = e.leaves;
        b.sahRaw = e.sahRaw;
    });

    // Totals in block order, so they do not depend on the thread count.
    result.depth = std::max(1, top.depth);
    result.leafCount = top.leaves;
    double sahRaw = top.sahRaw;
    for (const Block& b : blocks) {
        result.depth = std::max(result.depth, b.level - 1 + b.depth);
        result.leafCount += b.leaves;
        sahRaw += b.sahRaw;
        result.blockRoots.push_back(b.offset);
    }
    const double rootArea = tree[tree.root].box().halfArea();
    result.sahCost = rootArea > 0.0 ? sahRaw / rootArea : 0.0;  // no area, no cost model
    return result;
}

}  // namespace vkrt::bvh
