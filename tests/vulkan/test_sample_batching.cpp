// On the device, the render kernel's image does not depend on the samples per dispatch, bit for
// bit, and a failure in a batch names its sample (sample_batching.h; the bound is tests/gpu).
#include <string>

#include <gtest/gtest.h>

#include "sample_batching.h"
#include "vulkan_errors.h"
#include "vulkan_test_support.h"

namespace vkrt {
namespace {

using test::TinyScene;
using test::VulkanTest;

// render.comp on the tiny scene with an area light (camera, light and shuffle samples all drawn):
// the same image bit for bit whatever the samples per dispatch, including a last pass of fewer.
TEST_F(VulkanTest, SamplesPerDispatchDoNotChangeTheImage) {
    TinyScene tiny;
    tiny.scene.lights[0].type = LightType::Area;
    tiny.scene.lights[0].width = tiny.scene.lights[0].length = 1.0f;
    RenderOptions options = test::smallRender(21, 19, 10);
    options.lightSamples = 2;
    GpuRenderer& gpu = renderer();
    GpuRenderStats stats;
    GpuRenderSettings one;
    one.samplesPerDispatch = 1;
    const Image reference = gpu.render(tiny.gpu(), options, &stats, one);
    EXPECT_EQ(stats.samplesPerDispatch, 1u);
    EXPECT_EQ(stats.dispatches, 10u);
    for (std::uint32_t k : {3u, 4u, 8u}) {
        GpuRenderSettings batched;
        batched.samplesPerDispatch = k;
        const Image image = gpu.render(tiny.gpu(), options, &stats, batched);
        EXPECT_EQ(stats.samplesPerDispatch, k);
        EXPECT_EQ(stats.dispatches, (10 + k - 1) / k);
        test::expectSameGpuImage(gpu, image, reference, "k = " + std::to_string(k));
    }
    // Left to the bound, this cheap scene takes the largest k (10 samples: 8 + 2).
    const Image automatic = gpu.render(tiny.gpu(), options, &stats);
    EXPECT_EQ(stats.samplesPerDispatch, kMaxSamplesPerDispatch);
    test::expectSameGpuImage(gpu, automatic, reference, "k chosen by the bound");
}

// A failure inside a pass of several samples names the sample it happened at (status_probe.comp
// fails pixel (5, 3) at sample 1, the second sample of a 3-sample pass).
TEST_F(VulkanTest, AFailureInABatchNamesItsSample) {
    TinyScene tiny;
    GpuRenderer& gpu = renderer({}, {.kernelSpirv = test::testKernel("status_probe")});
    GpuRenderSettings batched;
    batched.samplesPerDispatch = 3;
    try {
        gpu.render(tiny.gpu(), test::smallRender(16, 16, 3), nullptr, batched);
        FAIL() << "the kernel's failure was ignored";
    } catch (const GpuKernelError& e) {
        EXPECT_NE(std::string(e.what()).find("pixel (5, 3), sample 1"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace vkrt
