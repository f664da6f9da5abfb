// The wavefront renderer's waves and path layout (host/gpu/wavefront_plan.h), without a device:
// every pixel gets each of its samples exactly once and in sample order, rounds end at the
// progressive breaks, a wave never holds more paths than asked (but a row at least) nor more than
// kMaxWaveSamples samples of a pixel, and the paths per wave shrink to fit the device's limits.
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "wavefront_plan.h"

namespace vkrt {
namespace {

// For every pixel of rows [rowBegin, rowEnd), the samples the plan's waves give it, in wave order.
std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> samplesPerPixel(const WavePlan& plan) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> out;
    for (const Wave& w : plan.waves)
        for (std::uint32_t y = w.band.y; y < w.band.y + w.band.height; ++y)
            for (std::uint32_t x = w.band.x; x < w.band.x + w.band.width; ++x)
                for (std::uint32_t s = w.firstSample; s < w.firstSample + w.samples; ++s) out[{x, y}].push_back(s);
    return out;
}

TEST(WavePlan, EveryPixelGetsItsSamplesOnceInOrder) {
    for (const std::uint64_t paths : {10ull, 35ull, 200ull, 1000ull, 1ull << 20}) {
        const WavePlan plan = planWaves(10, 3, 17, 7, paths);
        const auto got = samplesPerPixel(plan);
        ASSERT_EQ(got.size(), 10u * 14u) << paths;
        for (const auto& [pixel, samples] : got) {
            ASSERT_EQ(samples.size(), 7u) << paths;
            for (std::uint32_t s = 0; s < 7; ++s) EXPECT_EQ(samples[s], s) << paths;
        }
        for (const Wave& w : plan.waves) {
            EXPECT_LE(w.paths(), std::max<std::uint64_t>(paths, 10)) << paths;
            EXPECT_LE(w.paths(), plan.maxPaths);
        }
        EXPECT_EQ(plan.roundEnds.back(), plan.waves.size());
    }
}

TEST(WavePlan, RoundsEndAtTheBreaksAndWavesHoldAtMostTheSampleCap) {
    const WavePlan plan = planWaves(4, 0, 4, 10, 1000, {3, 6});
    std::vector<std::uint32_t> ends;
    for (const std::size_t end : plan.roundEnds) ends.push_back(plan.waves[end - 1].firstSample + plan.waves[end - 1].samples);
    EXPECT_EQ(ends, (std::vector<std::uint32_t>{3, 6, 10}));

    const WavePlan many = planWaves(1, 0, 1, 3 * kMaxWaveSamples, 1ull << 30);
    for (const Wave& w : many.waves) EXPECT_LE(w.samples, kMaxWaveSamples);
    EXPECT_EQ(many.waves.size(), 3u);
}

TEST(WavefrontPathLayout, CountsEveryShadowRayAHitCanAskForAndTheQueues) {
    SceneTables tables;
    gpu::Light point{}, area{};
    area.info.x = gpu::LIGHT_AREA;
    tables.lights = {point, area, area};
    FeatureSet features;
    features.emitters = true;
    features.environment = true;
    features.pathStackSize = 5;
    gpu::FrameParams frame{};
    frame.sampling.z = 4;   // light samples
    frame.lighting.x = 2;   // emitters
    frame.lighting.z = 16;  // an environment map's face size
    const WavefrontPathLayout layout = wavefrontPathLayout(tables, features, frame);
    EXPECT_EQ(layout.shadowsPerPath, 1u + 4u + 4u + 4u + 4u);
    EXPECT_EQ(layout.texelsPerPath(), 6u + 2u * 17u + 3u * 5u + 2u + 17u);
    frame.lighting = glm::uvec4(0u);  // no emitters, no map: no rays for them
    EXPECT_EQ(wavefrontPathLayout(tables, features, frame).shadowsPerPath, 9u);
}

TEST(WavePaths, ShrinkToTheDevicesLimits) {
    BufferLimits limits;
    limits.maxTexelBufferElements = 1u << 20;
    limits.maxMemoryAllocationSize = 1ull << 40;
    limits.heapBytes = 1ull << 40;
    limits.maxStorageBufferRange = 1u << 27;
    WavefrontPathLayout layout;
    layout.shadowsPerPath = 2;
    const std::uint64_t paths = wavePathsFor(limits, 1000, layout, 65535, 1u << 20);
    EXPECT_GT(paths, 0u);
    EXPECT_LE(1000 + paths * layout.texelsPerPath(), limits.maxTexelBufferElements);  // fits the texel buffer
    EXPECT_EQ(wavePathsFor(limits, 1000, layout, 65535, 100), 100u);                  // the target when it fits
    EXPECT_LE(wavePathsFor(limits, 1000, layout, 10, 1u << 20) * 2, 10u * 64u);        // SHADOW's dispatch covers every ray
}

}  // namespace
}  // namespace vkrt
