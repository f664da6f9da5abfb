// host/lighting/final_rays.h: which rays ending at the maximum depth can bring light, feature by
// feature. Each case adds one thing a ray there can see to a scene where none can (Diffuse,
// Mirror and Dielectric shaders, black background, no emitter, no map), and checks the flags.
// Bug targeted: a forgotten source of light at the maximum depth (the renderers would skip rays
// that add to the image), or a flag that never allows skipping.
#include <gtest/gtest.h>

#include "final_rays.h"

namespace vkrt {
namespace {

Shader shaderOf(ShaderType type, bool diffuseBounce = false) {
    Shader s;
    s.type = type;
    s.diffuseBounce = diffuseBounce;
    return s;
}

Scene darkAtMaxDepth() {
    Scene scene;
    scene.background = glm::vec3(0.0f);
    scene.shaders = {shaderOf(ShaderType::Lambertian, true), shaderOf(ShaderType::Mirror), shaderOf(ShaderType::Dielectric)};
    return scene;
}

void expectFlags(const Scene& scene, const RenderOptions& options, bool bounce, bool reflection, const char* what) {
    const FinalRays rays = finalRays(scene, options);
    EXPECT_EQ(rays.bounceSeesLight, bounce) << what;
    EXPECT_EQ(rays.reflectionSeesLight, reflection) << what;
}

TEST(FinalRays, OnlyDiffuseMirrorAndGlassUnderABlackSkyLeaveNothingToFind) {
    expectFlags(darkAtMaxDepth(), RenderOptions{}, false, false, "Diffuse, Mirror, Dielectric, black sky");
}

TEST(FinalRays, EveryShaderWithLocalShadingIsLitAtTheMaximumDepth) {
    for (ShaderType type : {ShaderType::Lambertian, ShaderType::BlinnPhong, ShaderType::Glaze, ShaderType::BlinnPhongMirrored,
                            ShaderType::CoolToWarm}) {
        Scene scene = darkAtMaxDepth();
        scene.shaders.push_back(shaderOf(type));
        expectFlags(scene, RenderOptions{}, true, true, "a local shader");
    }
}

TEST(FinalRays, TheBackgroundCountsUnlessBlackAndTheOptionOverridesTheScene) {
    Scene scene = darkAtMaxDepth();
    scene.background = glm::vec3(0.0f, 0.0f, 1e-30f);
    expectFlags(scene, RenderOptions{}, true, true, "a faint background");
    RenderOptions black;
    black.background = glm::vec3(0.0f);
    expectFlags(scene, black, false, false, "--bg 0,0,0 over the scene's");
    RenderOptions grey;
    grey.background = glm::vec3(50.0f / 255.0f);
    expectFlags(darkAtMaxDepth(), grey, true, true, "--bg grey over a black scene");
    // The background is never light-sampled: a bounce finds it under every estimator, nee too.
    grey.estimator = Estimator::Nee;
    expectFlags(darkAtMaxDepth(), grey, true, true, "--bg grey under nee");
}

TEST(FinalRays, EmittersAndTheMapAreFoundByReflectionsAlwaysAndByBouncesUnlessNeeAlone) {
    Scene withEmitter = darkAtMaxDepth();
    withEmitter.emitters.emplace_back();
    Scene withMap = darkAtMaxDepth();
    withMap.environment.faceSize = 4;
    for (Estimator e : {Estimator::Bounce, Estimator::Nee, Estimator::MisBalance, Estimator::MisPower}) {
        RenderOptions options;
        options.estimator = e;
        const bool bounceFinds = e != Estimator::Nee;
        expectFlags(withEmitter, options, bounceFinds, true, "a shape emitter");
        expectFlags(withMap, options, bounceFinds, true, "an environment map");
    }
    // --no-environment: leaving rays see the (black) background instead.
    RenderOptions noMap;
    noMap.environment = false;
    expectFlags(withMap, noMap, false, false, "an environment map not used");
}

}  // namespace
}  // namespace vkrt
