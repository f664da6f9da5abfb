// The feature set a scene derives (what is used, not what is declared), and the specialization
// constants reaching the kernel: spec_probe.comp writes back the values it was compiled with.
#include <gtest/gtest.h>

#include "feature_set.h"
#include "vulkan_test_support.h"

namespace vkrt {
namespace {

using test::TinyScene;
using test::VulkanTest;

TEST(FeatureSet, TinySceneUsesOnlySpheresAndLambert) {
    TinyScene tiny;
    RenderOptions options = test::smallRender(8, 8, 1);
    options.glossSamples = 3;
    const FeatureSet f = deriveFeatureSet(tiny.scene, tiny.accel, options);
    EXPECT_FALSE(f.triangles);
    EXPECT_TRUE(f.spheres);
    EXPECT_FALSE(f.boxes);
    EXPECT_FALSE(f.instances);
    EXPECT_FALSE(f.areaLights);
    EXPECT_FALSE(f.specular || f.reflection || f.gloss || f.dielectric || f.textures || f.coolToWarm);
    EXPECT_EQ(f.maxDepth, 0u);  // nothing reflects: the kernel needs no secondary rays
    EXPECT_EQ(f.pathStackSize, 0u);  // nothing emits a second ray: no path stack, whatever glossSamples
    EXPECT_EQ(f.sampler, gpu::SAMPLER_JITTERED);  // the default sampler, compiled in
    EXPECT_EQ(f.describe(), "spheres sampler=jittered depth=0 stack=0");
}

TEST(FeatureSet, TheRendersSamplerIsCompiledIn) {
    TinyScene tiny;
    RenderOptions options = test::smallRender(8, 8, 1);
    for (SamplerKind kind : {SamplerKind::Jittered, SamplerKind::Regular, SamplerKind::Random, SamplerKind::Sobol}) {
        options.sampler = kind;
        const FeatureSet f = deriveFeatureSet(tiny.scene, tiny.accel, options);
        EXPECT_EQ(f.specializationValues()[gpu::SPEC_SAMPLER], static_cast<std::uint32_t>(kind));
    }
    options.sampler = SamplerKind::Sobol;
    EXPECT_EQ(deriveFeatureSet(tiny.scene, tiny.accel, options).describe(), "spheres sampler=sobol depth=0 stack=0");
    // The general kernel reads the sampler from the frame, whatever the options.
    EXPECT_EQ(generalFeatureSet(options).specializationValues()[gpu::SPEC_SAMPLER], gpu::SAMPLER_FROM_FRAME);
    // Two renders that differ only in the sampler need two pipelines.
    options.sampler = SamplerKind::Random;
    const FeatureSet random = deriveFeatureSet(tiny.scene, tiny.accel, options);
    options.sampler = SamplerKind::Regular;
    EXPECT_NE(random, deriveFeatureSet(tiny.scene, tiny.accel, options));
}

TEST(FeatureSet, UnusedShadersSwitchNothingOn) {
    TinyScene tiny;
    Shader glass;
    glass.type = ShaderType::Dielectric;
    glass.roughness = 0.3f;
    tiny.scene.shaders.push_back(glass);  // declared, never assigned to a shape
    const FeatureSet f = deriveFeatureSet(tiny.scene, tiny.accel, test::smallRender(8, 8, 1));
    EXPECT_FALSE(f.dielectric);
    EXPECT_FALSE(f.gloss);
    EXPECT_EQ(f.maxDepth, 0u);
}

TEST(FeatureSet, ShaderFeaturesFollowTheShapesShader) {
    struct Case {
        ShaderType type;
        bool FeatureSet::*flag;
    };
    const Case cases[] = {{ShaderType::BlinnPhong, &FeatureSet::specular},        {ShaderType::Mirror, &FeatureSet::reflection},
                          {ShaderType::Glaze, &FeatureSet::reflection},           {ShaderType::BlinnPhongMirrored, &FeatureSet::reflection},
                          {ShaderType::BlinnPhongMirrored, &FeatureSet::specular}, {ShaderType::Dielectric, &FeatureSet::dielectric},
                          {ShaderType::CoolToWarm, &FeatureSet::coolToWarm}};
    for (const Case& c : cases) {
        TinyScene tiny;
        tiny.scene.shaders[0].type = c.type;
        RenderOptions options = test::smallRender(8, 8, 1);
        options.maxDepth = 6;
        const FeatureSet f = deriveFeatureSet(tiny.scene, tiny.accel, options);
        EXPECT_TRUE(f.*c.flag) << static_cast<int>(c.type);
        const bool secondary = c.type == ShaderType::Mirror || c.type == ShaderType::Glaze ||
                               c.type == ShaderType::BlinnPhongMirrored || c.type == ShaderType::Dielectric;
        EXPECT_EQ(f.maxDepth, secondary ? 6u : 0u) << static_cast<int>(c.type);
        // Only a dielectric emits two rays at one hit (gloss fan-out needs glossSamples > 1).
        EXPECT_EQ(f.pathStackSize, c.type == ShaderType::Dielectric ? f.maxDepth + 1u : 0u) << static_cast<int>(c.type);
    }
}

TEST(FeatureSet, GlossFanOutNeedsThePathStack) {
    TinyScene tiny;
    tiny.scene.shaders[0].type = ShaderType::Mirror;
    tiny.scene.shaders[0].roughness = 0.2f;
    RenderOptions options = test::smallRender(8, 8, 1);
    options.maxDepth = 3;
    options.glossSamples = 1;  // one reflection per hit: it continues in place
    EXPECT_EQ(deriveFeatureSet(tiny.scene, tiny.accel, options).pathStackSize, 0u);
    options.glossSamples = 4;  // four at the primary hit: three wait on the stack
    EXPECT_EQ(deriveFeatureSet(tiny.scene, tiny.accel, options).pathStackSize, 3u + 4u);
    tiny.scene.shaders[0].roughness = 0.0f;  // a sharp mirror reflects once whatever glossSamples
    EXPECT_EQ(deriveFeatureSet(tiny.scene, tiny.accel, options).pathStackSize, 0u);
}

TEST(FeatureSet, GlossTexturesAreaLightsAndInstances) {
    TinyScene tiny;
    tiny.scene.shaders[0].roughness = 0.2f;
    tiny.scene.shaders[0].diffuseTexture = 0;
    tiny.scene.lights[0].type = LightType::Area;
    tiny.accel.bvh.instances[0].objectToWorld[0].w = 2.0f;  // one instance, but translated
    const FeatureSet f = deriveFeatureSet(tiny.scene, tiny.accel, test::smallRender(8, 8, 1));
    EXPECT_TRUE(f.gloss);
    EXPECT_TRUE(f.textures);
    EXPECT_TRUE(f.areaLights);
    EXPECT_TRUE(f.instances);

    TinyScene two;
    two.accel.bvh.instances.push_back(two.accel.bvh.instances[0]);  // two identity instances
    EXPECT_TRUE(deriveFeatureSet(two.scene, two.accel, test::smallRender(8, 8, 1)).instances);
}

TEST(FeatureSet, InstanceOverrideCounts) {
    TinyScene tiny;
    Shader mirror;
    mirror.type = ShaderType::Mirror;
    tiny.scene.shaders.push_back(mirror);
    tiny.scene.prototypes.push_back(tiny.scene.shapes[0]);  // shader 0 (Lambertian)
    Instance instance;
    instance.prototype = 0;
    instance.shaderOverride = 1;
    tiny.scene.instances.push_back(instance);
    EXPECT_TRUE(deriveFeatureSet(tiny.scene, tiny.accel, test::smallRender(8, 8, 1)).reflection);
}

TEST(FeatureSet, GeneralHasEverything) {
    RenderOptions options = test::smallRender(8, 8, 1);
    options.maxDepth = 5;
    options.glossSamples = 4;
    const FeatureSet g = generalFeatureSet(options);
    const auto values = g.specializationValues();
    for (std::uint32_t id = 0; id <= gpu::SPEC_HAS_COOL_TO_WARM; ++id) EXPECT_EQ(values[id], 1u) << id;
    EXPECT_EQ(values[gpu::SPEC_MAX_DEPTH], 5u);
    EXPECT_EQ(values[gpu::SPEC_PATH_STACK_SIZE], 9u);
}

// spec_probe.comp writes (feature bit mask, MAX_DEPTH, PATH_STACK_SIZE) into every pixel.
glm::vec3 probe(GpuRenderer& gpu, const Scene& scene, const SceneAccel& accel, const RenderOptions& options,
                KernelVariant variant, GpuRenderStats* stats) {
    const Image image = gpu.render(scene, accel, options, stats, {.variant = variant});
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
    GpuRenderer& gpu = renderer({.kernelSpirv = test::testKernel("spec_probe")});
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
    const FeatureSet plainFeatures = deriveFeatureSet(plain.scene, plain.accel, options);
    const glm::vec3 a = probe(gpu, plain.scene, plain.accel, options, KernelVariant::Specialised, &stats);
    EXPECT_EQ(a, glm::vec3(expectedMask(plainFeatures), 0.0f, 0.0f));
    EXPECT_EQ(static_cast<std::uint32_t>(a.x) >> 11u, gpu::SAMPLER_SOBOL + 1u);  // the sampler reached it too
    EXPECT_GT(stats.pipelineSeconds, 0.0);
    std::cout << "pipeline creation (spec_probe): " << stats.pipelineSeconds << " s\n";

    const FeatureSet shinyFeatures = deriveFeatureSet(shiny.scene, shiny.accel, options);
    ASSERT_NE(shinyFeatures, plainFeatures);
    const glm::vec3 b = probe(gpu, shiny.scene, shiny.accel, options, KernelVariant::Specialised, &stats);
    EXPECT_EQ(b, glm::vec3(expectedMask(shinyFeatures), 3.0f, 5.0f));
    EXPECT_EQ(gpu.pipelineCount(), 2u);

    const glm::vec3 c = probe(gpu, plain.scene, plain.accel, options, KernelVariant::General, &stats);
    EXPECT_EQ(c, glm::vec3(2047.0f, 3.0f, 5.0f));  // all eleven flags, the sampler read from the frame
    EXPECT_TRUE(stats.generalKernel);
    EXPECT_EQ(gpu.pipelineCount(), 3u);

    probe(gpu, plain.scene, plain.accel, options, KernelVariant::Specialised, &stats);  // cached
    EXPECT_EQ(stats.pipelineSeconds, 0.0);
    EXPECT_EQ(gpu.pipelineCount(), 3u);
}

}  // namespace
}  // namespace vkrt
