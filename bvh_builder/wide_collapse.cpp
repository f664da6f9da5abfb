#include "wide_collapse.h"

#include <algorithm>
#include <array>
#include <cfloat>

#include "node_layout.h"

namespace vkrt::bvh {

namespace {

struct Slot {
    std::uint32_t node;  // the two-child node holding this child
    int k;               // which of its two children
    float area;  // half surface area, computed once
    std::uint32_t link, count;
    bool inner() const { return count == 0 && link != NODE_NONE; }
};

// Links in the part above the blocks that point at a block's root, patched once blocks are placed.
constexpr std::uint32_t kBlockLink = 0x80000000u;

// The greedy collapse of one two-child tree (or the part of it above the blocks), planned once:
// the 8-wide nodes are recorded in output order, so the number of them is known before the one
// allocation, and writing them is a pass over the records. (Counting and writing used to descend
// the tree twice, computing every node's slots twice.)
class Collapser {
public:
    // blockRoots: sorted two-child nodes rooting separately collapsed blocks (never opened here;
    // their slot's link becomes kBlockLink | block index), or null.
    Collapser(const std::vector<BinaryNode>& nodes, const std::vector<std::uint32_t>* blockRoots)
        : nodes_(nodes), blockRoots_(blockRoots) {}

    // Records the subtree at `node` depth-first into out (a node's index is its position there,
    // links to inner children as such indices, flagged relative); returns its index.
    std::uint32_t plan(std::uint32_t node, std::vector<PlannedNode>& out) const {
        std::array<Slot, kWideWidth> slots;
        const int n = gather(node, slots);
        const auto index = static_cast<std::uint32_t>(out.size());
        out.emplace_back();
        PlannedNode p{};
        for (int k = 0; k < kWideWidth; ++k) {
            if (k >= n) {
                p.source[k] = NODE_NONE;
                continue;
            }
            p.source[k] = slots[k].node;
            p.side[k] = static_cast<std::uint8_t>(slots[k].k);
            if (!slots[k].inner()) {
                p.link[k] = slots[k].link;
            } else if (const int b = block(slots[k].link); b >= 0) {
                p.link[k] = kBlockLink | static_cast<std::uint32_t>(b);
            } else {
                p.link[k] = plan(slots[k].link, out);
                p.relative |= static_cast<std::uint8_t>(1u << k);
            }
        }
        out[index] = p;  // after the children: out may have grown
        return index;
    }

    int block(std::uint32_t node) const {
        if (!blockRoots_) return -1;
        const auto it = std::lower_bound(blockRoots_->begin(), blockRoots_->end(), node);
        return it != blockRoots_->end() && *it == node ? static_cast<int>(it - blockRoots_->begin()) : -1;
    }

private:
    // The up-to-8 child slots of an 8-wide node: the two-child node's children, then repeatedly the
    // inner child with the largest surface area replaced by its two children while there is room
    // (the SAH's view: the largest box is the one most rays enter). Recursion in plan() is as
    // deep as the two-child tree, which the builder bounds.
    int gather(std::uint32_t node, std::array<Slot, kWideWidth>& slots) const {
        int n = 0;
        auto addChildren = [&](std::uint32_t index, int at) {
            const BinaryNode& src = nodes_[index];
            const auto* f = reinterpret_cast<const float*>(&src);
            for (int k = 0; k < 2; ++k) {
                const std::uint32_t link = childLink(src, k), count = childCount(src, k);
                if (count == 0 && link == NODE_NONE) continue;
                const float* xy = f + 4 * k;
                const float* z = f + 8 + 2 * k;
                const float ex = xy[1] - xy[0], ey = xy[3] - xy[2], ez = z[1] - z[0];
                for (int j = n; j > at; --j) slots[j] = slots[j - 1];
                slots[at++] = {index, k, ex * ey + ey * ez + ez * ex, link, count};
                ++n;
            }
        };
        addChildren(node, 0);
        for (;;) {
            int widest = -1;
            for (int k = 0; k < n; ++k)
                if (slots[k].inner() && block(slots[k].link) < 0 && (widest < 0 || slots[k].area > slots[widest].area))
                    widest = k;
            if (widest < 0 || n + 1 > kWideWidth) break;
            const std::uint32_t open = slots[widest].link;
            for (int j = widest; j + 1 < n; ++j) slots[j] = slots[j + 1];
            --n;
            addChildren(open, widest);
        }
        return n;
    }

