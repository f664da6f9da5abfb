// A dielectric slab between an orthographic camera and a lit wall, seen at normal incidence.
// eta = 1: no reflection, no bending, so the wall appears multiplied by Beer's law a^T exactly.
// eta = 1.5: the exact Fresnel factor F = ((eta-1)/(eta+1))^2 at each face, with the internal
// reflections the depth limit and the 1/1024 branch cut (RENDERING.md §5-§6) allow, summed here
// term by term along the one line the light travels on.
#include <cmath>
#include <cstdio>
#include <functional>

#include <gtest/gtest.h>

#include "analytic_scene.h"

namespace vkrt::test {
namespace {

constexpr double kFront = -1.0, kBack = -3.0;  // slab faces (z); thickness 2
constexpr double kWallZ = -10.0;
const glm::dvec3 kLight{0.0, 0.0, -5.0};  // between slab and wall: the wall's shadow rays avoid the slab
const glm::dvec3 kWallKd{0.8, 0.7, 0.6};
const glm::dvec3 kBackground{0.2, 0.3, 0.4};

Scene slabScene(float eta, glm::vec3 attenuation) {
    Scene scene;
    scene.cameras.push_back(orthographicCamera({0, 0, 10}, {0, 0, -1}, 2.0f));
    scene.background = glm::vec3(kBackground);
    scene.lights.push_back(pointLight(glm::vec3(kLight), {1, 1, 1}));
    Shader glass = makeShader(ShaderType::Dielectric);
    glass.refractiveIndex = eta;
    glass.attenuation = attenuation;
    const int g = addShader(scene, glass);
    const int wall = addShader(scene, makeShader(ShaderType::Lambertian, glm::vec3(kWallKd)));
    scene.shapes.push_back(box({-20, -20, float(kBack)}, {20, 20, float(kFront)}, g));
    scene.shapes.push_back(box({-40, -40, -30}, {40, 40, float(kWallZ)}, wall));
    return scene;
}

glm::dvec3 wallAt(double x, double y) {
    const glm::dvec3 p(x, y, kWallZ);
    return kWallKd * std::max(0.0, glm::dot(glm::dvec3(0, 0, 1), glm::normalize(kLight - p)));
}

double maxComponent(glm::dvec3 v) { return std::max(v.x, std::max(v.y, v.z)); }

// The radiance of a ray travelling along the z axis at (x, y), at a slab face of the given depth.
// Inside the slab the ray alternates between the faces; every face it reaches is a "leaving" hit
// (Beer over the thickness), the first face is the only "entering" one.
struct SlabModel {
    double eta;
    glm::dvec3 a;  // per-unit transmittance
    int maxDepth;

    double fresnel() const { return eta == 1.0 ? 0.0 : std::pow((eta - 1.0) / (eta + 1.0), 2.0); }

    // A ray inside the slab reaching a face at `depth`, going towards the wall (down) or the camera.
    glm::dvec3 inside(double x, double y, int depth, bool down, glm::dvec3 weight) const {
        const double f = fresnel();
        const glm::dvec3 beer = glm::pow(a, glm::dvec3(kFront - kBack));
        const glm::dvec3 here = weight * beer;
        glm::dvec3 reflected(0.0), transmitted(0.0);
        if (depth < maxDepth) {
            if (maxComponent(here * f) >= 1.0 / 1024.0) reflected = inside(x, y, depth + 1, !down, here * f);
            if (maxComponent(here * (1.0 - f)) >= 1.0 / 1024.0)
                transmitted = down ? wallAt(x, y) : kBackground;  // the wall is shaded at depth + 1
        }
        return beer * (f * reflected + (1.0 - f) * transmitted);
    }

    Seen operator()(const DRay& ray) const {
        const double f = fresnel();
        const double x = ray.origin.x, y = ray.origin.y;
        glm::dvec3 reflected(0.0), refracted(0.0);
        if (maxDepth > 0) {
            if (f >= 1.0 / 1024.0) reflected = kBackground;  // straight back to the camera side: escapes
            refracted = inside(x, y, 1, true, glm::dvec3(1.0 - f));
        }
        return {0, f * reflected + (1.0 - f) * refracted};
    }
};

void expectSlab(float eta, glm::vec3 attenuation, int maxDepth, const char* name) {
    const Scene scene = slabScene(eta, attenuation);
    RenderOptions o;
    o.width = 24;
    o.height = 24;
    o.samplesPerPixel = 4;
    o.maxDepth = maxDepth;
    RenderStats stats;
    const Image image = renderChecked(scene, o, &stats);
    const SlabModel model{eta, glm::dvec3(attenuation), maxDepth};
    const Agreement a = compareWithClosedForm(image, makeDCamera(scene.cameras[0], o.width, o.height), model, o);
    std::printf("[dielectric] %-44s max error %.2e (centre pixel %.4f %.4f %.4f, %llu refraction rays)\n", name,
                a.maxError, image.at(12, 12).x, image.at(12, 12).y, image.at(12, 12).z,
                static_cast<unsigned long long>(stats.refractionRays));
    EXPECT_EQ(a.compared, o.width * o.height);
    // 1e-4: float geometry as elsewhere, plus a^t evaluated at the float hit distance t = 2 +- 1e-6.
    EXPECT_LE(a.maxError, 1e-4) << a.worst;
}

TEST(DielectricSlab, IndexOneIsBeerLambertOnly) {
    expectSlab(1.0f, {0.9f, 0.5f, 0.25f}, 4, "eta 1: wall * a^2 (Beer-Lambert)");
}

TEST(DielectricSlab, BeerLambertIsPerUnitTransmittance) {
    // Cross-check of the model itself against numbers written out: a = 0.5 over 2 units is 0.25.
    const SlabModel model{1.0, {0.5, 0.5, 0.5}, 4};
    const Seen seen = model({{0, 0, 10}, {0, 0, -1}});
    EXPECT_NEAR(seen.radiance.x, 0.25 * wallAt(0, 0).x, 1e-12);
}

TEST(DielectricSlab, FresnelAtNormalIncidence) {
    expectSlab(1.5f, {0.9f, 0.8f, 0.7f}, 4, "eta 1.5: F = 0.04 at both faces, max-depth 4");
}

TEST(DielectricSlab, DepthLimitCutsTheInternalReflections) {
    expectSlab(1.5f, {0.95f, 0.95f, 0.95f}, 2, "eta 1.5, max-depth 2");
}

}  // namespace
}  // namespace vkrt::test
