// Direct lighting against closed forms: every clean pixel (one surface and one shadow state over
// its whole footprint) must equal the mean, over the pixel's camera samples, of the analytic
// radiance computed here in double precision by brute force over the primitives.
//
// Tolerance 1e-4 in linear radiance (1/40 of an 8-bit step): the renderer works in float, so
// directions and hit points carry relative errors of ~1e-6 and a Blinn-Phong exponent of 32
// magnifies them to ~3e-5; a wrong normal, a half-pixel shift or a missing light is > 1e-2.
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "analytic_scene.h"

namespace vkrt::test {
namespace {

constexpr double kTolerance = 1e-4;

struct DMaterial {
    glm::dvec3 kd{0.0}, ks{0.0};
    double phongExp = 1.0;
};

// One primitive in double precision, possibly an instanced sphere (unit sphere under `toWorld`).
struct DPrim {
    enum Kind { Sphere, Box, Triangle, Ellipsoid } kind = Sphere;
    glm::dvec3 a{0.0}, b{0.0}, c{0.0};  // sphere: centre, (radius,..); box: lo, hi; triangle: v0 v1 v2
    glm::dmat4 toWorld{1.0};
    DMaterial material;
};

struct DHit {
    double t = INFINITY;
    glm::dvec3 normal{0.0};  // unit, outward
    int id = -1;
};

void intersect(const DPrim& p, int index, const DRay& ray, DHit& best) {
    auto consider = [&](double t, glm::dvec3 n, int face) {
        if (t > 1e-9 && t < best.t) best = {t, glm::normalize(n), index * 8 + face};
    };
    switch (p.kind) {
    case DPrim::Sphere:
        if (auto t = raySphere(ray, p.a, p.b.x)) consider(*t, ray.origin + *t * ray.dir - p.a, 0);
        break;
    case DPrim::Ellipsoid: {
        const glm::dmat4 inv = glm::inverse(p.toWorld);
        const glm::dvec3 o = glm::dvec3(inv * glm::dvec4(ray.origin, 1.0));
        const glm::dvec3 d = glm::dvec3(inv * glm::dvec4(ray.dir, 0.0));
        const double a = glm::dot(d, d), b = glm::dot(o, d), c = glm::dot(o, o) - 1.0;
        const double disc = b * b - a * c;
        if (disc < 0.0) break;
        const double t = (-b - std::sqrt(disc)) / a;  // camera outside: the near root
        const glm::dvec3 nObject = o + t * d;
        consider(t, glm::transpose(glm::inverse(glm::dmat3(p.toWorld))) * nObject, 0);
        break;
    }
    case DPrim::Box: {
        double tNear = -INFINITY, tFar = INFINITY;
        int axis = 0;
        for (int k = 0; k < 3; ++k) {
            const double t0 = (p.a[k] - ray.origin[k]) / ray.dir[k], t1 = (p.b[k] - ray.origin[k]) / ray.dir[k];
            const double lo = std::min(t0, t1), hi = std::max(t0, t1);
            if (lo > tNear) { tNear = lo; axis = k; }
            tFar = std::min(tFar, hi);
        }
        if (tNear > tFar || tNear <= 0.0) break;  // the tests look at boxes from outside
        glm::dvec3 n(0.0);
        n[axis] = ray.dir[axis] < 0.0 ? 1.0 : -1.0;
        consider(tNear, n, 1 + axis * 2 + (n[axis] > 0 ? 1 : 0));
        break;
    }
    case DPrim::Triangle: {
        const glm::dvec3 e1 = p.b - p.a, e2 = p.c - p.a;
        const glm::dvec3 pv = glm::cross(ray.dir, e2);
        const double det = glm::dot(e1, pv);
        if (det == 0.0) break;
        const glm::dvec3 tv = ray.origin - p.a;
        const double u = glm::dot(tv, pv) / det;
        const glm::dvec3 qv = glm::cross(tv, e1);
        const double v = glm::dot(ray.dir, qv) / det;
        if (u < 0.0 || v < 0.0 || u + v > 1.0) break;
        consider(glm::dot(e2, qv) / det, glm::cross(e1, e2), 0);
        break;
    }
    }
}

struct DLight {
    glm::dvec3 position, intensity;
};

// Whitted direct lighting (RENDERING.md §4-§5) with hard shadows, written independently.
struct DirectScene {
    std::vector<DPrim> prims;
    std::vector<DLight> lights;
    glm::dvec3 background{0.0};

    DHit closest(const DRay& ray) const {
        DHit best;
        for (std::size_t k = 0; k < prims.size(); ++k) intersect(prims[k], static_cast<int>(k), ray, best);
        return best;
    }

