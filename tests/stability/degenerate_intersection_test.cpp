// Grazing and degenerate rays against the CPU intersection routines and traversal directly
// (bvh_builder/intersect.h, bvh.h): axis-parallel rays on slab planes, rays nearly parallel to
// triangles and box faces, zero-area triangles, spheres of radius 1e-6 and 1e6. Every answer must be
// finite and follow the rules of RENDERING.md §3; the GPU kernel's versions are checked by the
// renders in degenerate_render_test.cpp against the same rules.
#include <cmath>
#include <limits>
#include <optional>

#include <gtest/gtest.h>

#include "bvh.h"
#include "intersect.h"

namespace vkrt::stability {
namespace {

bool finite(const bvh::PrimHit& h) { return std::isfinite(h.t) && std::isfinite(h.u) && std::isfinite(h.v); }

// ---- boxes and axis-parallel rays ------------------------------------------------------------

// The half-open rule of RENDERING.md §3 for a ray with a zero component along an axis.
bool insideHalfOpen(float c, float lo, float hi) { return lo <= c && c < hi; }

TEST(AxisParallelRays, FollowTheHalfOpenSlabRuleWithoutNaN) {
    const glm::vec3 lo(-1.0f, -0.5f, -2.0f), hi(1.0f, 0.5f, 2.0f);
    bvh::SceneBvh bvh = bvh::buildSceneBvh({{bvh::PrimitiveInput{gpu::PRIM_KIND_BOX, lo, hi, {}}}}, {bvh::InstanceInput{}});
    int checked = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const int b = (axis + 1) % 3, c = (axis + 2) % 3;
        auto probes = [](float l, float h) {
            return std::vector<float>{std::nextafter(l, -10.0f), l, 0.5f * (l + h), std::nextafter(h, -10.0f), h,
                                      std::nextafter(h, 10.0f)};
        };
        for (float sign : {-1.0f, 1.0f})
            for (float zero : {0.0f, -0.0f})  // a negative zero must behave like a positive one
                for (float pb : probes(lo[b], hi[b]))
                    for (float pc : probes(lo[c], hi[c])) {
                        glm::vec3 o(0.0f), d(zero);
                        o[axis] = -sign * 10.0f;
                        o[b] = pb;
                        o[c] = pc;
                        d[axis] = sign;
                        bvh::PrimHit h;
                        const bool hit = bvh::intersectBox(o, d, lo, hi, 1e30f, h);
                        const bool expected = insideHalfOpen(pb, lo[b], hi[b]) && insideHalfOpen(pc, lo[c], hi[c]);
                        EXPECT_EQ(hit, expected) << "axis " << axis << " sign " << sign << " at " << pb << ", " << pc;
                        if (hit) {
                            EXPECT_TRUE(finite(h));
                            EXPECT_FLOAT_EQ(h.t, 10.0f - (sign > 0 ? -lo[axis] : hi[axis]));
                            EXPECT_EQ(h.face, 2 * axis + (sign > 0 ? 0 : 1));  // the entry face
                        }
                        // The traversal's node test must not cull what the box test hits, or let through
                        // what it rejects.
                        bvh::Ray ray;
                        ray.origin = o;
                        ray.dir = d;
                        bvh::Hit bh;
                        EXPECT_EQ(bvh::intersectClosest(bvh, ray, bh), expected);
                        ++checked;
                    }
    }
    EXPECT_EQ(checked, 3 * 2 * 2 * 36);
}

TEST(AxisParallelRays, NeverEnterAZeroThicknessBoxEdgeOn) {
    // A tile with lo.y == hi.y: a ray lying in its plane does not hit (the slab is empty); rays
    // through it from above and below do, on the face they enter.
    const glm::vec3 lo(-1.0f, 0.25f, -1.0f), hi(1.0f, 0.25f, 1.0f);
    bvh::PrimHit h;
    EXPECT_FALSE(bvh::intersectBox({-5.0f, 0.25f, 0.0f}, {1.0f, 0.0f, 0.0f}, lo, hi, 1e30f, h));
    EXPECT_FALSE(bvh::intersectBox({-5.0f, 0.25f, 0.0f}, {1.0f, -0.0f, 0.0f}, lo, hi, 1e30f, h));
    ASSERT_TRUE(bvh::intersectBox({0.0f, 2.25f, 0.0f}, {0.0f, -1.0f, 0.0f}, lo, hi, 1e30f, h));
    EXPECT_EQ(h.t, 2.0f);
    EXPECT_EQ(h.face, 3);  // +y
    ASSERT_TRUE(bvh::intersectBox({0.0f, -1.75f, 0.0f}, {0.0f, 1.0f, 0.0f}, lo, hi, 1e30f, h));
    EXPECT_EQ(h.t, 2.0f);
    EXPECT_EQ(h.face, 2);  // -y
}

// ---- grazing rays ----------------------------------------------------------------------------

// Rays aimed at a point of a surface from 5 units away at elevation angle theta. Down to 1e-3 rad
// the hit must be at the aimed point (t = 1 within 1e-3); below, the crossing is ill-conditioned
// (t's error grows like eps / theta) and a hit or a miss are both right, but never a NaN, a t
// outside (0, tmax) or barycentrics outside [0, 1].
template <class Intersect>
void sweepGrazing(const glm::vec3& target, const Intersect& intersect, const char* what) {
    for (double theta : {0.3, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-9, 0.0})
        for (double azimuth : {0.0, 0.7, 2.0, 3.9, 5.5}) {
            const glm::dvec3 back(-std::cos(theta) * std::cos(azimuth), std::sin(theta), -std::cos(theta) * std::sin(azimuth));
            const glm::vec3 origin = glm::vec3(glm::dvec3(target) + 5.0 * back);
            const glm::vec3 dir = target - origin;
            bvh::PrimHit h;
            const bool hit = intersect(origin, dir, h);
            if (theta >= 1e-3) {
                EXPECT_TRUE(hit) << what << " theta " << theta << " azimuth " << azimuth;
            }
            if (!hit) continue;
            EXPECT_TRUE(finite(h)) << what << " theta " << theta;
            EXPECT_GT(h.t, 0.0f);
            if (theta >= 1e-3) {
                EXPECT_NEAR(h.t, 1.0f, 1e-3f) << what << " theta " << theta;
            }
            EXPECT_GE(h.u, 0.0f);
            EXPECT_GE(h.v, 0.0f);
            EXPECT_LE(h.u + h.v, 1.0f + 1e-6f);
        }
}

TEST(GrazingRays, NearlyParallelToATriangle) {
    const glm::vec3 v0(-2.0f, 0.0f, -2.0f), v1(2.0f, 0.0f, -2.0f), v2(0.0f, 0.0f, 2.0f);
    sweepGrazing({0.1f, 0.0f, -0.3f}, [&](glm::vec3 o, glm::vec3 d, bvh::PrimHit& h) {
        return bvh::intersectTriangle(bvh::WatertightRay(o, d), v0, v1, v2, 1e30f, h);
    }, "triangle");
    // A ray lying in the triangle's plane never hits it (det = 0).
    bvh::PrimHit h;
    EXPECT_FALSE(bvh::intersectTriangle(bvh::WatertightRay({-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}), v0, v1, v2, 1e30f, h));
}

TEST(GrazingRays, NearlyParallelToABoxFace) {
    const glm::vec3 lo(-2.0f, -1.0f, -2.0f), hi(2.0f, 0.0f, 2.0f);
    sweepGrazing({0.1f, 0.0f, -0.3f}, [&](glm::vec3 o, glm::vec3 d, bvh::PrimHit& h) {
        return bvh::intersectBox(o, d, lo, hi, 1e30f, h);
    }, "box");
}

// ---- zero-area triangles ---------------------------------------------------------------------

TEST(ZeroAreaTriangles, AreNeverHit) {
    const glm::vec3 a(-1.0f, 0.0f, 0.0f), b(1.0f, 0.0f, 0.0f), mid(0.0f, 0.0f, 0.0f), far(3.0f, 0.0f, 0.0f);
    const glm::vec3 tilted0(-1.0f, -1.0f, 0.5f), tilted1(0.5f, 0.5f, -0.25f), tilted2(2.0f, 2.0f, -1.0f);  // collinear
    const std::vector<std::array<glm::vec3, 3>> degenerate = {
        {a, b, mid}, {a, mid, b}, {a, b, far}, {a, a, b}, {a, b, b}, {mid, mid, mid}, {tilted0, tilted1, tilted2}};
    // Rays through the segment's points from every side, and rays along the segment itself.
    std::vector<std::pair<glm::vec3, glm::vec3>> rays;
    for (const glm::vec3& p : {a, mid, b, glm::vec3(0.3f, 0.0f, 0.0f), tilted1})
        for (const glm::vec3& d : {glm::vec3(0, 0, -1), glm::vec3(0, -1, 0), glm::vec3(0.3f, -1.0f, 0.2f), glm::vec3(1, 0, 0),
                                   glm::vec3(1, 1, -0.5f)})
            rays.emplace_back(p - 3.0f * d, d);
    for (const auto& tri : degenerate)
        for (const auto& [o, d] : rays) {
            bvh::PrimHit h;
            EXPECT_FALSE(bvh::intersectTriangle(bvh::WatertightRay(o, d), tri[0], tri[1], tri[2], 1e30f, h))
                << "ray from (" << o.x << "," << o.y << "," << o.z << ") dir (" << d.x << "," << d.y << "," << d.z << ")";
        }
}

// ---- tiny and huge spheres -------------------------------------------------------------------

std::optional<double> raySphereDouble(glm::dvec3 o, glm::dvec3 d, glm::dvec3 c, double r) {
    const double a = glm::dot(d, d);
    const glm::dvec3 f = o - c;
    const double b = glm::dot(f, d);
    const glm::dvec3 l = f - (b / a) * d;
    const double disc = r * r - glm::dot(l, l);
    if (disc < 0.0) return std::nullopt;
    const double root = std::sqrt(a * disc);
    const double t0 = (-b - root) / a, t1 = (-b + root) / a;
    if (t0 > 0.0) return t0;
    if (t1 > 0.0) return t1;
    return std::nullopt;
}

TEST(ExtremeSpheres, HitWhereDoublePrecisionSays) {
    // Radius 1e-6 and 1e6, at the origin and 1e3 radii away from it; rays from outside (towards the
    // centre and offset up to 0.99 r) and from inside. t must agree with double to 1e-5 relative,
    // except for rays grazing the silhouette, which only need to be finite.
    int compared = 0;
    for (double r : {1e-6, 1.0, 1e6})
        for (double offsetFromOrigin : {0.0, 1e3}) {
            const glm::vec3 c(glm::dvec3(offsetFromOrigin * r, 0.0, 0.0));
            for (double eyeDistance : {0.0, 0.5, 4.0, 100.0})  // in radii; 0 and 0.5 are inside
                for (double aim : {0.0, 0.3, 0.9, 0.99, 0.999999}) {
                    const glm::vec3 o = c + glm::vec3(glm::dvec3(0.1 * r, 0.0, eyeDistance * r));
                    const glm::vec3 target = c + glm::vec3(glm::dvec3(aim * r, 0.0, 0.0));
                    const glm::vec3 d = target - o;
                    bvh::PrimHit h;
                    const bool hit = bvh::intersectSphere(o, d, c, static_cast<float>(r), 1e30f, h);
                    const auto expected = raySphereDouble(glm::dvec3(o), glm::dvec3(d), glm::dvec3(c), double(float(r)));
                    if (hit) {
                        EXPECT_TRUE(finite(h));
                    }
                    if (aim > 0.99) continue;  // near-tangent from outside: either answer
                    ASSERT_EQ(hit, expected.has_value()) << "r " << r << " eye " << eyeDistance << " aim " << aim;
                    if (!hit) continue;
                    EXPECT_NEAR(h.t, *expected, 1e-5 * *expected) << "r " << r << " eye " << eyeDistance << " aim " << aim;
                    ++compared;
                }
        }
    EXPECT_GT(compared, 50);
}

}  // namespace
}  // namespace vkrt::stability
