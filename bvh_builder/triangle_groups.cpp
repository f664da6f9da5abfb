#include "triangle_groups.h"

#include <algorithm>

#include "intersect_inline.h"
#include "node_layout.h"
#include "wide_bvh.h"

namespace vkrt::bvh {

namespace {

bool allTriangles(const std::vector<gpu::Primitive>& prims, std::uint32_t first, std::uint32_t count) {
    for (std::uint32_t p = first; p < first + count; ++p)
        if (gpu::primitiveKind(prims[p].a) != gpu::PRIM_KIND_TRIANGLE) return false;
    return true;
}

glm::vec3 corner(const glm::uvec4& texel) { return {bitsFloat(texel.x), bitsFloat(texel.y), bitsFloat(texel.z)}; }

// One leaf's triangles into its groups, four lanes each.
void fillGroups(const std::vector<gpu::Primitive>& prims, std::uint32_t first, std::uint32_t count, TriangleGroup* out) {
    for (std::uint32_t base = 0; base < count; base += 4, ++out) {
        TriangleGroup& g = *out;
        for (std::uint32_t lane = 0; lane < 4; ++lane) {
            const std::uint32_t p = first + base + lane;
            const bool real = base + lane < count;
            const glm::vec3 v[3] = {real ? corner(prims[p].a) : glm::vec3(0.0f), real ? corner(prims[p].b) : glm::vec3(0.0f),
                                    real ? corner(prims[p].c) : glm::vec3(0.0f)};
            for (int c = 0; c < 3; ++c)
                for (int axis = 0; axis < 3; ++axis) g.corner[c][axis][lane] = v[c][axis];
            if (real && !detail::collinear(v[0], v[1], v[2])) g.lanes |= 1u << lane;
        }
    }
}

}  // namespace

TriangleGroups buildTriangleGroups(const std::vector<gpu::Primitive>& prims, const WideNode* nodes,
                                   std::uint32_t bottomNodes, ThreadPool& pool) {
    // The leaves first (a pass over the nodes), so the groups are allocated once and filled in
    // parallel: filling them one by one into a growing array was most of the CPU copy's time
    // (dragon 3-6 ms of the copy's 5.8, sphere:512 77-82 of its 103; docs/BVH.md §4).
    struct Leaf {
        std::uint32_t first, count, group;
    };
    std::vector<Leaf> leaves;
    std::uint32_t groupCount = 0;
    for (std::uint32_t n = 0; n < bottomNodes; ++n) {
        for (int k = 0; k < kWideWidth; ++k) {
            const std::uint32_t first = nodes[n].link[k], count = nodes[n].count[k];
            if (count < 2 || !allTriangles(prims, first, count)) continue;
            leaves.push_back({first, count, groupCount});
            groupCount += (count + 3) / 4;
        }
    }
    TriangleGroups out;
    out.leafGroup.assign(prims.size(), TriangleGroups::kNone);
    out.groups.resize(groupCount);
    constexpr std::size_t kLeavesPerJob = 4096;
    pool.parallelFor((leaves.size() + kLeavesPerJob - 1) / kLeavesPerJob, [&](std::size_t job) {
        const std::size_t end = std::min(leaves.size(), (job + 1) * kLeavesPerJob);
        for (std::size_t i = job * kLeavesPerJob; i < end; ++i) {
            const Leaf& leaf = leaves[i];
            out.leafGroup[leaf.first] = leaf.group;
            fillGroups(prims, leaf.first, leaf.count, &out.groups[leaf.group]);
        }
    });
    return out;
}

}  // namespace vkrt::bvh
