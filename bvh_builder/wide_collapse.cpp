#include "wide_collapse.h"

#include <array>

#include "huge_pages.h"
#include "node_layout.h"

namespace vkrt::bvh {

namespace {

struct Slot {
    Aabb box;
    std::uint32_t link = gpu::NODE_NONE, count = 0;
    bool inner() const { return count == 0 && link != gpu::NODE_NONE; }
};

class Collapser {
public:
    Collapser(const std::vector<gpu::BvhNode>& nodes, WideBvh& out) : nodes_(nodes), out_(out) {}

    // Recursion depth is the two-child tree's depth, which the builder bounds.
    std::uint32_t convert(std::uint32_t node) {
        std::array<Slot, 4> slots;
        int n = 0;
        auto addChildren = [&](std::uint32_t index, int at) {
            // Inserts the non-empty child slots of a two-child node at position `at`.
            const gpu::BvhNode& src = nodes_[index];
            for (int k = 0; k < 2; ++k) {
                const Slot s{childBox(src, k), childLink(src, k), childCount(src, k)};
                if (s.count == 0 && s.link == gpu::NODE_NONE) continue;
                for (int j = n; j > at; --j) slots[j] = slots[j - 1];
                slots[at++] = s;
                ++n;
            }
        };
        addChildren(node, 0);
        // Open the inner child with the largest surface area while there is room for its two
        // children (the SAH's view: the largest box is the one most rays enter).
        for (;;) {
            int widest = -1;
            for (int k = 0; k < n; ++k)
                if (slots[k].inner() && (widest < 0 || slots[k].box.halfArea() > slots[widest].box.halfArea())) widest = k;
            if (widest < 0 || n + 1 > 4) break;
            const std::uint32_t open = slots[widest].link;
            for (int j = widest; j + 1 < n; ++j) slots[j] = slots[j + 1];
            --n;
            addChildren(open, widest);
        }
        const auto index = static_cast<std::uint32_t>(out_.nodes.size());
        out_.nodes.emplace_back();
        std::array<std::uint32_t, 4> links{};
        for (int k = 0; k < n; ++k) links[k] = slots[k].inner() ? convert(slots[k].link) : slots[k].link;
        WideNode& w = out_.nodes[index];
        for (int k = 0; k < 4; ++k) {
            const Slot s = k < n ? slots[k] : Slot{};
            w.bounds[0][k] = s.box.lo.x;
            w.bounds[1][k] = s.box.hi.x;
            w.bounds[2][k] = s.box.lo.y;
            w.bounds[3][k] = s.box.hi.y;
            w.bounds[4][k] = s.box.lo.z;
            w.bounds[5][k] = s.box.hi.z;
            w.link[k] = k < n ? links[k] : gpu::NODE_NONE;
            w.count[k] = s.count;
        }
        return index;
    }

private:
    const std::vector<gpu::BvhNode>& nodes_;
    WideBvh& out_;
};

}  // namespace

WideBvh collapseToWide(const SceneBvh& bvh) {
    WideBvh wide;
    // A 4-wide tree has about a third of the two-child tree's nodes.
    reserveHuge(wide.nodes, bvh.nodes.size() / 2 + 16);
    Collapser c(bvh.nodes, wide);
    for (const GroupRange& g : bvh.groups) wide.groupRoots.push_back(c.convert(g.rootNode));
    wide.topRoot = c.convert(bvh.topRoot);
    return wide;
}

}  // namespace vkrt::bvh
