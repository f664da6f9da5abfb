// Moving a hit point off its surface before tracing a new ray from it (docs/RENDERING.md §6).
//
// Wachter & Binder 2019 ("A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing
// Gems ch. 6): the point is nudged along the normal by a number of ULPs proportional to the
// normal's component, so the offset scales with the magnitude of each coordinate and works the
// same at any scene scale; near the origin, where ULPs become tiny, a fixed float offset is used.
// No t epsilon is needed anywhere else.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

namespace vkrt::cpu {

// p: the hit point in world space; n: the unit geometric normal on the side the new ray leaves on.
inline glm::vec3 offsetRayOrigin(const glm::vec3& p, const glm::vec3& n) {
    constexpr float kOriginRadius = 1.0f / 32.0f;  // below this |coordinate|, ULPs are too small
    constexpr float kFloatScale = 1.0f / 65536.0f;  // the fixed offset used there
    constexpr float kIntScale = 256.0f;             // ULPs per unit of normal component
    glm::vec3 out;
    for (int c = 0; c < 3; ++c) {
        const auto ulps = static_cast<std::int32_t>(kIntScale * n[c]);  // truncates toward zero, like GLSL int()
        const auto bits = std::bit_cast<std::int32_t>(p[c]);
        const float moved = std::bit_cast<float>(bits + (p[c] < 0.0f ? -ulps : ulps));
        out[c] = std::fabs(p[c]) < kOriginRadius ? p[c] + kFloatScale * n[c] : moved;
    }
    return out;
}

// The unit normal n flipped to the side of `dir` (the side a ray in direction `dir` leaves on);
// a direction exactly in the tangent plane counts as the front side.
inline glm::vec3 sideOf(const glm::vec3& n, const glm::vec3& dir) { return glm::dot(dir, n) >= 0.0f ? n : -n; }

}  // namespace vkrt::cpu
