// The feature set a scene derives: what is used, not what is declared (no device needed; the
// specialization constants reaching the kernel are tests/vulkan/test_feature_set.cpp).
#include <gtest/gtest.h>

#include "feature_set.h"
#include "tiny_scene.h"

namespace vkrt {
namespace {

using test::TinyScene;

TEST(FeatureSet, TinySceneUsesOnlySpheresAndLambert) {
    TinyScene tiny;
    RenderOptions options = test::smallRender(8, 8, 1);
    options.glossSamples = 3;
    const FeatureSet f = deriveFeatureSet(tiny.scene, tiny.accel, options, true);
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
        const FeatureSet f = deriveFeatureSet(tiny.scene, tiny.accel, options, true);
        EXPECT_EQ(f.specializationValues()[gpu::SPEC_SAMPLER], static_cast<std::uint32_t>(kind));
    }
    options.sampler = SamplerKind::Sobol;
    EXPECT_EQ(deriveFeatureSet(tiny.scene, tiny.accel, options, true).describe(), "spheres sampler=sobol depth=0 stack=0");
    // The general kernel reads the sampler from the frame, whatever the options.
    EXPECT_EQ(generalFeatureSet(options, true).specializationValues()[gpu::SPEC_SAMPLER], gpu::SAMPLER_FROM_FRAME);
    // Two renders that differ only in the sampler need two pipelines.
    options.sampler = SamplerKind::Random;
    const FeatureSet random = deriveFeatureSet(tiny.scene, tiny.accel, options, true);
    options.sampler = SamplerKind::Regular;
    EXPECT_NE(random, deriveFeatureSet(tiny.scene, tiny.accel, options, true));
}

TEST(FeatureSet, UnusedShadersSwitchNothingOn) {
    TinyScene tiny;
    Shader glass;
    glass.type = ShaderType::Dielectric;
    glass.roughness = 0.3f;
    tiny.scene.shaders.push_back(glass);  // declared, never assigned to a shape
    const FeatureSet f = deriveFeatureSet(tiny.scene, tiny.accel, test::smallRender(8, 8, 1), true);
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
        const FeatureSet f = deriveFeatureSet(tiny.scene, tiny.accel, options, true);
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
    EXPECT_EQ(deriveFeatureSet(tiny.scene, tiny.accel, options, true).pathStackSize, 0u);
    options.glossSamples = 4;  // four at the primary hit: three wait on the stack
    EXPECT_EQ(deriveFeatureSet(tiny.scene, tiny.accel, options, true).pathStackSize, 3u + 4u);
    tiny.scene.shaders[0].roughness = 0.0f;  // a sharp mirror reflects once whatever glossSamples
    EXPECT_EQ(deriveFeatureSet(tiny.scene, tiny.accel, options, true).pathStackSize, 0u);
}

TEST(FeatureSet, GlossTexturesAreaLightsAndInstances) {
    TinyScene tiny;
    tiny.scene.shaders[0].roughness = 0.2f;
    tiny.scene.shaders[0].diffuseTexture = 0;
    tiny.scene.lights[0].type = LightType::Area;
    tiny.accel.bvh.instances[0].objectToWorld[0].w = 2.0f;  // one instance, but translated
    const FeatureSet f = deriveFeatureSet(tiny.scene, tiny.accel, test::smallRender(8, 8, 1), true);
    EXPECT_TRUE(f.gloss);
    EXPECT_TRUE(f.textures);
    EXPECT_TRUE(f.areaLights);
    EXPECT_TRUE(f.instances);

    TinyScene two;
    two.accel.bvh.instances.push_back(two.accel.bvh.instances[0]);  // two identity instances
    EXPECT_TRUE(deriveFeatureSet(two.scene, two.accel, test::smallRender(8, 8, 1), true).instances);
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
    EXPECT_TRUE(deriveFeatureSet(tiny.scene, tiny.accel, test::smallRender(8, 8, 1), true).reflection);
}

TEST(FeatureSet, GeneralHasEverything) {
    RenderOptions options = test::smallRender(8, 8, 1);
    options.maxDepth = 5;
    options.glossSamples = 4;
    const FeatureSet g = generalFeatureSet(options, true);
    const auto values = g.specializationValues();
    for (std::uint32_t id = 0; id <= gpu::SPEC_HAS_COOL_TO_WARM; ++id) EXPECT_EQ(values[id], 1u) << id;
    EXPECT_EQ(values[gpu::SPEC_MAX_DEPTH], 5u);
    EXPECT_EQ(values[gpu::SPEC_PATH_STACK_SIZE], 9u);
}

}  // namespace
}  // namespace vkrt
