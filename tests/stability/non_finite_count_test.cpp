// Non-finite samples are counted alike on both devices (issue 22). Each path replaces a NaN or Inf
// sample by black and counts it (RENDERING.md §8; the CPU in cpu_renderer.cpp, the GPU in
// render.comp's addSample, read back as GpuRenderStats::nonFiniteSamples), and `vkrt` prints the
// same warning for either. The values here are valid and finite: a diffuse colour and a light of
// 3e38 each, whose product (9e76) overflows float to +Inf on any IEEE device. The expected count
// is known independently: every sample that sees the lit wall, and only those.
#include <cfloat>

#include <gtest/gtest.h>

#include "both_paths.h"
#include "cpu_renderer.h"
#include "gpu_environment.h"
#include "image_compare.h"
#include "scene_building.h"

namespace vkrt::stability {
namespace {

constexpr float kHuge = 3e38f;  // finite; kHuge * kHuge is not

// An orthographic view straight at a Lambertian wall lit from the camera's side; the wall's right
// edge at x = `wallRightEdge` in the 2-unit-wide view (3 fills the image).
Scene overflowingWall(float wallRightEdge) {
    Scene scene;
    scene.path = "overflowing wall (built in code)";
    scene.background = glm::vec3(0.2f, 0.3f, 0.4f);
    scene.cameras.push_back(orthographic({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, 2.0f));
    scene.lights.push_back(pointLight({0.0f, 0.0f, 10.0f}, glm::vec3(kHuge, 1.0f, 1.0f)));
    const int wall = add(scene, lambertian({kHuge, 0.5f, 0.5f}));
    scene.shapes.push_back(box({-3.0f, -3.0f, -1.0f}, {wallRightEdge, 3.0f, 0.0f}, wall));
    return scene;
}

struct Counted {
    Image cpu, gpu;
    std::uint64_t cpuCount = 0, gpuCount = 0;
};

Counted renderCounting(const Scene& scene, const RenderOptions& options) {
    Counted out;
    RenderStats cpuStats;
    GpuRenderStats gpuStats;
    out.cpu = renderCpu(scene, prepareCpuScene(scene), options, &cpuStats);
    out.gpu = sharedGpu().render(GpuRenderer::prepare(scene), options, &gpuStats);
    out.cpuCount = cpuStats.nonFiniteSamples;
    out.gpuCount = gpuStats.nonFiniteSamples;
    return out;
}

TEST(NonFiniteSamples, AWallThatOverflowsIsCountedSampleBySampleOnBothDevices) {
    const RenderOptions options = smallOptions(16, 12, 4);
    const Counted c = renderCounting(overflowingWall(3.0f), options);
    const std::uint64_t all = 16u * 12u * 4u;  // the wall fills the view: every sample overflows
    EXPECT_EQ(c.cpuCount, all);
    EXPECT_EQ(c.gpuCount, all);
    // Replaced by black on both: the image is black, not Inf and not the background.
    for (const Image* image : {&c.cpu, &c.gpu})
        for (const glm::vec3& p : image->pixels) ASSERT_EQ(p, glm::vec3(0.0f));
}

// Each sample finite, their sum not: a wall of diffuse 0.5 under a light of 2e38 gives samples of
// 1e38, and four of them sum past FLT_MAX (3.4e38) to +Inf. Both devices clamp such a pixel to
// FLT_MAX (float_range.h: the true mean is at most that) and count it, so vkrt warns; no sample is
// counted as non-finite (issue 37: the pixel was Inf, silently).
TEST(NonFiniteSamples, FiniteSamplesSummingPastFloatAreClampedAndCountedOnBothDevices) {
    Scene scene = overflowingWall(3.0f);
    scene.lights[0].intensity = glm::vec3(2e38f, 1.0f, 1.0f);
    scene.shaders[0].diffuse = glm::vec3(0.5f);
    const RenderOptions options = smallOptions(16, 12, 4);
    RenderStats cpuStats;
    GpuRenderStats gpuStats;
    const Image cpu = renderCpu(scene, prepareCpuScene(scene), options, &cpuStats);
    const Image gpu = sharedGpu().render(GpuRenderer::prepare(scene), options, &gpuStats);
    EXPECT_EQ(cpuStats.nonFiniteSamples, 0u);
    EXPECT_EQ(gpuStats.nonFiniteSamples, 0u);
    EXPECT_EQ(cpuStats.overflowedPixels, 16u * 12u);
    EXPECT_EQ(gpuStats.overflowedPixels, 16u * 12u);
    for (const Image* image : {&cpu, &gpu})
        for (const glm::vec3& p : image->pixels) {
            ASSERT_EQ(p.x, FLT_MAX);
            // The light's other channels: 0.5 x 1 x N.L (0.99 or more here), untouched by the clamp.
            ASSERT_TRUE(p.y > 0.49f && p.y <= 0.5f) << p.y;
        }
}

TEST(NonFiniteSamples, HalfAWallGivesTheSameCountAndImageOnBothDevices) {
    // The wall ends at x = 0.1 (not on a pixel edge: 16 pixels over 2 units are 0.125 wide), so
    // about 55% of the samples overflow; the rest see the background.
    const RenderOptions options = smallOptions(16, 12, 16);
    const Counted c = renderCounting(overflowingWall(0.1f), options);
    const std::uint64_t all = 16u * 12u * 16u;
    EXPECT_GT(c.cpuCount, all / 2);
    EXPECT_LT(c.cpuCount, all * 6 / 10);
    EXPECT_EQ(c.gpuCount, c.cpuCount);
    const Distance d = distance(c.gpu, c.cpu);
    recordRow("non-finite samples counted (wall half overflowing)", d);
    EXPECT_EQ(d.maxSteps, 0) << d.describe();
}

}  // namespace
}  // namespace vkrt::stability
