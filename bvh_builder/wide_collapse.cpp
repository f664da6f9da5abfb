#include "wide_collapse.h"

#include <algorithm>
#include <array>
#include <cfloat>

#include "node_layout.h"

namespace vkrt::bvh {

namespace {

struct Slot {
    const float* box;  // the two-child node's floats; this child's lanes are selected by k
    int k;
    float area;  // half surface area, computed once
    std::uint32_t link, count;
    bool inner() const { return count == 0 && link != gpu::NODE_NONE; }
};

// Links in the part above the blocks that point at a block's root, patched once blocks are placed.
constexpr std::uint32_t kBlockLink = 0x80000000u;

// The greedy collapse of one two-child tree (or the part of it above the blocks). Run twice: once
// counting the 4-wide nodes (so every part's place in the output is known), once writing them
// straight into their place, so no part needs a temporary array.
class Collapser {
public:
    // blockRoots: sorted two-child nodes rooting separately collapsed blocks (never opened here;
    // their slot's link becomes kBlockLink | block index), or null.
    Collapser(const std::vector<gpu::BvhNode>& nodes, const std::vector<std::uint32_t>* blockRoots)
        : nodes_(nodes), blockRoots_(blockRoots) {}

    // Number of 4-wide nodes the subtree at `node` becomes.
    std::uint32_t count(std::uint32_t node) const {
        std::array<Slot, 4> slots;
        const int n = gather(node, slots);
        std::uint32_t total = 1;
        for (int k = 0; k < n; ++k)
            if (slots[k].inner() && block(slots[k].link) < 0) total += count(slots[k].link);
        return total;
    }

    // Writes the subtree at `node` into out[next...] depth-first (links as out indices + base,
    // which is out's index in the final array); returns the index of its root.
    std::uint32_t write(std::uint32_t node, WideNode* out, std::uint32_t base, std::uint32_t& next) const {
        std::array<Slot, 4> slots;
        const int n = gather(node, slots);
        const std::uint32_t index = next++;
        std::array<std::uint32_t, 4> links{};
        for (int k = 0; k < n; ++k) {
            if (!slots[k].inner()) links[k] = slots[k].link;
            else if (const int b = block(slots[k].link); b >= 0) links[k] = kBlockLink | static_cast<std::uint32_t>(b);
            else links[k] = base + write(slots[k].link, out, base, next);
        }
        WideNode& w = out[index];
        for (int k = 0; k < 4; ++k) {
            if (k >= n) {  // empty slot: the empty box (see wide_bvh.h)
                for (int row = 0; row < 6; ++row) w.bounds[row][k] = (row % 2) ? -FLT_MAX : FLT_MAX;
                w.link[k] = gpu::NODE_NONE;
                w.count[k] = 0;
                continue;
            }
            const float* xy = slots[k].box + 4 * slots[k].k;
            const float* z = slots[k].box + 8 + 2 * slots[k].k;
            w.bounds[0][k] = xy[0];
            w.bounds[1][k] = xy[1];
            w.bounds[2][k] = xy[2];
            w.bounds[3][k] = xy[3];
            w.bounds[4][k] = z[0];
            w.bounds[5][k] = z[1];
            w.link[k] = links[k];
            w.count[k] = slots[k].count;
        }
        return index;
    }

