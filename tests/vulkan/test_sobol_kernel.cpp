// The Sobol sampler on the device against the host (sampling.h is compiled for both): the GPU
// reverses bits with bitfieldReverse, the host with a ladder of swaps, and both hash and convert
// with their own integer and float instructions. The renderers' noise is only the same on both
// devices (and the images of one seed comparable pixel by pixel) if every sample is the same.
#include <cstdint>

#include <gtest/gtest.h>

#include "frame_params.h"
#include "sampling.h"
#include "vulkan_test_support.h"

namespace vkrt {
namespace {

using test::TinyScene;
using test::VulkanTest;

// Bug targeted: a device bit reversal (or hash) that differs from the host's in any bit of any
// sample: the 24-bit samples then differ by at least 2^-24 and the sums below are not equal.
// One sample per pixel, so a pixel is the kernel's sum of two floats per channel (Vulkan rounds
// float additions correctly) and equality is exact; the kernel's point number 37 * pixel + 0
// runs through 777 of them, up to 28,712 (15 bits).
TEST_F(VulkanTest, SobolSamplesAreTheHostsBitForBit) {
    TinyScene tiny;
    RenderOptions options = test::smallRender(37, 21, 1);
    options.sampler = SamplerKind::Sobol;
    options.seed = 12345;
    GpuRenderer& gpu = renderer({}, {.kernelSpirv = test::testKernel("sobol_samples")});
    const Image device = gpu.render(tiny.gpu(), options);

    const gpu::FrameParams f = makeFrameParams(tiny.scene, tiny.accel, options);
    ASSERT_EQ(f.scene.x, 12345u);  // the kernel reads the seed from there
    Image host(options.width, options.height);
    for (int y = 0; y < options.height; ++y)
        for (int x = 0; x < options.width; ++x) {
            const auto pixel = static_cast<std::uint32_t>(y * options.width + x);
            const std::uint32_t index = 37u * pixel;
            const glm::vec2 camera = sampling::sobolSample2D(pixel, index, sampling::DIM_CAMERA, f.scene.x);
            const glm::vec2 bounce = sampling::sobolSample2D(pixel, index, sampling::dimBounce(2), f.scene.x);
            const glm::vec2 light = sampling::sobolSample2D(pixel, index, sampling::dimLight(1, 3), f.scene.x);
            host.at(x, y) = glm::vec3(camera.x + bounce.y, camera.y + light.x, bounce.x + light.y);
        }
    EXPECT_EQ(device.pixels, host.pixels);
}

}  // namespace
}  // namespace vkrt
