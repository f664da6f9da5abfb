// Moving a hit point off its surface before tracing a new ray from it (docs/RENDERING.md §6).
//
// The point moves along the normal by a bound on the floating-point error of the computation that
// produced it, in the spirit of pbrt's error bounds (Pharr, Jakob & Humphreys, "Physically Based
// Rendering" 3rd ed., §3.9): every error in computing a hit point, transforming it and testing the
// next ray against the same primitive is a few float epsilons (2^-24) times the largest magnitude
// involved, `magnitude` below. The offset is 16 epsilons of it: measured on both paths, shadow acne
// first appears at 1 epsilon and never at 4 (docs/STABILITY.md), so the margin is 4x, while a
// larger offset visibly moves refractions and contact shadows in scenes far from the origin. It
// scales with the scene: the same scene gives the same image at 1e-4 or 1e5, and a point near the
// origin on a large primitive (a ground sphere of radius 1e3 centred 1e3 below the origin) is moved
// by the primitive's error, not by its own tiny coordinates.
// No t epsilon is needed anywhere else.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace vkrt::cpu {

// 2^-20 = 16 * 2^-24: see above and RENDERING.md §6.
constexpr float kRayOffsetScale = 0x1p-20f;

// The largest absolute coordinate of v.
inline float maxAbs(const glm::vec3& v) { return std::max(std::fabs(v.x), std::max(std::fabs(v.y), std::fabs(v.z))); }

// p: the hit point in world space; n: the unit geometric normal on the side the new ray leaves on;
// magnitude: the hit's error magnitude (SurfacePoint::errorMagnitude); |p| is used when larger.
inline glm::vec3 offsetRayOrigin(const glm::vec3& p, const glm::vec3& n, float magnitude = 0.0f) {
    return p + (kRayOffsetScale * std::max(magnitude, maxAbs(p))) * n;
}

// The unit normal n flipped to the side of `dir` (the side a ray in direction `dir` leaves on);
// a direction exactly in the tangent plane counts as the front side.
inline glm::vec3 sideOf(const glm::vec3& n, const glm::vec3& dir) { return glm::dot(dir, n) >= 0.0f ? n : -n; }

}  // namespace vkrt::cpu
