// Several samples per dispatch (sample_batching.h): the passes cover every sample once in order,
// and the bound keeps k = 1 where a pass of k samples could reach the driver's loop limit (on the
// device, tests/vulkan/test_sample_batching.cpp checks that k does not change the image).
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "feature_set.h"
#include "sample_batching.h"
#include "tiny_scene.h"

namespace vkrt {
namespace {

using test::TinyScene;

TEST(SampleBatching, PassesCoverEverySampleOnceInOrder) {
    for (std::uint32_t spp : {1u, 7u, 8u, 10u, 64u})
        for (std::uint32_t k : {1u, 3u, 4u, 8u}) {
            const SampleBatching b{spp, k};
            std::uint32_t next = 0;
            for (std::uint32_t p = 0; p < b.passes(); ++p) {
                EXPECT_EQ(b.first(p), next) << spp << " " << k;
                EXPECT_GE(b.count(p), 1u);
                EXPECT_LE(b.count(p), k);
                next += b.count(p);
            }
            EXPECT_EQ(next, spp) << spp << " " << k;
        }
    const SampleBatching tenByFour{10, 4};
    EXPECT_EQ(tenByFour.passes(), 3u);
    EXPECT_EQ(tenByFour.count(2), 2u);  // 4 + 4 + 2
}

TEST(SampleBatching, KFitsTheLoopBudget) {
    // k * bound * kLockstepFactor must stay within the kernel's loop budget.
    const std::uint64_t perK = gpu::LOOP_BUDGET / kLockstepFactor;
    EXPECT_EQ(samplesPerDispatch(perK / 5, 64), 5u);
    EXPECT_EQ(samplesPerDispatch(perK / 3, 64), 1u);  // below kMinSamplesPerDispatch: not worth a loop
    EXPECT_EQ(samplesPerDispatch(perK, 64), 1u);
    EXPECT_EQ(samplesPerDispatch(perK * 100, 64), 1u);  // never 0
    EXPECT_EQ(samplesPerDispatch(1, 64), kMaxSamplesPerDispatch);
    EXPECT_EQ(samplesPerDispatch(1, 5), 5u);  // never more than the pixel's samples
    EXPECT_EQ(samplesPerDispatch(perK * 100, 64, 6), 6u);  // forced (tests)
    EXPECT_EQ(samplesPerDispatch(1, 4, 6), 4u);
    // Without lavapipe's group-wide limiter (lockstep factor 1) a sample may cost 8x more.
    EXPECT_EQ(samplesPerDispatch(perK * 8 / 5, 64, 0, 1), 5u);
    EXPECT_EQ(samplesPerDispatch(perK * 8 / 5, 64), 1u);
}

TEST(SampleBatching, TheBoundKeepsHeavyScenesAtOneSample) {
    TinyScene tiny;  // one sphere, one point light, Lambertian
    RenderOptions options = test::smallRender(8, 8, 16);
    const FeatureSet plain = deriveFeatureSet(tiny.scene, tiny.accel, options, true);
    const std::uint64_t cheap = sampleLoopBound(tiny.scene, tiny.accel.bvh, plain, options);
    EXPECT_EQ(samplesPerDispatch(cheap, 16), kMaxSamplesPerDispatch);

    // A mirror at depth 4 reflects a chain of at most 5 rays per sample.
    tiny.scene.shaders[0].type = ShaderType::Mirror;
    const FeatureSet mirror = deriveFeatureSet(tiny.scene, tiny.accel, options, true);
    EXPECT_EQ(sampleLoopBound(tiny.scene, tiny.accel.bvh, mirror, options), 5 * (cheap - 8) + 8);
    // With 3 gloss samples fanning out at the primary hit, three such chains.
    tiny.scene.shaders[0].roughness = 0.3f;
    options.glossSamples = 3;
    const FeatureSet glossy = deriveFeatureSet(tiny.scene, tiny.accel, options, true);
    EXPECT_GT(sampleLoopBound(tiny.scene, tiny.accel.bvh, glossy, options), 15 * (cheap - 8));
    options.glossSamples = 1;
    tiny.scene.shaders[0].roughness = 0.0f;
    // A dielectric at depth 4 can spawn a tree of 31 rays per sample: the bound grows 32-fold.
    tiny.scene.shaders[0].type = ShaderType::Dielectric;
    const FeatureSet glass = deriveFeatureSet(tiny.scene, tiny.accel, options, true);
    const std::uint64_t deep = sampleLoopBound(tiny.scene, tiny.accel.bvh, glass, options);
    EXPECT_EQ(deep, 32 * (cheap - 8) + 8);
    // More light samples mean more shadow traversals per ray.
    tiny.scene.lights[0].type = LightType::Area;
    options.lightSamples = 64;
    EXPECT_GT(sampleLoopBound(tiny.scene, tiny.accel.bvh, glass, options), 20 * deep);
    EXPECT_EQ(samplesPerDispatch(sampleLoopBound(tiny.scene, tiny.accel.bvh, glass, options), 16), 1u);

    // A tree too deep to count saturates instead of wrapping around to a small bound.
    options.maxDepth = 70;
    options.glossSamples = 64;
    const FeatureSet abyss = deriveFeatureSet(tiny.scene, tiny.accel, options, true);
    EXPECT_EQ(sampleLoopBound(tiny.scene, tiny.accel.bvh, abyss, options), std::numeric_limits<std::uint64_t>::max());
    options.maxDepth = 40;
    options.glossSamples = 1 << 24;  // 2^24 * 2^41 rays of thousands of passes: past 2^64 as a plain product
    const FeatureSet deep40 = deriveFeatureSet(tiny.scene, tiny.accel, options, true);
    EXPECT_EQ(sampleLoopBound(tiny.scene, tiny.accel.bvh, deep40, options), std::numeric_limits<std::uint64_t>::max());
    EXPECT_EQ(samplesPerDispatch(sampleLoopBound(tiny.scene, tiny.accel.bvh, deep40, options), 16), 1u);
}

}  // namespace
}  // namespace vkrt