    Seen operator()(const DRay& ray) const {
        const DHit hit = closest(ray);
        if (hit.id < 0) return {-1, background};
        const DMaterial& m = prims[hit.id / 8].material;
        const glm::dvec3 p = ray.origin + hit.t * ray.dir;
        const glm::dvec3 n = glm::dot(hit.normal, ray.dir) > 0.0 ? -hit.normal : hit.normal;  // two-sided
        Seen seen{hit.id * 16, glm::dvec3(0.0)};
        for (std::size_t k = 0; k < lights.size(); ++k) {
            const glm::dvec3 toLight = lights[k].position - p;
            const double dist = glm::length(toLight);
            const glm::dvec3 l = toLight / dist;
            const double nl = glm::dot(n, l);
            if (nl <= 0.0) continue;
            const DHit blocker = closest({p + 1e-7 * n, l});
            if (blocker.id >= 0 && blocker.t < dist) {
                seen.surface += 1 << k;  // shadow boundaries are discontinuities too
                continue;
            }
            const glm::dvec3 h = glm::normalize(l - ray.dir);
            seen.radiance += m.kd * lights[k].intensity * nl +
                             m.ks * lights[k].intensity * std::pow(std::max(0.0, glm::dot(n, h)), m.phongExp);
        }
        return seen;
    }
};

// The same scene for the renderer; ellipsoids become prototype instances.
Scene toScene(const DirectScene& d, const Camera& camera) {
    Scene scene;
    scene.cameras.push_back(camera);
    scene.background = glm::vec3(d.background);
    for (const DLight& l : d.lights) scene.lights.push_back(pointLight(glm::vec3(l.position), glm::vec3(l.intensity)));
    for (const DPrim& p : d.prims) {
        Shader s = makeShader(glm::dot(p.material.ks, p.material.ks) > 0.0 ? ShaderType::BlinnPhong : ShaderType::Lambertian,
                              glm::vec3(p.material.kd));
        s.specular = glm::vec3(p.material.ks);
        s.phongExp = static_cast<float>(p.material.phongExp);
        const int shader = addShader(scene, s);
        switch (p.kind) {
        case DPrim::Sphere: scene.shapes.push_back(sphere(glm::vec3(p.a), float(p.b.x), shader)); break;
        case DPrim::Box: scene.shapes.push_back(box(glm::vec3(p.a), glm::vec3(p.b), shader)); break;
        case DPrim::Triangle:
            scene.shapes.push_back(triangle(glm::vec3(p.a), glm::vec3(p.b), glm::vec3(p.c), shader));
            break;
        case DPrim::Ellipsoid: {
            scene.prototypes.push_back(sphere(glm::vec3(0.0f), 1.0f, shader));
            Instance inst;
            inst.prototype = static_cast<int>(scene.prototypes.size()) - 1;
            inst.objectToWorld = glm::mat4(p.toWorld);
            scene.instances.push_back(inst);
            break;
        }
        }
    }
    return scene;
}

void expectAgreement(const DirectScene& d, const Camera& camera, const RenderOptions& options, const char* name,
                     int minCompared) {
    const Scene scene = toScene(d, camera);
    const Image image = renderChecked(scene, options);
    const DCamera dcam = makeDCamera(camera, options.width, options.height);
    const Agreement a = compareWithClosedForm(image, dcam, d, options);
    std::printf("[closed form] %-34s %4d clean pixels, max error %.2e\n", name, a.compared, a.maxError);
    EXPECT_GE(a.compared, minCompared) << "too few clean pixels: the scene does not test what it should";
    EXPECT_LE(a.maxError, kTolerance) << a.worst;
}

DPrim sphereAt(glm::dvec3 c, double r, DMaterial m) {
    DPrim p;
    p.kind = DPrim::Sphere;
    p.a = c;
    p.b = glm::dvec3(r, 0, 0);
    p.material = m;
    return p;
}

// oneSphere-like: a Lambertian sphere 5 units in front of the camera under two point lights.
DirectScene lambertianSphere() {
    DirectScene d;
    d.prims.push_back(sphereAt({0, 0, -5}, 1.0, {{0.9, 0.6, 0.3}}));
    d.lights = {{{5, 5, 0}, {1.0, 0.9, 0.8}}, {{-3, 1, 2}, {0.3, 0.3, 0.5}}};
    d.background = {0.1, 0.2, 0.3};
    return d;
}

RenderOptions options(int size, int rpp, SamplerKind sampler) {
    RenderOptions o;
    o.width = size;
    o.height = size;
    o.samplesPerPixel = rpp;
    o.sampler = sampler;
    return o;
}

TEST(ClosedForm, LambertianSphereCentreRays) {
    // Regular sampling with one sample: the centre ray of each pixel.
    expectAgreement(lambertianSphere(), perspectiveCamera({0, 0, 0}, {0, 0, -1}, 1.0f, 0.5f),
                    options(64, 1, SamplerKind::Regular), "Lambertian sphere, centre rays", 2500);
}

TEST(ClosedForm, LambertianSphereJittered16) {
    expectAgreement(lambertianSphere(), perspectiveCamera({0, 0, 0}, {0, 0, -1}, 1.0f, 0.5f),
                    options(48, 16, SamplerKind::Jittered), "Lambertian sphere, 16 jittered", 1400);
}

TEST(ClosedForm, LambertianSphereNonSquareImage) {
    // 64x40: the image plane height is W * ny / nx; a wrong aspect would move the sphere's rim.
    RenderOptions o = options(64, 1, SamplerKind::Regular);
    o.height = 40;
    expectAgreement(lambertianSphere(), perspectiveCamera({0, 0.3f, 0}, {0.1f, -0.05f, -1}, 1.0f, 0.5f), o,
                    "Lambertian sphere, 64x40", 1500);
}

TEST(ClosedForm, OrthographicSphere) {
    expectAgreement(lambertianSphere(), orthographicCamera({0.2f, 0.1f, 3}, {0, 0, -1}, 2.5f),
                    options(48, 4, SamplerKind::Jittered), "Lambertian sphere, orthographic", 900);
}

TEST(ClosedForm, CameraLookingStraightDown) {
    // |gaze.y| > 0.9999 switches the up vector to (1,0,0) (RENDERING.md §1): the independent double
    // camera (analytic_scene.cpp) and the renderer must agree on it, or the off-centre sphere moves.
    DirectScene d = lambertianSphere();
    d.prims[0].a = {0.3, -5, 0.2};
    expectAgreement(d, perspectiveCamera({0, 0, 0}, {0, -1, 0}, 1.0f, 0.5f), options(40, 1, SamplerKind::Regular),
                    "sphere below a downward camera", 700);
}

TEST(ClosedForm, InstancedEllipsoidBlinnPhong) {
    // A unit-sphere prototype placed by translate * rotate * rotate * scale: normals go through
    // M^-T, and a Blinn-Phong highlight (exponent 20) is sensitive to any error in them.
    DirectScene d;
    DPrim e;
    e.kind = DPrim::Ellipsoid;
    e.toWorld = glm::translate(glm::dmat4(1.0), glm::dvec3(0.3, -0.2, -6.0)) *
                glm::rotate(glm::dmat4(1.0), glm::radians(30.0), glm::dvec3(0, 0, 1)) *
                glm::rotate(glm::dmat4(1.0), glm::radians(40.0), glm::dvec3(1, 0, 0)) *
                glm::scale(glm::dmat4(1.0), glm::dvec3(1.5, 0.7, 1.0));
    e.material = {{0.2, 0.5, 0.8}, {0.6, 0.6, 0.6}, 20.0};
    d.prims.push_back(e);
    d.lights = {{{4, 6, 1}, {1.0, 1.0, 1.0}}, {{-5, -2, 0}, {0.4, 0.2, 0.1}}};
    d.background = {0.05, 0.05, 0.05};
    expectAgreement(d, perspectiveCamera({0, 0, 0}, {0, 0, -1}, 1.0f, 0.6f), options(56, 4, SamplerKind::Jittered),
                    "instanced ellipsoid, Blinn-Phong", 900);
}

TEST(ClosedForm, BoxTriangleSphereWithShadows) {
    // A ground box, a box (three faces visible), a triangle and a sphere under two lights: box face
    // normals, triangle normals (either winding: two-sided), Blinn-Phong and hard shadows.
    DirectScene d;
    DPrim ground;
    ground.kind = DPrim::Box;
    ground.a = {-20, -2, -30};
    ground.b = {20, -1, 10};
    ground.material = {{0.6, 0.6, 0.6}};
    DPrim cube;
    cube.kind = DPrim::Box;
    cube.a = {-1.6, -1, -6.5};
    cube.b = {-0.4, 0.2, -5.3};
    cube.material = {{0.8, 0.3, 0.2}, {0.5, 0.5, 0.5}, 8.0};
    DPrim tri;
    tri.kind = DPrim::Triangle;
    tri.a = {0.4, -1, -6};
    tri.b = {2.0, -0.8, -5.5};  // wound so that the camera sees its back side
    tri.c = {1.0, 0.8, -6.5};
    tri.material = {{0.2, 0.7, 0.3}};
    d.prims = {ground, cube, tri, sphereAt({0.2, -0.5, -4.0}, 0.5, {{0.3, 0.3, 0.9}, {1, 1, 1}, 32.0})};
    d.lights = {{{-4, 6, -2}, {0.9, 0.9, 0.9}}, {{5, 3, -1}, {0.4, 0.3, 0.2}}};
    d.background = {0.2, 0.2, 0.2};
    expectAgreement(d, perspectiveCamera({0, 1.5f, 0}, {0, -0.35f, -1}, 1.0f, 0.8f),
                    options(64, 4, SamplerKind::Jittered), "boxes, triangle, sphere, shadows", 2500);
}

}  // namespace
}  // namespace vkrt::test