    const std::vector<BinaryNode>& nodes_;
    const std::vector<std::uint32_t>* blockRoots_;
};

// Writes a planned 8-wide node; base: the output index of its part's first node.
void writeNode(const std::vector<BinaryNode>& nodes, const PlannedNode& p, std::uint32_t base, WideNode& w) {
    for (int k = 0; k < kWideWidth; ++k) {
        if (p.source[k] == NODE_NONE) {  // empty slot: the empty box (see wide_bvh.h)
            for (int row = 0; row < 6; ++row) w.bounds[row][k] = (row % 2) ? -FLT_MAX : FLT_MAX;
            w.link[k] = NODE_NONE;
            w.count[k] = 0;
            continue;
        }
        const BinaryNode& src = nodes[p.source[k]];
        const auto* f = reinterpret_cast<const float*>(&src);
        const float* xy = f + 4 * p.side[k];
        const float* z = f + 8 + 2 * p.side[k];
        w.bounds[0][k] = xy[0];
        w.bounds[1][k] = xy[1];
        w.bounds[2][k] = xy[2];
        w.bounds[3][k] = xy[3];
        w.bounds[4][k] = z[0];
        w.bounds[5][k] = z[1];
        w.link[k] = p.link[k] + (((p.relative >> k) & 1u) ? base : 0u);
        w.count[k] = childCount(src, p.side[k]);
    }
}

}  // namespace

CollapsePlan planCollapse(const std::vector<BinaryNode>& nodes, std::uint32_t root,
                          const std::vector<std::uint32_t>& blockRoots, ThreadPool& pool) {
    CollapsePlan plan;
    plan.root = root;
    plan.blocks = blockRoots;
    std::sort(plan.blocks.begin(), plan.blocks.end());
    plan.rootIsBlock = std::binary_search(plan.blocks.begin(), plan.blocks.end(), root);
    const Collapser whole(nodes, nullptr);
    const Collapser above(nodes, &plan.blocks);
    // The part above the blocks, then each block (in parallel); they are placed in that order.
    if (!plan.rootIsBlock) above.plan(root, plan.top);
    plan.topCount = static_cast<std::uint32_t>(plan.top.size());
    plan.blockNodes.resize(plan.blocks.size());
    plan.blockSizes.resize(plan.blocks.size());
    pool.parallelFor(plan.blocks.size(), [&](std::size_t i) {
        whole.plan(plan.blocks[i], plan.blockNodes[i]);
        plan.blockSizes[i] = static_cast<std::uint32_t>(plan.blockNodes[i].size());
    });
    plan.total = plan.topCount;
    for (std::uint32_t s : plan.blockSizes) plan.total += s;
    return plan;
}

std::uint32_t writeCollapse(const std::vector<BinaryNode>& nodes, const CollapsePlan& plan, ThreadPool& pool,
                            WideNode* out, std::uint32_t first) {
    std::vector<std::uint32_t> offsets(plan.blocks.size());
    std::uint32_t total = first + plan.topCount;
    for (std::size_t i = 0; i < offsets.size(); ++i) {
        offsets[i] = total;
        total += plan.blockSizes[i];
    }
    // Every part straight into its place.
    for (std::uint32_t i = 0; i < plan.topCount; ++i) {
        WideNode& w = out[first + i];
        writeNode(nodes, plan.top[i], first, w);
        for (int k = 0; k < kWideWidth; ++k)
            if (w.count[k] == 0 && w.link[k] != NODE_NONE && (w.link[k] & kBlockLink))
                w.link[k] = offsets[w.link[k] & ~kBlockLink];
    }
    pool.parallelFor(plan.blocks.size(), [&](std::size_t i) {
        const std::vector<PlannedNode>& part = plan.blockNodes[i];
        for (std::size_t j = 0; j < part.size(); ++j) writeNode(nodes, part[j], offsets[i], out[offsets[i] + j]);
    });
    if (!plan.rootIsBlock) return first;
    const auto it = std::lower_bound(plan.blocks.begin(), plan.blocks.end(), plan.root);
    return offsets[static_cast<std::size_t>(it - plan.blocks.begin())];
}

}  // namespace vkrt::bvh
