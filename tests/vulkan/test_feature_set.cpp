// The specialization constants reaching the kernel: spec_probe.comp writes back the values it was
// compiled with, and pipelines are cached per variant.
#include <gtest/gtest.h>

#include "feature_set.h"
#include "vulkan_test_support.h"

namespace vkrt {
namespace {

using test::TinyScene;
using test::VulkanTest;

// spec_probe.comp writes (feature bit mask, MAX_DEPTH, PATH_STACK_SIZE) into every pixel.
glm::vec3 probe(GpuRenderer& gpu, const TinyScene& tiny, const RenderOptions& options, KernelVariant variant,
                GpuRenderStats* stats) {
    const Image image = gpu.render(tiny.gpu(), options, stats, {.variant = variant});
    for (const glm::vec3& p : image.pixels) EXPECT_EQ(p, image.pixels[0]);
    return image.pixels[0];
}

float expectedMask(const FeatureSet& f) {
    const auto values = f.specializationValues();
    std::uint32_t mask = 0;
    for (std::uint32_t id = 0; id <= gpu::SPEC_HAS_COOL_TO_WARM; ++id) mask |= values[id] << id;
    const std::uint32_t sampler = values[gpu::SPEC_SAMPLER];
    mask |= (sampler == gpu::SAMPLER_FROM_FRAME ? 0u : sampler + 1u) << 11u;  // spec_probe.comp
    return static_cast<float>(mask);
}

TEST_F(VulkanTest, SpecializationConstantsReachTheKernelAndPipelinesAreCached) {
    GpuRenderer& gpu = renderer({}, {.kernelSpirv = test::testKernel("spec_probe")});
    TinyScene plain;
    TinyScene shiny;
    shiny.scene.shaders[0].type = ShaderType::Glaze;
    shiny.scene.shaders[0].roughness = 0.5f;
    shiny.scene.lights[0].type = LightType::Area;
    RenderOptions options = test::smallRender(16, 8, 1);
    options.maxDepth = 3;
    options.glossSamples = 2;
    options.sampler = SamplerKind::Sobol;

    GpuRenderStats stats;
    const FeatureSet plainFeatures = deriveFeatureSet(plain.scene, plain.accel, options, plain.gpu().nodes.packed);
    const glm::vec3 a = probe(gpu, plain, options, KernelVariant::Specialised, &stats);
    EXPECT_EQ(a, glm::vec3(expectedMask(plainFeatures), 0.0f, 0.0f));
    EXPECT_EQ(static_cast<std::uint32_t>(a.x) >> 11u, gpu::SAMPLER_SOBOL + 1u);  // the sampler reached it too
    EXPECT_GT(stats.pipelineSeconds, 0.0);
    std::cout << "pipeline creation (spec_probe): " << stats.pipelineSeconds << " s\n";

    const FeatureSet shinyFeatures = deriveFeatureSet(shiny.scene, shiny.accel, options, shiny.gpu().nodes.packed);
    ASSERT_NE(shinyFeatures, plainFeatures);
    const glm::vec3 b = probe(gpu, shiny, options, KernelVariant::Specialised, &stats);
    EXPECT_EQ(b, glm::vec3(expectedMask(shinyFeatures), 3.0f, 5.0f));
    EXPECT_EQ(gpu.pipelineCount(), 2u);

    const glm::vec3 c = probe(gpu, plain, options, KernelVariant::General, &stats);
    EXPECT_EQ(c, glm::vec3(2047.0f, 3.0f, 5.0f));  // all eleven flags, the sampler read from the frame
    EXPECT_TRUE(stats.generalKernel);
    EXPECT_EQ(gpu.pipelineCount(), 3u);

    probe(gpu, plain, options, KernelVariant::Specialised, &stats);  // cached
    EXPECT_EQ(stats.pipelineSeconds, 0.0);
    EXPECT_EQ(gpu.pipelineCount(), 3u);
}

}  // namespace
}  // namespace vkrt
