#include "triangle_groups.h"

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

}  // namespace

TriangleGroups buildTriangleGroups(const std::vector<gpu::Primitive>& prims, const WideNode* nodes,
                                   std::uint32_t bottomNodes) {
    TriangleGroups out;
    out.leafGroup.assign(prims.size(), TriangleGroups::kNone);
    for (std::uint32_t n = 0; n < bottomNodes; ++n) {
        for (int k = 0; k < kWideWidth; ++k) {
            const std::uint32_t first = nodes[n].link[k], count = nodes[n].count[k];
            if (count < 2 || !allTriangles(prims, first, count)) continue;
            out.leafGroup[first] = static_cast<std::uint32_t>(out.groups.size());
            for (std::uint32_t base = 0; base < count; base += 4) {
                TriangleGroup& g = out.groups.emplace_back();
                for (std::uint32_t lane = 0; lane < 4; ++lane) {
                    const std::uint32_t p = first + base + lane;
                    const bool real = base + lane < count;
                    const glm::vec3 v[3] = {real ? corner(prims[p].a) : glm::vec3(0.0f),
                                            real ? corner(prims[p].b) : glm::vec3(0.0f),
                                            real ? corner(prims[p].c) : glm::vec3(0.0f)};
                    for (int c = 0; c < 3; ++c)
                        for (int axis = 0; axis < 3; ++axis) g.corner[c][axis][lane] = v[c][axis];
                    if (real && !detail::collinear(v[0], v[1], v[2])) g.lanes |= 1u << lane;
                }
            }
        }
    }
    return out;
}

}  // namespace vkrt::bvh
