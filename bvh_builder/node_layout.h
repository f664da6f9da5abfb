// Reading and writing the two child slots of a gpu::BvhNode (layout: shaders/shared/device_host.h,
// byte by byte in docs/BVH.md). Floats travel as their bit patterns (the kernels read RGBA32UI
// texels), so encoding is a bit_cast and decoding gives back exactly the builder's floats.
#pragma once

#include <bit>
#include <cfloat>
#include <cstdint>

#include "aabb.h"
#include "../shaders/shared/device_host.h"

namespace vkrt::bvh {

inline std::uint32_t floatBits(float f) { return std::bit_cast<std::uint32_t>(f); }
inline float bitsFloat(std::uint32_t u) { return std::bit_cast<float>(u); }

// Child k (0 or 1): its box, and link/count as device_host.h defines them.
inline void setChild(gpu::BvhNode& node, int k, const Aabb& box, std::uint32_t link, std::uint32_t count) {
    glm::uvec4& xy = k == 0 ? node.xy0 : node.xy1;
    xy = {floatBits(box.lo.x), floatBits(box.hi.x), floatBits(box.lo.y), floatBits(box.hi.y)};
    node.z01[2 * k] = floatBits(box.lo.z);
    node.z01[2 * k + 1] = floatBits(box.hi.z);
    node.link[k] = link;
    node.link[2 + k] = count;
}

inline void setEmptyChild(gpu::BvhNode& node, int k) { setChild(node, k, Aabb{}, gpu::NODE_NONE, 0); }

inline Aabb childBox(const gpu::BvhNode& node, int k) {
    const glm::uvec4& xy = k == 0 ? node.xy0 : node.xy1;
    return {{bitsFloat(xy[0]), bitsFloat(xy[2]), bitsFloat(node.z01[2 * k])},
            {bitsFloat(xy[1]), bitsFloat(xy[3]), bitsFloat(node.z01[2 * k + 1])}};
}
inline std::uint32_t childLink(const gpu::BvhNode& node, int k) { return node.link[k]; }
inline std::uint32_t childCount(const gpu::BvhNode& node, int k) { return node.link[2 + k]; }
inline bool childIsInner(const gpu::BvhNode& node, int k) {
    return childCount(node, k) == 0 && childLink(node, k) != gpu::NODE_NONE;
}

}  // namespace vkrt::bvh
