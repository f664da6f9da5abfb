// CPU ray/primitive intersection in object space: the reference for the GLSL kernels and the
// routines of the CPU traversal. A hit needs 0 < t < tmax; t is in units of |dir| (the caller's
// world units, since instance transforms never renormalise the direction).
// The definitions live in intersect_inline.h (inlined into the traversal); vkrt_bvh is compiled
// with -ffp-contract=off because a fused multiply-add in an edge function breaks watertightness
// (a shared edge must give exactly opposite values in its two triangles).
#pragma once

#include <cmath>
#include <cstdint>
#include <utility>

#include <glm/glm.hpp>

namespace vkrt::bvh {

struct PrimHit {
    float t = 0.0f;
    float u = 0.0f, v = 0.0f;  // triangle: barycentric weights of v1 and v2
    int face = -1;             // box: face hit, 0..5 = -x, +x, -y, +y, -z, +z (outward normal)
};

// The ray as the watertight triangle test wants it (Woop, Benthin & Wald 2013, "Watertight
// Ray/Triangle Intersection", JCGT 2(1)): the axis where |dir| is largest becomes z, and a shear
// maps the direction to +z, so each edge test is a 2D cross product that adjacent triangles compute
// identically (no ray slips through a shared edge or vertex).
struct WatertightRay {
    glm::vec3 org{0.0f};
    int kx = 0, ky = 1, kz = 2;
    float sx = 0.0f, sy = 0.0f, sz = 1.0f;

    WatertightRay() = default;
    WatertightRay(const glm::vec3& o, const glm::vec3& d) : org(o) {
        const glm::vec3 a = glm::abs(d);
        kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
        kx = (kz + 1) % 3;
        ky = (kx + 1) % 3;
        const float dv[3] = {d.x, d.y, d.z};  // an array: glm indexes by a runtime axis with branches
        if (dv[kz] < 0.0f) std::swap(kx, ky);  // keeps the winding, so U, V, W keep their meaning
        sx = dv[kx] / dv[kz];
        sy = dv[ky] / dv[kz];
        sz = 1.0f / dv[kz];
    }
};

// Two-sided; zero-area triangles never hit (the determinant is exactly 0, or, for collinear
// corners whose float determinant is rounding noise, the edge cross product in double is 0).
bool intersectTriangle(const WatertightRay& r, const glm::vec3& v0, const glm::vec3& v1, const glm::vec3& v2,
                       float tmax, PrimHit& hit);

// Ray/sphere with the numerically stable quadratic of Haines et al., "Precision Improvements for
// Ray/Sphere Intersection" (Ray Tracing Gems, ch. 7). A sphere of radius 0 is never hit.
bool intersectSphere(const glm::vec3& o, const glm::vec3& d, const glm::vec3& centre, float radius, float tmax,
                     PrimHit& hit);

// Ray/box slab test for a solid box, returning the face hit (the exit face when the origin is
// inside). A zero direction component is taken as +1e-30 (the kernel's rule), so no NaN can arise
// and a ray lying exactly in a face plane is inside at the min face, outside at the max face.
bool intersectBox(const glm::vec3& o, const glm::vec3& d, const glm::vec3& lo, const glm::vec3& hi, float tmax,
                  PrimHit& hit);

// Outward normal of a box face index as intersectBox returns it.
inline glm::vec3 boxFaceNormal(int face) {
    glm::vec3 n(0.0f);
    n[face / 2] = (face % 2) ? 1.0f : -1.0f;
    return n;
}

}  // namespace vkrt::bvh
