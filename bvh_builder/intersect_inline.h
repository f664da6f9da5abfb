// Definitions of intersect.h, inlined into the CPU traversal. Only for vkrt_bvh's own sources,
// which are compiled without floating-point contraction (see intersect.h).
#pragma once

#include <algorithm>

#include "intersect.h"

namespace vkrt::bvh {

namespace detail {
// The paper's fallback: when an edge function is exactly zero in float, recompute all three in
// double, where the products of floats are exact, so a ray through an edge picks one side.
void edgeFunctionsDouble(float ax, float ay, float bx, float by, float cx, float cy, float& u, float& v, float& w);
// Whether the corners are collinear: the edge cross product in double, where the differences and
// products of the float coordinates are exact for all but extreme exponent ranges.
bool collinear(const glm::vec3& v0, const glm::vec3& v1, const glm::vec3& v2);
}  // namespace detail

// The watertight test after its three edge functions (u, v, w: float, with exact zeros already
// redone in double) and the sheared corners' z (az, bz, cz): the sign test, then the distance.
// Shared by the one-triangle test below and the traversal's four-triangle leaves (traverse.cpp),
// so both report the same hits bit for bit. Does not check for collinear corners.
[[gnu::always_inline]] inline bool watertightDistance(float u, float v, float w, float az, float bz, float cz,
                                                      float tmax, PrimHit& hit) {
    if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return false;
    const float det = u + v + w;
    if (det == 0.0f) return false;
    const float tScaled = u * az + v * bz + w * cz;
    // Reject before dividing: t = tScaled / det must lie in (0, tmax), with det of either sign.
    if (det > 0.0f ? (tScaled <= 0.0f || tScaled >= tmax * det) : (tScaled >= 0.0f || tScaled <= tmax * det))
        return false;
    const float inv = 1.0f / det;
    const float t = tScaled * inv;
    if (!(t > 0.0f && t < tmax)) return false;  // rounding of the division
    hit.t = t;
    hit.u = v * inv;
    hit.v = w * inv;
    hit.face = -1;
    return true;
}

[[gnu::always_inline]] inline bool intersectTriangleInline(const WatertightRay& r, const glm::vec3& v0, const glm::vec3& v1,
                              const glm::vec3& v2, float tmax, PrimHit& hit) {
    // Plain arrays, not glm::vec3: glm indexes a vector by a runtime axis with a chain of compares
    // and branches, an array by one indexed load.
    const float a[3] = {v0.x - r.org.x, v0.y - r.org.y, v0.z - r.org.z};
    const float b[3] = {v1.x - r.org.x, v1.y - r.org.y, v1.z - r.org.z};
    const float c[3] = {v2.x - r.org.x, v2.y - r.org.y, v2.z - r.org.z};
    const float ax = a[r.kx] - r.sx * a[r.kz], ay = a[r.ky] - r.sy * a[r.kz];
    const float bx = b[r.kx] - r.sx * b[r.kz], by = b[r.ky] - r.sy * b[r.kz];
    const float cx = c[r.kx] - r.sx * c[r.kz], cy = c[r.ky] - r.sy * c[r.kz];
    float u = cx * by - cy * bx;
    float v = ax * cy - ay * cx;
    float w = bx * ay - by * ax;
    if (u == 0.0f || v == 0.0f || w == 0.0f) detail::edgeFunctionsDouble(ax, ay, bx, by, cx, cy, u, v, w);
    PrimHit h;
    if (!watertightDistance(u, v, w, r.sz * a[r.kz], r.sz * b[r.kz], r.sz * c[r.kz], tmax, h)) return false;
    if (detail::collinear(v0, v1, v2)) return false;  // only reached by rays along a degenerate triangle
    hit = h;
    return true;
}

// The discriminant comes from the distance between the centre and the line's closest point (no
// b^2 - 4ac cancellation for far origins or large radii), and the two roots are q/a and c/q (no
// cancellation between -b and the square root).
inline bool intersectSphereInline(const glm::vec3& o, const glm::vec3& d, const glm::vec3& centre, float radius,
                            float tmax, PrimHit& hit) {
    if (!(radius > 0.0f)) return false;
    const glm::vec3 f = o - centre;
    const float a = glm::dot(d, d);
    const float bHalf = glm::dot(f, d);
    const glm::vec3 l = f - (bHalf / a) * d;  // centre -> closest point of the line
    const float disc = radius * radius - glm::dot(l, l);
    if (disc < 0.0f) return false;
    const float c = glm::dot(f, f) - radius * radius;
    const float q = -(bHalf + std::copysign(std::sqrt(a * disc), bHalf));
    if (q == 0.0f) return false;  // tangent line through the origin: both roots are 0
    float t0 = c / q, t1 = q / a;
    if (t0 > t1) std::swap(t0, t1);
    const float t = t0 > 0.0f ? t0 : t1;
    if (!(t > 0.0f && t < tmax)) return false;
    hit.t = t;
    hit.u = hit.v = 0.0f;
    hit.face = -1;
    return true;
}

inline bool intersectBoxInline(const glm::vec3& o, const glm::vec3& d, const glm::vec3& lo, const glm::vec3& hi,
                         float tmax, PrimHit& hit) {
    float tNear = -INFINITY, tFar = INFINITY;
    int nearFace = -1, farFace = -1;
    for (int axis = 0; axis < 3; ++axis) {
        // A zero component (either sign) becomes +1e-30, as in the GLSL kernel, so both paths agree on
        // rays lying exactly in a face plane (RENDERING.md §3): inside at the min face, outside at the
        // max face, never inside a zero-thickness slab. Slab distances stay finite or infinite, never NaN.
        const bool positive = !(d[axis] < 0.0f);
        const float inv = (positive ? 1.0f : -1.0f) / std::max(std::fabs(d[axis]), 1e-30f);
        float t0 = (lo[axis] - o[axis]) * inv, t1 = (hi[axis] - o[axis]) * inv;
        if (!positive) std::swap(t0, t1);
        if (t0 > tNear) {
            tNear = t0;
            nearFace = 2 * axis + (positive ? 0 : 1);
        }
        if (t1 < tFar) {
            tFar = t1;
            farFace = 2 * axis + (positive ? 1 : 0);
        }
    }
    if (tNear > tFar) return false;
    if (tNear > 0.0f) {
        if (!(tNear < tmax)) return false;
        hit.t = tNear;
        hit.face = nearFace;
    } else {
        if (!(tFar > 0.0f && tFar < tmax)) return false;
        hit.t = tFar;
        hit.face = farFace;
    }
    hit.u = hit.v = 0.0f;
    return true;
}

}  // namespace vkrt::bvh
