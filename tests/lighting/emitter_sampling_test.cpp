// Light samples of shape emitters (shaders/shared/emitter_sampling.h over host/lighting's
// EmitterTable) against closed forms: a triangle's solid angle, Lambert's polygon formula for the
// cosine integral of a quad, the agreement of a sample's density with the density a bounce's hit
// is weighed with, and the bound on a sample's weight near an emitter that solid-angle sampling
// exists for. Seeds are fixed: each test is deterministic; statistical bounds are 4 standard
// errors (p ~ 6e-5).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "emitter_sampling.h"
#include "emitter_table.h"
#include "sampling.h"
#include "scene.h"

namespace vkrt::test {
namespace {

constexpr double kPi = std::numbers::pi;

gpu::EmitterTriangle triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    gpu::EmitterTriangle t;
    t.corner = glm::vec4(a, 1.0f);
    t.edge1 = glm::vec4(b - a, 0.0f);
    t.edge2 = glm::vec4(c - a, 0.0f);
    return t;
}

// Lambert's formula: the integral of max(0, n . w) over the directions from x to the convex
// polygon's inside, (1/2) sum_i angle(v_i, v_i+1) n . unit(v_i x v_i+1), in double.
double polygonCosineIntegral(glm::dvec3 x, glm::dvec3 n, const std::vector<glm::dvec3>& corners) {
    double sum = 0.0;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const glm::dvec3 a = glm::normalize(corners[i] - x), b = glm::normalize(corners[(i + 1) % corners.size()] - x);
        sum += 0.5 * std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::dot(n, glm::normalize(glm::cross(a, b)));
    }
    return std::fabs(sum);
}

// Bug targeted: a solid angle off by a factor (2, the missing atan2 branch past pi/2) or one
// that loses its digits for a far triangle.
TEST(EmitterSampling, TriangleSolidAnglesMatchTheirClosedForms) {
    // The face z = 0.5 of the unit cube seen from its centre is 4 pi / 6, each half pi / 3.
    const glm::vec3 a(-0.5f, -0.5f, 0.5f), b(0.5f, -0.5f, 0.5f), c(0.5f, 0.5f, 0.5f), d(-0.5f, 0.5f, 0.5f);
    EXPECT_NEAR(emitters::triangleSolidAngle(triangle(a, b, c), glm::vec3(0.0f)), kPi / 3.0, 1e-6);
    EXPECT_NEAR(emitters::triangleSolidAngle(triangle(a, c, d), glm::vec3(0.0f)), kPi / 3.0, 1e-6);
    // Nearly the whole hemisphere (the atan2 branch beyond pi / 2): a 200 x 200 square 1 away,
    // 2 pi - 4 asin(...) in closed form: the solid angle of a w x w square at height h on its
    // axis is 4 asin(w^2 / (w^2 + 4 h^2)).
    const float w = 200.0f;
    const double square = 4.0 * std::asin(double(w) * w / (double(w) * w + 4.0));
    const glm::vec3 p(-w / 2, -w / 2, 1.0f), q(w / 2, -w / 2, 1.0f), r(w / 2, w / 2, 1.0f), s(-w / 2, w / 2, 1.0f);
    const double both = double(emitters::triangleSolidAngle(triangle(p, q, r), glm::vec3(0.0f))) +
                        emitters::triangleSolidAngle(triangle(p, r, s), glm::vec3(0.0f));
    EXPECT_NEAR(both / square, 1.0, 1e-5);
    // A 1 mm triangle 10 m away, facing x: its area over distance^2 to 1e-4.
    const glm::vec3 far(10.0f, 0.2f, -0.3f);
    const double tiny = emitters::triangleSolidAngle(
        triangle(far, far + glm::vec3(0.0f, 1e-3f, 0.0f), far + glm::vec3(0.0f, 0.0f, 1e-3f)), glm::vec3(0.0f));
    const double projected = 0.5e-6 * far.x / std::pow(glm::length(glm::dvec3(far)), 3.0);
    EXPECT_NEAR(tiny / projected, 1.0, 1e-4);
    // A point in the triangle's plane sees none of it.
    EXPECT_EQ(emitters::triangleSolidAngle(triangle(a, b, c), glm::vec3(2.0f, 0.0f, 0.5f)), 0.0f);
}

