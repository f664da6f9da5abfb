// Glossy translucency (issue 21): `roughness` on a Dielectric perturbs the refracted direction as
// gloss perturbs the reflected one (RENDERING.md §6), on both devices:
//   - the mean of many perturbed refraction directions is the refracted direction;
//   - roughness 0 is today's Dielectric: the general kernel (translucency code compiled in)
//     renders it bit for bit as the specialised kernel (none) does;
//   - a rough slab blurs the edge seen through it, more with more roughness, and a tiny roughness
//     approaches the smooth image;
//   - the two devices agree by the project's rule.
#include <cmath>

#include <gtest/gtest.h>

#include "both_paths.h"
#include "dielectric.h"
#include "gpu_environment.h"
#include "sampling.h"
#include "scene_building.h"
#include "shading.h"

namespace vkrt::stability {
namespace {

TEST(Translucency, TheMeanPerturbedRefractionIsTheRefractedDirection) {
    const glm::vec3 d = glm::normalize(glm::vec3(0.4f, -1.0f, 0.2f));
    const glm::vec3 n(0.0f, 1.0f, 0.0f);
    const glm::vec3 t = cpu::refractDirection(d, n, 1.0f, 1.5f);
    const glm::uvec4 grid = sampling::makeSampleGrid(4096);
    for (const float a : {0.05f, 0.3f, 1.0f}) {
        glm::dvec3 mean(0.0);
        for (std::uint32_t s = 0; s < 4096; ++s)
            mean += glm::dvec3(cpu::glossyDirection(t, a, sampling::sample2D(gpu::SAMPLER_JITTERED, grid, 5, s, sampling::dimTranslucency(0), 1)));
        // 4096 jittered samples of a symmetric square: the mean's direction is t within ~1e-3 rad
        // (the jitter's noise, ~a / 4096^0.75 per axis), far below the spread a.
        const double angle = std::acos(std::min(1.0, glm::dot(glm::normalize(mean), glm::dvec3(t))));
        EXPECT_LT(angle, 2e-3) << "roughness " << a;
    }
}

// A glass slab in front of a black-and-white vertical edge, seen orthographically along -z.
Scene slabBeforeEdge(float roughness) {
    Scene scene;
    scene.path = "a rough glass slab before an edge (built in code)";
    scene.background = glm::vec3(0.0f);
    scene.cameras.push_back(orthographic({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, 2.0f));
    // Between the slab and the wall: a shadow ray through the glass would be blocked.
    scene.lights.push_back(pointLight({0.0f, 0.0f, -1.0f}, glm::vec3(1.0f)));
    const int white = add(scene, lambertian(glm::vec3(1.0f)));
    const int black = add(scene, lambertian(glm::vec3(0.0f)));
    scene.shapes.push_back(box({-3.0f, -3.0f, -2.1f}, {0.0f, 3.0f, -2.0f}, white));
    scene.shapes.push_back(box({0.0f, -3.0f, -2.1f}, {3.0f, 3.0f, -2.0f}, black));
    Shader glass = dielectric(1.5f);
    glass.roughness = roughness;
    scene.shapes.push_back(box({-3.0f, -3.0f, 0.0f}, {3.0f, 3.0f, 0.2f}, add(scene, glass)));
    return scene;
}

// Columns of the middle row whose brightness is strictly between 5% and 95%: the edge's width.
int edgeWidth(const Image& image) {
    int width = 0;
    for (int x = 0; x < image.width; ++x) {
        const float g = image.at(x, image.height / 2).g;
        const float white = image.at(2, image.height / 2).g;
        width += g > 0.05f * white && g < 0.95f * white;
    }
    return width;
}

TEST(Translucency, RoughnessZeroIsTheDielectricBitForBit) {
    expectGeneralKernelRendersItBitForBit(slabBeforeEdge(0.0f), smallOptions(32, 8, 4), "translucency");
}

TEST(Translucency, ARoughSlabBlursTheEdgeBehindItMoreWithMoreRoughness) {
    const RenderOptions options = smallOptions(64, 8, 64);
    const BothImages smooth = renderBoth(slabBeforeEdge(0.0f), options);
    const BothImages tiny = renderBoth(slabBeforeEdge(1e-4f), options);
    const BothImages rough = renderBoth(slabBeforeEdge(0.1f), options);
    const BothImages rougher = renderBoth(slabBeforeEdge(0.4f), options);
    // Through a smooth slab at normal incidence the edge stays within one pixel column.
    EXPECT_LE(edgeWidth(smooth.cpu), 1);
    EXPECT_LE(edgeWidth(smooth.gpu), 1);
    // Roughness 1e-4 moves a ray by ~1e-4 * 2.1 units behind the slab: ~0.007 of a pixel.
    EXPECT_TRUE(agrees(distance(tiny.cpu, smooth.cpu))) << distance(tiny.cpu, smooth.cpu).describe();
    EXPECT_TRUE(agrees(distance(tiny.gpu, smooth.gpu))) << distance(tiny.gpu, smooth.gpu).describe();
    const int w1 = edgeWidth(rough.cpu), w2 = edgeWidth(rougher.cpu);
    recordNote("translucency edge width (64 px over 2 units)",
               "roughness 0: " + std::to_string(edgeWidth(smooth.cpu)) + " px, 0.1: " + std::to_string(w1) + " px, 0.4: " + std::to_string(w2) + " px");
    EXPECT_GE(w1, 2);
    EXPECT_GT(w2, w1);
    const Distance d = distance(rougher.gpu, rougher.cpu);
    recordRow("translucency roughness 0.4: GPU vs CPU", d);
    EXPECT_TRUE(agrees(d)) << d.describe();
    EXPECT_NE(rougher.gpuStats.features.find("translucency"), std::string::npos) << rougher.gpuStats.features;
}

}  // namespace
}  // namespace vkrt::stability
