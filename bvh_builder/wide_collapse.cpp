#include "wide_collapse.h"

#include <algorithm>
#include <array>
#include <cfloat>

#include "node_layout.h"

namespace vkrt::bvh {

namespace {

struct Slot {
    const float* box;  // the two-child node's 6 floats for this child, see readBox
    int k;             // which child of that node (selects the lanes)
    float area;        // half surface area, computed once
    std::uint32_t link, count;
    bool inner() const { return count == 0 && link != gpu::NODE_NONE; }
};

// Links in the part above the blocks that point at a block's (not yet placed) root.
constexpr std::uint32_t kBlockLink = 0x80000000u;

class Collapser {
public:
    // isBlock: two-child nodes that root a separately collapsed block (never opened here; their
    // slot's link becomes kBlockLink | block index).
    Collapser(const std::vector<gpu::BvhNode>& nodes, std::vector<WideNode>& out,
              const std::vector<std::uint32_t>* blockRoots)
        : nodes_(nodes), out_(out), blockRoots_(blockRoots) {}

    // Recursion depth is the two-child tree's depth, which the builder bounds.
    std::uint32_t convert(std::uint32_t node) {
        std::array<Slot, 4> slots;
        int n = 0;
        auto addChildren = [&](std::uint32_t index, int at) {
            // Inserts the non-empty child slots of a two-child node at position `at`.
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
        // Open the inner child with the largest surface area while there is room for its two
        // children (the SAH's view: the largest box is the one most rays enter).
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
        const auto index = static_cast<std::uint32_t>(out_.size());
        out_.emplace_back();
        std::array<std::uint32_t, 4> links;
        for (int k = 0; k < n; ++k) {
            if (!slots[k].inner()) links[k] = slots[k].link;
            else if (const int b = block(slots[k].link); b >= 0) links[k] = kBlockLink | static_cast<std::uint32_t>(b);
            else links[k] = convert(slots[k].link);
        }
        WideNode& w = out_[index];
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

private:
    int block(std::uint32_t node) const {
        if (!blockRoots_) return -1;
        const auto it = std::lower_bound(blockRoots_->begin(), blockRoots_->end(), node);
        return it != blockRoots_->end() && *it == node ? static_cast<int>(it - blockRoots_->begin()) : -1;
    }

    const std::vector<gpu::BvhNode>& nodes_;
    std::vector<WideNode>& out_;
    const std::vector<std::uint32_t>* blockRoots_;
};

}  // namespace

std::uint32_t collapseTree(const std::vector<gpu::BvhNode>& nodes, std::uint32_t root,
                           const std::vector<std::uint32_t>& blockRoots, const std::vector<std::uint32_t>& blockSizes,
                           ThreadPool& pool, std::vector<WideNode>& out) {
    // Blocks first, in parallel, each into its own array (local links, root at 0), in the order
    // of their roots (flatten's blocks come in depth-first order, so they are sorted already).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> order;
    for (std::size_t i = 0; i < blockRoots.size(); ++i) order.push_back({blockRoots[i], blockSizes[i]});
    std::sort(order.begin(), order.end());
    std::vector<std::uint32_t> sorted;
    for (const auto& o : order) sorted.push_back(o.first);
    std::vector<std::vector<WideNode>> blocks(sorted.size());
    pool.parallelFor(sorted.size(), [&](std::size_t i) {
        blocks[i].reserve(order[i].second);
        Collapser(nodes, blocks[i], nullptr).convert(sorted[i]);
    });
    // The part above the blocks, then the blocks appended, links moved by their offsets.
    const auto first = static_cast<std::uint32_t>(out.size());
    const bool rootIsBlock = std::binary_search(sorted.begin(), sorted.end(), root);
    if (!rootIsBlock) Collapser(nodes, out, &sorted).convert(root);
    const auto topEnd = static_cast<std::uint32_t>(out.size());
    std::vector<std::uint32_t> offsets(blocks.size());
    std::size_t total = out.size();
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        offsets[i] = static_cast<std::uint32_t>(total);
        total += blocks[i].size();
    }
    out.resize(total);
    for (std::uint32_t i = first; i < topEnd; ++i)
        for (int k = 0; k < 4; ++k)
            if (out[i].count[k] == 0 && out[i].link[k] != gpu::NODE_NONE && (out[i].link[k] & kBlockLink))
                out[i].link[k] = offsets[out[i].link[k] & ~kBlockLink];
    pool.parallelFor(blocks.size(), [&](std::size_t i) {
        for (std::size_t j = 0; j < blocks[i].size(); ++j) {
            WideNode w = blocks[i][j];
            for (int k = 0; k < 4; ++k)
                if (w.count[k] == 0 && w.link[k] != gpu::NODE_NONE) w.link[k] += offsets[i];
            out[offsets[i] + j] = w;
        }
    });
    return rootIsBlock ? offsets[static_cast<std::size_t>(std::lower_bound(sorted.begin(), sorted.end(), root) - sorted.begin())]
                       : first;
}

}  // namespace vkrt::bvh