// A scene with one emitter, a 1 x 0.8 quad (two triangles) at y = 1 facing down, radiance 1.
Scene quadEmitterScene() {
    Scene scene;
    Mesh mesh;
    mesh.positions = {{-0.5f, 1.0f, -0.4f}, {0.5f, 1.0f, -0.4f}, {0.5f, 1.0f, 0.4f}, {-0.5f, 1.0f, 0.4f}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    scene.meshes.push_back(mesh);
    Emitter e;
    e.shape.type = ShapeType::Mesh;
    e.shape.mesh = 0;
    e.shape.shader = -1;
    scene.emitters.push_back(e);
    return scene;
}

// Bug targeted: Arvo's construction with a wrong sub-triangle (samples off the triangle, or
// bunched towards a corner), a triangle picked out of proportion to its solid angle, a density
// that is not 1 / the total solid angle. Receivers at 2 cm, 0.3 and 3 from the quad's plane, under
// its middle and its edge; the light samples' estimate of the cosine integral against Lambert's
// formula.
TEST(EmitterSampling, AQuadSampledBySolidAngleGivesLambertsCosineIntegral) {
    const Scene scene = quadEmitterScene();
    const EmitterTable table = buildEmitterTable(scene);
    const gpu::EmitterRecord& record = table.records.at(0);
    const std::vector<glm::dvec3> corners(scene.meshes[0].positions.begin(), scene.meshes[0].positions.end());
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    for (const glm::vec3 x : {glm::vec3(0.1f, 0.98f, 0.05f), glm::vec3(0.49f, 0.98f, -0.2f), glm::vec3(-0.3f, 0.7f, 0.2f),
                              glm::vec3(0.8f, -2.0f, -1.0f)}) {
        const int n = 20000;
        double sum = 0.0, sum2 = 0.0;
        for (int i = 0; i < n; ++i) {
            const emitters::EmitterSample s = sampleEmitter(table, record, x, glm::vec2(u01(rng), u01(rng)));
            ASSERT_GT(s.pdf, 0.0f);
            // On the quad: its plane and inside its rectangle (to float rounding of the intersection).
            ASSERT_NEAR(s.point.y, 1.0f, 1e-5f);
            ASSERT_LE(std::fabs(s.point.x), 0.5f + 1e-5f);
            ASSERT_LE(std::fabs(s.point.z), 0.4f + 1e-5f);
            // The density a bounce that hits this point is weighed with is the sample's own.
            ASSERT_NEAR(emitterPdf(table, record, x, s.point, s.normal) / s.pdf, 1.0f, 1e-5f);
            const double cosine = std::max(0.0, double(glm::normalize(s.point - x).y));
            const double v = cosine / s.pdf;
            sum += v;
            sum2 += v * v;
        }
        const double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
        const double exact = polygonCosineIntegral(glm::dvec3(x), {0.0, 1.0, 0.0}, corners);
        EXPECT_NEAR(mean, exact, 4.0 * se + 1e-6 * exact) << x.x << ", " << x.y << ", " << x.z;
    }
}

// Bug targeted: area sampling back near an emitter (issue 37: a surface 2 cm from a quad got
// samples of huge variance). By solid angle, a sample's weight cos / pdf is at most the quad's
// solid angle: bounded however near the receiver is; by area it is cos cos' d^2 / (area pdf), up to
// ~(0.5 / 0.02)^2 = 625 times its mean at 2 cm.
TEST(EmitterSampling, SamplesNearAQuadCarryBoundedWeights) {
    const EmitterTable table = buildEmitterTable(quadEmitterScene());
    const gpu::EmitterRecord& record = table.records.at(0);
    const glm::vec3 x(0.45f, 0.98f, 0.35f);  // 2 cm under a corner
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    double largest = 0.0, sum = 0.0;
    const int n = 4096;
    for (int i = 0; i < n; ++i) {
        const emitters::EmitterSample s = sampleEmitter(table, record, x, glm::vec2(u01(rng), u01(rng)));
        const double w = std::max(0.0, double(glm::normalize(s.point - x).y)) / s.pdf;
        largest = std::max(largest, w);
        sum += w;
    }
    EXPECT_LE(largest / (sum / n), 2.0 / (1.0 - 1e-3)) << "cos / pdf <= omega, and the mean of cos over the quad's "
                                                           "directions is >= 1/2 here";
}

// emitter_sampling.h solidAngleNear: a triangle set is sampled by solid angle from points within
// SOLID_ANGLE_NEAR radii of its bounding sphere's centre (the density 1 / the triangles' total solid
// angle wherever the sample lands) and by area beyond (the density distance^2 / (area cos)).
// Bug targeted: a bounding sphere not filled in (every point sampled by area, heavy-tailed near
// the emitter), the rule inverted, or a bounce's hit weighed by the other rule than its sample's
// (a wrong MIS weight: a bias the images would show only as a slight brightness error).
TEST(EmitterSampling, ATriangleSetIsSampledBySolidAngleNearItAndByAreaFarFromIt) {
    const Scene scene = quadEmitterScene();
    const EmitterTable table = buildEmitterTable(scene);
    const gpu::EmitterRecord& record = table.records.at(0);
    // The 1 x 0.8 quad's bounding sphere: its centre and half its diagonal.
    EXPECT_NEAR(record.sphere.x, 0.0f, 1e-6f);
    EXPECT_NEAR(record.sphere.y, 1.0f, 1e-6f);
    EXPECT_NEAR(record.sphere.z, 0.0f, 1e-6f);
    const float radius = std::sqrt(0.25f + 0.16f);
    EXPECT_NEAR(record.sphere.w, radius, 1e-5f);
    const float reach = emitters::SOLID_ANGLE_NEAR * radius;
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    // Straight under the centre, just inside and just outside the reach, and far off to the side.
    for (const float distance : {0.3f, 0.99f * reach, 1.01f * reach, 4.0f * reach}) {
        const glm::vec3 x(0.0f, 1.0f - distance, 0.0f);
        const bool near = distance < reach;
        const double omega = double(emitters::triangleSolidAngle(table.triangles[0], x)) +
                             emitters::triangleSolidAngle(table.triangles[1], x);
        for (int i = 0; i < 256; ++i) {
            const emitters::EmitterSample s = sampleEmitter(table, record, x, glm::vec2(u01(rng), u01(rng)));
            ASSERT_GT(s.pdf, 0.0f);
            const glm::dvec3 d = glm::dvec3(s.point) - glm::dvec3(x);
            const double byArea = glm::dot(d, d) / (0.8 * std::fabs(glm::normalize(d).y));
            const double expected = near ? 1.0 / omega : byArea;
            ASSERT_NEAR(s.pdf / expected, 1.0, 1e-4) << "distance " << distance << (near ? " (near)" : " (far)");
            ASSERT_NEAR(emitterPdf(table, record, x, s.point, s.normal) / s.pdf, 1.0f, 1e-5f);
        }
    }
}

// A box emitter, [-0.5, 0.5]^3 under `toWorld`.
Scene boxEmitterScene(const glm::mat4& toWorld) {
    Scene scene;
    Emitter e;
    e.shape.type = ShapeType::Box;
    e.shape.minPt = glm::vec3(-0.5f);
    e.shape.maxPt = glm::vec3(0.5f);
    e.shape.shader = -1;
    e.objectToWorld = toWorld;
    scene.emitters.push_back(e);
    return scene;
}

// The solid angle of a rectangle of sides a, b seen from distance d on its centre's normal.
double centredRectangleSolidAngle(double a, double b, double d) {
    return 4.0 * std::asin(a * b / std::sqrt((a * a + 4.0 * d * d) * (b * b + 4.0 * d * d)));
}

// emitter_sampling.h triangleFacesPoint: a box's light samples seen from outside go only to the
// faces in front of the point, and the density is 1 / their solid angle; from inside, to every face,
// whose solid angle is then the whole sphere's 4 pi. Under a rotation with a mirror (which reverses
// every triangle's winding: the table winds them outwards again) and a scale.
// Bug targeted: samples spent on the hidden faces (the density would be 1 / both sides' solid
// angle, half the samples occluded by the box itself), a winding left mirrored (the hidden faces
// taken for the front ones: samples behind the box), a point inside given no light at all, a
// bounce's hit weighed with another density than the samples'.
TEST(EmitterSampling, ABoxsLightSamplesGoToTheFacesInFrontOfThePoint) {
    const glm::mat4 toWorld = glm::rotate(glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 2.0f, -3.0f)),
                                                     glm::vec3(-2.0f, 2.0f, 2.0f)),
                                          0.7f, glm::normalize(glm::vec3(1.0f, 2.0f, 0.5f)));
    const EmitterTable table = buildEmitterTable(boxEmitterScene(toWorld));
    const gpu::EmitterRecord& record = table.records.at(0);
    ASSERT_TRUE(gpu::emitterConvex(record));
    const glm::mat4 toObject = glm::inverse(toWorld);
    // An object-space point 1.5 in front of the +z face, on its centre's normal: only that face (2 x 2
    // in the world) faces it, at world distance 3.
    struct Probe {
        glm::vec3 objectPoint;
        double omega;
    };
    const Probe probes[] = {{glm::vec3(0.0f, 0.0f, 2.0f), centredRectangleSolidAngle(2.0, 2.0, 3.0)},
                            {glm::vec3(0.1f, -0.2f, 0.15f), 4.0 * kPi}};
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    for (const Probe& probe : probes) {
        const glm::vec3 x(toWorld * glm::vec4(probe.objectPoint, 1.0f));
        const bool outside = glm::any(glm::greaterThan(glm::abs(probe.objectPoint), glm::vec3(0.5f)));
        for (int i = 0; i < 4000; ++i) {
            const emitters::EmitterSample s = sampleEmitter(table, record, x, glm::vec2(u01(rng), u01(rng)));
            ASSERT_GT(s.pdf, 0.0f);
            EXPECT_NEAR(s.pdf * probe.omega, 1.0, 2e-5) << (outside ? "outside" : "inside");
            const glm::vec3 q(toObject * glm::vec4(s.point, 1.0f));
            ASSERT_NEAR(std::max({std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)}), 0.5f, 1e-5f);  // on the box
            // Outside: on the +z face, the one in front of the point.
            if (outside) ASSERT_NEAR(q.z, 0.5f, 1e-5f) << q.x << ", " << q.y << ", " << q.z;
            ASSERT_NEAR(emitterPdf(table, record, x, s.point, s.normal) / s.pdf, 1.0f, 1e-5f);
        }
    }
    // From a point off every face's axis, three faces are in front: every sample lands on one of them.
    const glm::vec3 corner(toWorld * glm::vec4(1.5f, 1.2f, 0.9f, 1.0f));
    for (int i = 0; i < 4000; ++i) {
        const emitters::EmitterSample s = sampleEmitter(table, record, corner, glm::vec2(u01(rng), u01(rng)));
        const glm::vec3 q(toObject * glm::vec4(s.point, 1.0f));
        const bool front = std::fabs(q.x - 0.5f) < 1e-5f || std::fabs(q.y - 0.5f) < 1e-5f || std::fabs(q.z - 0.5f) < 1e-5f;
        ASSERT_TRUE(front) << q.x << ", " << q.y << ", " << q.z;
    }
}