    int block(std::uint32_t node) const {
        if (!blockRoots_) return -1;
        const auto it = std::lower_bound(blockRoots_->begin(), blockRoots_->end(), node);
        return it != blockRoots_->end() && *it == node ? static_cast<int>(it - blockRoots_->begin()) : -1;
    }

private:
    // The up-to-4 child slots of a 4-wide node: the two-child node's children, then repeatedly the
    // inner child with the largest surface area replaced by its two children while there is room
    // (the SAH's view: the largest box is the one most rays enter). Recursion in count/write is as
    // deep as the two-child tree, which the builder bounds.
    int gather(std::uint32_t node, std::array<Slot, 4>& slots) const {
        int n = 0;
        auto addChildren = [&](std::uint32_t index, int at) {
            const gpu::BvhNode& src = nodes_[index];
            const auto* f = reinterpret_cast<const float*>(&src);
            for (int k = 0; k < 2; ++k) {
                const std::uint32_t link = childLink(src, k), count = childCount(src, k);
                if (count == 0 && link == gpu::NODE_NONE) continue;
                const float* xy = f + 4 * k;
                const float* z = f + 8 + 2 * k;
                const float ex = xy[1] - xy[0], ey = xy[3] - xy[2], ez = z[1] - z[0];
                for (int j = n; j > at; --j) slots[j] = slots[j - 1];
                slots[at++] = {f, k, ex * ey + ey * ez + ez * ex, link, count};
                ++n;
            }
        };
        addChildren(node, 0);
        for (;;) {
            int widest = -1;
            for (int k = 0; k < n; ++k)
                if (slots[k].inner() && block(slots[k].link) < 0 && (widest < 0 || slots[k].area > slots[widest].area))
                    widest = k;
            if (widest < 0 || n + 1 > 4) break;
            const std::uint32_t open = slots[widest].link;
            for (int j = widest; j + 1 < n; ++j) slots[j] = slots[j + 1];
            --n;
            addChildren(open, widest);
        }
        return n;
    }

    const std::vector<gpu::BvhNode>& nodes_;
    const std::vector<std::uint32_t>* blockRoots_;
};

}  // namespace

CollapsePlan planCollapse(const std::vector<gpu::BvhNode>& nodes, std::uint32_t root,
                          const std::vector<std::uint32_t>& blockRoots, ThreadPool& pool) {
    CollapsePlan plan;
    plan.root = root;
    plan.blocks = blockRoots;
    std::sort(plan.blocks.begin(), plan.blocks.end());
    plan.rootIsBlock = std::binary_search(plan.blocks.begin(), plan.blocks.end(), root);
    const Collapser whole(nodes, nullptr);
    const Collapser above(nodes, &plan.blocks);
    // The part above the blocks, then each block (in parallel); they are placed in that order.
    plan.topCount = plan.rootIsBlock ? 0 : above.count(root);
    plan.blockSizes.resize(plan.blocks.size());
    pool.parallelFor(plan.blocks.size(), [&](std::size_t i) { plan.blockSizes[i] = whole.count(plan.blocks[i]); });
    plan.total = plan.topCount;
    for (std::uint32_t s : plan.blockSizes) plan.total += s;
    return plan;
}

std::uint32_t writeCollapse(const std::vector<gpu::BvhNode>& nodes, const CollapsePlan& plan, ThreadPool& pool,
                            WideNode* out, std::uint32_t first) {
    const Collapser whole(nodes, nullptr);
    const Collapser above(nodes, &plan.blocks);
    std::vector<std::uint32_t> offsets(plan.blocks.size());
    std::uint32_t total = first + plan.topCount;
    for (std::size_t i = 0; i < offsets.size(); ++i) {
        offsets[i] = total;
        total += plan.blockSizes[i];
    }
    // Every part straight into its place.
    if (!plan.rootIsBlock) {
        std::uint32_t next = 0;
        above.write(plan.root, out + first, first, next);
        for (std::uint32_t i = first; i < first + plan.topCount; ++i)
            for (int k = 0; k < 4; ++k)
                if (out[i].count[k] == 0 && out[i].link[k] != gpu::NODE_NONE && (out[i].link[k] & kBlockLink))
                    out[i].link[k] = offsets[out[i].link[k] & ~kBlockLink];
    }
    pool.parallelFor(plan.blocks.size(), [&](std::size_t i) {
        std::uint32_t next = 0;
        whole.write(plan.blocks[i], out + offsets[i], offsets[i], next);
    });
    if (!plan.rootIsBlock) return first;
    const auto it = std::lower_bound(plan.blocks.begin(), plan.blocks.end(), plan.root);
    return offsets[static_cast<std::size_t>(it - plan.blocks.begin())];
}

}  // namespace vkrt::bvh
