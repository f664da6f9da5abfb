// The kernel's failure report (RenderStatus) becomes an error naming pixel, sample and remedy;
// and the real render kernel, driven by this host code, shades the tiny scene's sphere.
#include <cmath>

#include <gtest/gtest.h>

#include "render_status.h"
#include "vulkan_errors.h"
#include "vulkan_test_support.h"

namespace vkrt {
namespace {

using test::TinyScene;
using test::VulkanTest;

std::string failure(const gpu::RenderStatus& status, std::uint32_t width, bool loopLimiter = true) {
    try {
        throwIfKernelFailed(status, width, loopLimiter);
    } catch (const GpuKernelError& e) {
        return e.what();
    }
    return "";
}

TEST(RenderStatus, CleanStatusPasses) {
    EXPECT_NO_THROW(throwIfKernelFailed(gpu::RenderStatus{glm::uvec4(0u, 0u, 0u, 12u)}, 100, true));  // NaN count alone is no failure
}

TEST(RenderStatus, LoopBudgetNamesPixelSampleAndRemedy) {
    const std::string m = failure({glm::uvec4(gpu::STATUS_LOOP_BUDGET_EXCEEDED, 3u * 100u + 7u + 1u, 9u, 0u)}, 100);
    EXPECT_NE(m.find("pixel (7, 3)"), std::string::npos) << m;
    EXPECT_NE(m.find("sample 9"), std::string::npos) << m;
    EXPECT_NE(m.find(std::to_string(gpu::LOOP_BUDGET)), std::string::npos) << m;
    EXPECT_NE(m.find("--max-depth"), std::string::npos) << m;
}

TEST(RenderStatus, LoopCutOffNamesTheLimiterAndTheWayOut) {
    const std::string m = failure({glm::uvec4(gpu::STATUS_LOOP_CUT_OFF, 2u * 64u + 5u + 1u, 0u, 0u)}, 64);
    EXPECT_NE(m.find("pixel (5, 2), sample 0"), std::string::npos) << m;
    EXPECT_NE(m.find("cut off"), std::string::npos) << m;
    EXPECT_NE(m.find("65,535"), std::string::npos) << m;
    EXPECT_NE(m.find("--device cpu"), std::string::npos) << m;
    EXPECT_EQ(m.find("unknown status"), std::string::npos) << m;
}

// On a driver without lavapipe's limiter the same flags must not blame lavapipe.
TEST(RenderStatus, OtherDriversAreNotToldAboutLavapipe) {
    const std::string cut = failure({glm::uvec4(gpu::STATUS_LOOP_CUT_OFF, 2u * 64u + 5u + 1u, 0u, 0u)}, 64, false);
    EXPECT_NE(cut.find("pixel (5, 2), sample 0"), std::string::npos) << cut;
    EXPECT_NE(cut.find("not known to do"), std::string::npos) << cut;
    EXPECT_EQ(cut.find("this driver ends loops silently"), std::string::npos) << cut;
    const std::string budget = failure({glm::uvec4(gpu::STATUS_LOOP_BUDGET_EXCEEDED, 1u, 0u, 0u)}, 64, false);
    EXPECT_NE(budget.find(std::to_string(gpu::LOOP_BUDGET)), std::string::npos) << budget;
    EXPECT_NE(budget.find("instead of a hang"), std::string::npos) << budget;
    EXPECT_EQ(budget.find("lavapipe"), std::string::npos) << budget;
}

// The wavefront stages' self-check (wavefront.glsl): the message says what disagreed and the way round.
TEST(RenderStatus, ShadowRayMismatchNamesTheStagesAndTheMegakernel) {
    const std::string m = failure({glm::uvec4(gpu::STATUS_SHADOW_RAYS_MISMATCH, 4u * 10u + 2u + 1u, 3u, 0u)}, 10);
    EXPECT_NE(m.find("pixel (2, 4), sample 3"), std::string::npos) << m;
    EXPECT_NE(m.find("wavefront_shade_record.comp"), std::string::npos) << m;
    EXPECT_NE(m.find("--gpu-kernel megakernel"), std::string::npos) << m;
    EXPECT_EQ(m.find("unknown status"), std::string::npos) << m;
}

TEST(RenderStatus, StackOverflowWithoutARecordedPixel) {
    const std::string m = failure({glm::uvec4(gpu::STATUS_RAY_STACK_OVERFLOW, 0u, 0u, 0u)}, 100);
    EXPECT_NE(m.find("stack overflowed"), std::string::npos) << m;
    EXPECT_NE(m.find("did not record the pixel"), std::string::npos) << m;
    EXPECT_NE(failure({glm::uvec4(0x10u, 0u, 0u, 0u)}, 100).find("unknown status flags 0x10"), std::string::npos);
}

// status_probe.comp flags pixel (5, 3) at sample 1: the render must stop with that pixel named.
TEST_F(VulkanTest, KernelFailureStopsTheRenderWithPixelAndSample) {
    TinyScene tiny;
    GpuRenderer& gpu = renderer({}, {.kernelSpirv = test::testKernel("status_probe")});
    const RenderOptions options = test::smallRender(16, 16, 3);
    try {
        gpu.render(tiny.gpu(), options);
        FAIL() << "the kernel's failure was ignored";
    } catch (const GpuKernelError& e) {
        EXPECT_NE(std::string(e.what()).find("pixel (5, 3), sample 1"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("loop iterations"), std::string::npos) << e.what();
    }
    tiny.scene.shaders[0].roughness = 0.5f;  // HAS_GLOSS: the probe reports a stack overflow instead
    try {
        gpu.render(tiny.gpu(), options);
        FAIL() << "the kernel's failure was ignored";
    } catch (const GpuKernelError& e) {
        EXPECT_NE(std::string(e.what()).find("stack overflowed"), std::string::npos) << e.what();
    }
}

// The real kernel (shaders/render.comp) on the hand-built tiny scene: camera at z = 5 looking at
// a unit sphere lit by a point light at (2, 4, 3). The centre ray hits (0, 0, 1) with N = (0, 0, 1):
// Lambert = kd * I * N.L = 0.5 * 2/sqrt(24); a corner ray (plane half-width 0.25 at f = 1, i.e.
// 1.25 at the sphere) misses and returns the black background.
TEST_F(VulkanTest, RenderKernelShadesTheTinySphere) {
    TinyScene tiny;
    GpuRenderer& gpu = renderer();
    GpuRenderStats stats;
    const RenderOptions options = test::smallRender(33, 33, 4);  // odd: pixel 16 is centred
    const Image image = gpu.render(tiny.gpu(), options, &stats);
    std::cout << "render kernel: features '" << stats.features << "', pipeline " << stats.pipelineSeconds << " s, "
              << stats.submissions << " submissions\n";
    const float lambert = 0.5f * 2.0f / std::sqrt(24.0f);
    // Jittered samples spread over the centre pixel (1/33 of the plane): N.L varies by ~1% there.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.at(16, 16)[c], lambert, 0.01f);
    EXPECT_EQ(image.at(0, 0), glm::vec3(0.0f));
    EXPECT_EQ(image.at(32, 32), glm::vec3(0.0f));
    EXPECT_EQ(stats.nonFiniteSamples, 0u);
}

}  // namespace
}  // namespace vkrt