// Bug targeted: the ellipsoid's cone density missing the Jacobian |det A| / |A w|^3 (or with the
// map's inverse), a sample off the ellipsoid, a bounce weighed with another density than the
// sample's. Inside or on it, area sampling; outside, the object sphere's cone.
TEST(EmitterSampling, AnEllipsoidsSamplesCarryTheDensityItsHitsAreWeighedWith) {
    Scene scene;
    Emitter e;
    e.shape.type = ShapeType::Sphere;
    e.shape.center = glm::vec3(0.1f, -0.2f, 0.0f);
    e.shape.radius = 0.7f;
    e.objectToWorld = glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.2f, 0.35f, 0.9f)), 0.7f,
                                             glm::vec3(0.3f, 1.0f, 0.2f)),
                                 glm::vec3(0.5f, 0.12f, 0.3f));
    scene.emitters.push_back(e);
    const EmitterTable table = buildEmitterTable(scene);
    const gpu::EmitterRecord& record = table.records.at(0);
    ASSERT_EQ(gpu::emitterKind(record), gpu::EMITTER_ELLIPSOID);
    const glm::mat4 toObject = glm::inverse(e.objectToWorld);
    std::mt19937 rng(13);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    // Whether the world ray x + t w meets the ellipsoid: the object ray meets the object sphere.
    auto hits = [&](glm::vec3 x, glm::vec3 w) {
        const glm::vec3 o = glm::vec3(toObject * glm::vec4(x, 1.0f)) - e.shape.center, d = glm::vec3(toObject * glm::vec4(w, 0.0f));
        const float b = glm::dot(o, d), c = glm::dot(o, o) - e.shape.radius * e.shape.radius, a = glm::dot(d, d);
        return b * b - a * c >= 0.0f && (c < 0.0f || b < 0.0f);
    };
    // Outside, 5% of the radius above its object-space top and far, and inside at its centre.
    auto world = [&](glm::vec3 object) { return glm::vec3(e.objectToWorld * glm::vec4(object, 1.0f)); };
    const glm::vec3 nearby = world(e.shape.center + glm::vec3(0.0f, 1.05f * e.shape.radius, 0.0f));
    const glm::vec3 centre = world(e.shape.center);
    for (const glm::vec3 x : {nearby, glm::vec3(1.5f, 0.4f, 0.2f), centre}) {
        const int n = 20000;
        double sum = 0.0, sum2 = 0.0;
        for (int i = 0; i < n; ++i) {
            const emitters::EmitterSample s = sampleEmitter(table, record, x, glm::vec2(u01(rng), u01(rng)));
            ASSERT_GT(s.pdf, 0.0f);
            const glm::vec3 object(toObject * glm::vec4(s.point, 1.0f));
            ASSERT_NEAR(glm::length(object - e.shape.center), e.shape.radius, 1e-4f);
            ASSERT_NEAR(emitterPdf(table, record, x, s.point, s.normal) / s.pdf, 1.0f, 1e-3f);
            sum += 1.0 / s.pdf;
            sum2 += 1.0 / (double(s.pdf) * s.pdf);
        }
        if (x == centre) continue;  // inside: area sampling (no cone)
        // Outside: the samples' mean 1 / pdf is the ellipsoid's solid angle, which uniform
        // directions measure independently (the fraction that hits it, times 4 pi).
        const double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
        const int m = 400000;
        int hit = 0;
        for (int i = 0; i < m; ++i) {
            const float z = 1.0f - 2.0f * u01(rng), phi = 2.0f * float(kPi) * u01(rng), r = std::sqrt(std::max(0.0f, 1.0f - z * z));
            hit += hits(x, glm::vec3(r * std::cos(phi), r * std::sin(phi), z)) ? 1 : 0;
        }
        const double p = double(hit) / m, omega = 4.0 * kPi * p, omegaSe = 4.0 * kPi * std::sqrt(p * (1.0 - p) / m);
        EXPECT_NEAR(mean, omega, 4.0 * std::hypot(se, omegaSe)) << x.x << ", " << x.y << ", " << x.z;
    }
}

// Each area light and shape emitter has a sample dimension of its own (sampling.h dimLight); more
// than MAX_LIGHT_ORDINALS of them would share the fixed dimensions (roulette, emitter choice) and
// correlate samples silently: such a scene is refused, naming both counts.
TEST(EmitterSampling, MoreLightsThanSampleDimensionsAreRefused) {
    Scene scene;
    scene.path = "many_lights.xml";
    Light area;
    area.type = LightType::Area;
    area.normal = glm::vec3(0.0f, -1.0f, 0.0f);
    scene.lights.assign(sampling::MAX_LIGHT_ORDINALS, area);
    EXPECT_NO_THROW(buildEmitterTable(scene));
    scene.lights.push_back(area);
    try {
        buildEmitterTable(scene);
        ADD_FAILURE() << "accepted " << scene.lights.size() << " area lights";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("many_lights.xml: 65531 area lights and 0 shape emitters"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace vkrt::test
