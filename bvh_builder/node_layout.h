// The builder's node, bvh::BinaryNode, and reading and writing its two child slots (byte by byte in
// docs/BVH.md §1). It never reaches a kernel: host/gpu/node_packing turns it into the layout the
// kernels read (gpu::GpuBvhNode, shaders/shared/device_host.h), and wide_collapse into the CPU's
// 8-wide copy. Floats are stored as their bit patterns, in the texel order the GPU layout keeps,
// so encoding is a bit_cast and decoding gives back exactly the builder's floats.
#pragma once

#include <bit>
#include <cfloat>
#include <cstdint>

#include <glm/glm.hpp>

#include "aabb.h"

namespace vkrt::bvh {

// An empty child's link (its count is 0 and its box empty).
inline constexpr std::uint32_t NODE_NONE = 0xffffffffu;

// 64 bytes, both children's boxes side by side (Aila & Laine 2009), so one contiguous fetch per
// inner step decides both children:
//   xy0:  child 0 box  lo.x hi.x lo.y hi.y   (float bits)
//   xy1:  child 1 box  lo.x hi.x lo.y hi.y   (float bits)
//   z01:  lo0.z hi0.z lo1.z hi1.z            (float bits)
//   link: link0 link1 count0 count1
// countK == 0: linkK is the index of an inner node in SceneBvh::nodes (NODE_NONE: empty child).
// countK  > 0: child K is a leaf holding primitives [linkK, linkK + countK) of SceneBvh::prims
//              (bottom level) or instances [linkK, linkK + countK) (top level).
// An empty child stores lo = +FLT_MAX, hi = -FLT_MAX; a min/max slab test would treat that
// inverted box as everything, so traversals skip an empty child by its link, never by its box.
struct BinaryNode {
    glm::uvec4 xy0;
    glm::uvec4 xy1;
    glm::uvec4 z01;
    glm::uvec4 link;
};
static_assert(sizeof(BinaryNode) == 64);

inline std::uint32_t floatBits(float f) { return std::bit_cast<std::uint32_t>(f); }
inline float bitsFloat(std::uint32_t u) { return std::bit_cast<float>(u); }

// Child k (0 or 1): its box, and link/count as above.
inline void setChild(BinaryNode& node, int k, const Aabb& box, std::uint32_t link, std::uint32_t count) {
    glm::uvec4& xy = k == 0 ? node.xy0 : node.xy1;
    xy = {floatBits(box.lo.x), floatBits(box.hi.x), floatBits(box.lo.y), floatBits(box.hi.y)};
    node.z01[2 * k] = floatBits(box.lo.z);
    node.z01[2 * k + 1] = floatBits(box.hi.z);
    node.link[k] = link;
    node.link[2 + k] = count;
}

inline void setEmptyChild(BinaryNode& node, int k) { setChild(node, k, Aabb{}, NODE_NONE, 0); }

inline Aabb childBox(const BinaryNode& node, int k) {
    const glm::uvec4& xy = k == 0 ? node.xy0 : node.xy1;
    return {{bitsFloat(xy[0]), bitsFloat(xy[2]), bitsFloat(node.z01[2 * k])},
            {bitsFloat(xy[1]), bitsFloat(xy[3]), bitsFloat(node.z01[2 * k + 1])}};
}
inline std::uint32_t childLink(const BinaryNode& node, int k) { return node.link[k]; }
inline std::uint32_t childCount(const BinaryNode& node, int k) { return node.link[2 + k]; }
inline bool childIsInner(const BinaryNode& node, int k) {
    return childCount(node, k) == 0 && childLink(node, k) != NODE_NONE;
}

}  // namespace vkrt::bvh
