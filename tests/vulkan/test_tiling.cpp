// Tiling and sample passes: the planner covers every (pixel, sample) exactly once in sample
// order, keeps submissions near the time target, respects the workgroup limit; the stride is a
// well-spread permutation; and on the device the tiling never changes the image, renders are
// deterministic, and the accumulated sums match an independent host computation.
#include <atomic>
#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "frame_params.h"
#include "sampling.h"
#include "submission_recorder.h"
#include "tile_planner.h"
#include "vulkan_test_support.h"

namespace vkrt {
namespace {

using test::TinyScene;
using test::VulkanTest;

// Runs a planner to the end with a simulated device taking `costOf(submission)` seconds,
// checking coverage and order; returns the submissions.
template <class Cost>
std::vector<Submission> simulate(std::uint32_t width, std::uint32_t height, std::uint32_t samples, const TilingPolicy& policy,
                                 Cost costOf) {
    TilePlanner planner(width, height, samples, policy);
    std::vector<std::uint32_t> nextSample(static_cast<std::size_t>(width) * height, 0);
    std::vector<Submission> all;
    while (!planner.done()) {
        const Submission s = planner.next();
        EXPECT_GT(s.sampleCount, 0u);
        EXPECT_LE(s.tile.x + s.tile.width, width);
        EXPECT_LE(s.tile.y + s.tile.height, height);
        for (std::uint32_t y = s.tile.y; y < s.tile.y + s.tile.height; ++y)
            for (std::uint32_t x = s.tile.x; x < s.tile.x + s.tile.width; ++x) {
                std::uint32_t& next = nextSample[static_cast<std::size_t>(y) * width + x];
                EXPECT_EQ(next, s.firstSample) << "pixel " << x << "," << y << " got samples out of order";
                next = s.firstSample + s.sampleCount;
            }
        planner.reportSeconds(costOf(s));
        all.push_back(s);
        if (all.size() > 1000000) {
            ADD_FAILURE() << "planner does not finish";
            break;
        }
    }
    for (std::uint32_t n : nextSample) EXPECT_EQ(n, samples);
    EXPECT_DOUBLE_EQ(planner.fractionDone(), 1.0);
    return all;
}

TEST(TilePlanner, CoversEveryPixelSampleOnceInOrder) {
    const TilingPolicy adaptive;
    for (auto [w, h, spp] : {std::tuple{1u, 1u, 1u}, {250u, 250u, 16u}, {70u, 45u, 5u}, {1000u, 3u, 2u}, {3u, 1000u, 7u}}) {
        SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + "x" + std::to_string(spp));
        simulate(w, h, spp, adaptive, [](const Submission& s) { return 1e-7 * static_cast<double>(s.tile.pixels() * s.sampleCount); });
        simulate(w, h, spp, adaptive, [](const Submission& s) { return 1e-3 * static_cast<double>(s.tile.pixels() * s.sampleCount); });
        TilingPolicy fixed;
        fixed.fixedTileWidth = 16;
        fixed.fixedTileHeight = 8;
        fixed.fixedSamplesPerSubmission = 3;
        simulate(w, h, spp, fixed, [](const Submission&) { return 0.01; });
    }
}

TEST(TilePlanner, FixedPolicyGivesTheAskedTiles) {
    TilingPolicy fixed;
    fixed.fixedTileWidth = 16;
    fixed.fixedTileHeight = 8;
    fixed.fixedSamplesPerSubmission = 2;
    const auto all = simulate(40, 10, 3, fixed, [](const Submission&) { return 0.01; });
    // Tiles: 3 across (16, 16, 8 wide) x 2 bands (8, 2 high); samples 0-1 then 2 per tile.
    ASSERT_EQ(all.size(), 12u);
    EXPECT_EQ(all[0].tile.width, 16u);
    EXPECT_EQ(all[0].sampleCount, 2u);
    EXPECT_EQ(all[1].firstSample, 2u);
    EXPECT_EQ(all[1].sampleCount, 1u);
    EXPECT_EQ(all[4].tile.width, 8u);
    EXPECT_EQ(all[6].tile.y, 8u);
    EXPECT_EQ(all[6].tile.height, 2u);
}

// With a uniform cost per pixel-sample the planner learns it from the first probe: no later
// submission may exceed the target, and once grown they should use at least half of it.
TEST(TilePlanner, SubmissionsStayNearTheTarget) {
    const TilingPolicy policy;  // 0.3 s
    const double cost = 2e-6;   // seconds per pixel-sample: 150,000 pixel-samples per target
    const auto all = simulate(1024, 768, 64, policy, [&](const Submission& s) { return cost * static_cast<double>(s.tile.pixels() * s.sampleCount); });
    int full = 0;
    for (std::size_t i = 1; i < all.size(); ++i) {
        const double seconds = cost * static_cast<double>(all[i].tile.pixels() * all[i].sampleCount);
        EXPECT_LE(seconds, policy.targetSeconds * 1.0001) << "submission " << i;
        if (seconds >= policy.targetSeconds / 2) ++full;
    }
    EXPECT_GT(full, static_cast<int>(all.size()) * 8 / 10) << all.size() << " submissions";
}

// A cheap region then a region 20x more expensive: a submission sized from the cheap region can
// overshoot when it reaches the expensive one - by at most the cost ratio - and the planner must
// recover at once (pieces of the too-large tile continue separately), so overshoots stay rare.
TEST(TilePlanner, AdaptsWhenTheCostJumps) {
    const TilingPolicy policy;
    auto seconds = [](const Submission& s) {
        double rows = 0.0;  // cost is additive over the tile's rows
        for (std::uint32_t y = s.tile.y; y < s.tile.y + s.tile.height; ++y) rows += y < 300 ? 1e-7 : 2e-6;
        return rows * s.tile.width * s.sampleCount;
    };
    const auto all = simulate(512, 600, 16, policy, seconds);
    int over = 0;
    double worst = 0.0;
    for (const Submission& s : all) {
        worst = std::max(worst, seconds(s));
        if (seconds(s) > policy.targetSeconds * 1.0001) ++over;
    }
    std::cout << all.size() << " submissions, " << over << " over the target, longest " << worst << " s\n";
    EXPECT_LE(worst, policy.targetSeconds * 20.0);
    EXPECT_LE(over, 2);
}

TEST(TilePlanner, NeverExceedsTheWorkgroupLimit) {
    TilingPolicy policy;
    policy.maxWorkgroups = 1000;
    const auto all = simulate(2000, 1500, 2, policy, [](const Submission& s) { return 1e-12 * static_cast<double>(s.tile.pixels()); });
    for (const Submission& s : all) EXPECT_LE(passParams(s.tile, 0).pass.z, 1000u);
}

TEST(InterleaveStride, IsAPermutationSpreadOverTheTile) {
    for (std::uint32_t n = 1; n <= 3000; ++n) {
        const std::uint32_t stride = interleaveStride(n);
        ASSERT_EQ(std::gcd(stride, n), 1u) << n;
        ASSERT_LT(stride, std::max(n, 2u)) << n;
    }
    // lavapipe gives each of its threads a contiguous run of workgroups: with 2 threads, the
    // first half of the workgroups must cover both halves of the tile about equally.
    const std::uint32_t n = 1000, stride = interleaveStride(n);
    std::vector<bool> seen(n, false);
    int firstHalfInLowerHalf = 0;
    for (std::uint32_t g = 0; g < n; ++g) {
        const std::uint32_t block = static_cast<std::uint32_t>((static_cast<std::uint64_t>(g) * stride) % n);
        EXPECT_FALSE(seen[block]);
        seen[block] = true;
        if (g < n / 2 && block < n / 2) ++firstHalfInLowerHalf;
    }
    EXPECT_NEAR(firstHalfInLowerHalf, 250, 25);
}

// camera_rays.comp, recomputed on the host: sum over samples of the unit perspective ray
// direction through the sample point, plus sample / 64 in blue, divided by rpp.
Image expectedCameraRays(const Scene& scene, const SceneAccel& accel, const RenderOptions& options) {
    const gpu::FrameParams f = makeFrameParams(scene, accel, options);
    Image image(options.width, options.height);
    for (int y = 0; y < options.height; ++y)
        for (int x = 0; x < options.width; ++x) {
            const std::uint32_t pixel = static_cast<std::uint32_t>(y * options.width + x);
            glm::vec3 sum(0.0f);
            for (std::uint32_t s = 0; s < static_cast<std::uint32_t>(options.samplesPerPixel); ++s) {
                const glm::vec2 j = gpu::sample2D(f.sampling.x, f.pixelGrid, pixel, s, gpu::DIM_CAMERA, f.scene.x);
                const float a = f.cameraU.w * ((static_cast<float>(x) + j.x) / static_cast<float>(options.width) - 0.5f);
                const float b = f.cameraV.w * (0.5f - (static_cast<float>(y) + j.y) / static_cast<float>(options.height));
                const glm::vec3 dir = glm::normalize(-f.cameraW.w * glm::vec3(f.cameraW) + a * glm::vec3(f.cameraU) + b * glm::vec3(f.cameraV));
                sum += dir + glm::vec3(0.0f, 0.0f, static_cast<float>(s) / 64.0f);
            }
            image.at(x, y) = sum / static_cast<float>(options.samplesPerPixel);
        }
    return image;
}

GpuRenderSettings fixedTiles(std::uint32_t w, std::uint32_t h, std::uint32_t samples) {
    GpuRenderSettings s;
    s.tiling.fixedTileWidth = w;
    s.tiling.fixedTileHeight = h;
    s.tiling.fixedSamplesPerSubmission = samples;
    return s;
}

TEST_F(VulkanTest, TilingDoesNotChangeTheImageAndMatchesTheHost) {
    TinyScene tiny;
    const RenderOptions options = test::smallRender(70, 45, 5);  // not multiples of 8
    GpuRenderer& gpu = renderer({.kernelSpirv = test::testKernel("camera_rays")});

    GpuRenderStats stats;
    const Image adaptive = gpu.render(tiny.scene, tiny.accel, options, &stats);
    std::cout << "adaptive: " << stats.submissions << " submissions, " << stats.dispatches << " dispatches, longest "
              << stats.maxSubmissionSeconds << " s\n";
    const Image small = gpu.render(tiny.scene, tiny.accel, options, &stats, fixedTiles(8, 8, 1));
    EXPECT_EQ(stats.submissions, 9u * 6u * 5u);  // 9 x 6 tiles, one pass each
    EXPECT_EQ(stats.dispatches, 9u * 6u * 5u);
    const Image odd = gpu.render(tiny.scene, tiny.accel, options, &stats, fixedTiles(24, 16, 3));
    EXPECT_EQ(stats.submissions, 3u * 3u * 2u);  // passes 0-2, then 3-4
    const Image whole = gpu.render(tiny.scene, tiny.accel, options, &stats, fixedTiles(70, 45, 5));
    EXPECT_EQ(stats.submissions, 1u);
    EXPECT_EQ(stats.dispatches, 5u);

    EXPECT_EQ(small.pixels, adaptive.pixels);
    EXPECT_EQ(odd.pixels, adaptive.pixels);
    EXPECT_EQ(whole.pixels, adaptive.pixels);

    // The device may contract a*b+c into an FMA and normalize() with its own inversesqrt
    // (a few ULP), so each of the 5 summed unit vectors can differ from the host's by ~1e-6;
    // 2e-5 bounds that with margin, while a missing, repeated or misplaced sample moves a
    // channel by at least 1/64/5 = 3e-3 (blue) or the ray change between pixels (~1e-3).
    const Image expected = expectedCameraRays(tiny.scene, tiny.accel, options);
    float worst = 0.0f;
    for (std::size_t i = 0; i < expected.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(adaptive.pixels[i][c] - expected.pixels[i][c]));
    EXPECT_LT(worst, 2e-5f);
    std::cout << "largest difference from the host: " << worst << "\n";
}

TEST_F(VulkanTest, RenderingIsDeterministic) {
    TinyScene tiny;
    RenderOptions options = test::smallRender(33, 17, 4);
    options.sampler = SamplerKind::Random;
    GpuRenderer& gpu = renderer({.kernelSpirv = test::testKernel("camera_rays")});
    const Image first = gpu.render(tiny.scene, tiny.accel, options);
    const Image second = gpu.render(tiny.scene, tiny.accel, options);
    EXPECT_EQ(first.pixels, second.pixels);
    options.seed += 1;  // and the seed matters, so equality above is not vacuous
    EXPECT_NE(gpu.render(tiny.scene, tiny.accel, options).pixels, first.pixels);
}

TEST_F(VulkanTest, StagingPathGivesTheSameImage) {
    TinyScene tiny;
    const RenderOptions options = test::smallRender(20, 20, 3);
    const Image mapped = renderer({.kernelSpirv = test::testKernel("camera_rays")}).render(tiny.scene, tiny.accel, options);
    const Image staged =
        renderer({.kernelSpirv = test::testKernel("camera_rays"), .forceStaging = true}).render(tiny.scene, tiny.accel, options);
    EXPECT_EQ(mapped.pixels, staged.pixels);
}

TEST_F(VulkanTest, CancelStopsBetweenSubmissions) {
    TinyScene tiny;
    std::atomic<bool> cancel{true};
    RenderOptions options = test::smallRender(16, 16, 2);
    options.cancel = &cancel;
    GpuRenderer& gpu = renderer({.kernelSpirv = test::testKernel("camera_rays")});
    EXPECT_THROW(gpu.render(tiny.scene, tiny.accel, options), RenderCancelled);
    cancel = false;
    EXPECT_NO_THROW(gpu.render(tiny.scene, tiny.accel, options));  // the renderer is still usable
}

}  // namespace
}  // namespace vkrt
