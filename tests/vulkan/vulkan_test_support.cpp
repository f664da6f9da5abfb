#include "vulkan_test_support.h"

#include "image_compare.h"

#include <stdexcept>

namespace vkrt::test {

std::vector<std::uint32_t> testKernel(std::string_view name) {
    for (const EmbeddedSpirv& k : testKernels())
        if (k.name == name) return {k.words.begin(), k.words.end()};
    throw std::runtime_error("no test kernel " + std::string(name));
}

Context& VulkanTest::context(const ContextOptions& options) {
    ContextOptions validated = options;
    validated.validation = true;
    context_ = std::make_unique<Context>(validated);
    logs_.push_back(context_->validationLog());
    return *context_;
}

GpuRenderer& VulkanTest::renderer(GpuRendererOptions options, const GpuTestHooks& hooks) {
    options.validation = true;
    renderer_ = std::make_unique<GpuRenderer>(options, hooks);
    logs_.push_back(renderer_->validationLog());
    return *renderer_;
}

GpuRayTracer& VulkanTest::rayTracer(const bvh::SceneBvh& scene, const GpuTestHooks& hooks) {
    GpuRendererOptions options;
    options.validation = true;
    rayTracer_ = std::make_unique<GpuRayTracer>(scene, options, hooks);
    watch(rayTracer_->validationLog());
    return *rayTracer_;
}

void VulkanTest::TearDown() {
    rayTracer_.reset();
    renderer_.reset();
    context_.reset();
    for (const auto& log : logs_) {
        ASSERT_NE(log, nullptr);
        EXPECT_EQ(log->count(), 0u) << "validation messages:\n" << log->joined();
    }
}

void expectSameGpuImage(const GpuRenderer& gpu, const Image& a, const Image& b, const std::string& what) {
    ASSERT_EQ(a.pixels.size(), b.pixels.size()) << what;
    if (gpu.deviceInfo().lavapipe) {
        EXPECT_EQ(a.pixels, b.pixels) << what;
        return;
    }
    const ImageDifference d = compareImages(a, b);
    EXPECT_LE(d.fractionOver2, 0.005) << what << " on " << gpu.deviceName();
    EXPECT_LE(d.meanAbs, 0.5 / 255.0) << what << " on " << gpu.deviceName();
}

}  // namespace vkrt::test
