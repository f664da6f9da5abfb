// Tiling and sample passes: the planner covers every (pixel, sample) exactly once in sample
// order, keeps submissions near the time target, respects the workgroup limit; the stride is a
// well-spread permutation; and on the device the tiling never changes the image, renders are
// deterministic, and the accumulated sums match an independent host computation.
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <optional>
#include <string>

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

// The 8x8 blocks a submission covers: render.comp's mapping of its workgroups.
std::vector<glm::uvec2> blocksOf(const Submission& s) {
    const gpu::PassParams p = passParams(s.tile, s.firstSample);
    const std::uint32_t blocksX = (s.tile.width + 7) / 8;
    std::vector<glm::uvec2> blocks;
    for (std::uint32_t g = s.firstWorkgroup; g < s.firstWorkgroup + s.workgroupCount; ++g) {
        const std::uint32_t block = (g * p.pass.y) % p.pass.z;  // 32-bit, as on the device
        blocks.emplace_back(s.tile.x / 8 + block % blocksX, s.tile.y / 8 + block / blocksX);
    }
    return blocks;
}

// Runs a planner to the end with a simulated device taking `costOf(submission)` seconds,
// checking that every 8x8 block of the image gets every sample exactly once and in order;
// returns the submissions.
template <class Cost>
std::vector<Submission> simulate(std::uint32_t width, std::uint32_t height, std::uint32_t samples, const TilingPolicy& policy,
                                 Cost costOf) {
    TilePlanner planner(width, height, samples, policy);
    const std::uint32_t blocksX = (width + 7) / 8, blocksY = (height + 7) / 8;
    std::vector<std::uint32_t> nextSample(static_cast<std::size_t>(blocksX) * blocksY, 0);
    std::vector<Submission> all;
    while (!planner.done()) {
        const Submission s = planner.next();
        EXPECT_GT(s.sampleCount, 0u);
        EXPECT_GT(s.workgroupCount, 0u);
        EXPECT_LE(s.firstWorkgroup + s.workgroupCount, s.tile.workgroups());
        EXPECT_LE(s.firstWorkgroup + s.workgroupCount, policy.maxWorkgroups);  // vkCmdDispatchBase's limit
        EXPECT_LE(s.tile.x + s.tile.width, width);
        EXPECT_LE(s.tile.y + s.tile.height, height);
        EXPECT_TRUE(s.sampleCount == 1 || s.workgroupCount == s.tile.workgroups()) << "several passes over part of a tile";
        for (const glm::uvec2 b : blocksOf(s)) {
            std::uint32_t& next = nextSample[static_cast<std::size_t>(b.y) * blocksX + b.x];
            EXPECT_EQ(next, s.firstSample) << "block " << b.x << "," << b.y << " got samples out of order";
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

double uniformCost(const Submission& s, double perBlockSample) {
    return perBlockSample * s.workgroupCount * s.sampleCount;
}

TEST(TilePlanner, CoversEveryBlockSampleOnceInOrder) {
    for (auto [w, h, spp] : {std::tuple{1u, 1u, 1u}, {250u, 250u, 16u}, {70u, 45u, 5u}, {1000u, 3u, 2u}, {3u, 1000u, 7u}}) {
        SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + "x" + std::to_string(spp));
        const TilingPolicy adaptive;
        simulate(w, h, spp, adaptive, [](const Submission& s) { return uniformCost(s, 1e-6); });
        simulate(w, h, spp, adaptive, [](const Submission& s) { return uniformCost(s, 1e-1); });
        TilingPolicy fixed;
        fixed.fixedTileWidth = 16;
        fixed.fixedTileHeight = 24;
        fixed.fixedWorkgroups = 5;
        simulate(w, h, spp, fixed, [](const Submission&) { return 0.01; });
        TilingPolicy passes;
        passes.fixedSamples = 3;
        simulate(w, h, spp, passes, [](const Submission&) { return 0.01; });
    }
}

TEST(TilePlanner, FixedPolicyGivesTheAskedSubmissions) {
    TilingPolicy fixed;
    fixed.fixedTileWidth = 16;
    fixed.fixedTileHeight = 8;
    fixed.fixedWorkgroups = 1;
    fixed.fixedSamples = 1;
    const auto all = simulate(40, 10, 3, fixed, [](const Submission&) { return 0.01; });
    // 3 x 2 tiles of 2, 2, 1 (top) and 2, 2, 1 (bottom) workgroups, one workgroup and one pass each.
    ASSERT_EQ(all.size(), (2u + 2u + 1u) * 2u * 3u);
    EXPECT_EQ(all[0].tile.width, 16u);
    EXPECT_EQ(all[1].firstWorkgroup, 1u);
    EXPECT_EQ(all[2].firstSample, 1u);
    EXPECT_EQ(all[12].tile.width, 8u);
    EXPECT_EQ(all[15].tile.y, 8u);
    EXPECT_EQ(all[15].tile.height, 2u);
}

// With a uniform cost the planner learns it from the first probe: no later submission may
// exceed the target, and once grown they should use at least half of it.
TEST(TilePlanner, SubmissionsStayNearTheTarget) {
    const TilingPolicy policy;  // 0.3 s
    const double cost = 1e-4;   // seconds per block-sample: 3000 per target
    const auto all = simulate(1024, 768, 64, policy, [&](const Submission& s) { return uniformCost(s, cost); });
    int full = 0;
    for (std::size_t i = 1; i < all.size(); ++i) {
        EXPECT_LE(uniformCost(all[i], cost), policy.targetSeconds * 1.0001) << "submission " << i;
        if (uniformCost(all[i], cost) >= policy.targetSeconds / 2) ++full;
    }
    EXPECT_GT(full, static_cast<int>(all.size()) * 9 / 10) << all.size() << " submissions";
}

// All the cost in a corner: a tenth of the image 100x more expensive than the rest. Spatial
// tiles sized from the cheap part would overshoot ~10x on reaching the corner; interleaved
// workgroup runs sample the corner in proportion from the first probe on.
TEST(TilePlanner, AnExpensiveCornerDoesNotMakeSubmissionsOvershoot) {
    const TilingPolicy policy;
    const std::uint32_t width = 640, height = 480;
    auto seconds = [&](const Submission& s) {
        double total = 0.0;
        for (const glm::uvec2 b : blocksOf(s)) total += (b.x < width / 8 / 4 && b.y < height / 8 * 4 / 10) ? 1e-3 : 1e-5;
        return total * s.sampleCount;
    };
    const auto all = simulate(width, height, 16, policy, seconds);
    double worst = 0.0;
    for (std::size_t i = 1; i < all.size(); ++i) worst = std::max(worst, seconds(all[i]));
    std::cout << all.size() << " submissions, longest " << worst << " s for a target of " << policy.targetSeconds << " s\n";
    // A run of n consecutive workgroups holds the corner's share of blocks to within a few blocks
    // (a golden-ratio sequence), so the estimate is off by a few percent at most.
    EXPECT_LE(worst, policy.targetSeconds * 1.2);
}

TEST(TilePlanner, LargeImagesAreSplitIntoBandsOfAtMostMaxWorkgroups) {
    TilingPolicy policy;
    policy.maxWorkgroups = 1000;
    const std::vector<TileRect> tiles = planTiles(800, 1000, policy);  // 100 blocks per row: 80 rows per band
    ASSERT_EQ(tiles.size(), 13u);
    EXPECT_EQ(tiles[0].height, 80u);
    EXPECT_EQ(tiles[12].height, 40u);
    for (const TileRect& t : tiles) EXPECT_LE(t.workgroups(), 1000u);
    simulate(800, 1000, 2, policy, [](const Submission& s) { return uniformCost(s, 1e-9); });
    EXPECT_EQ(planTiles(250, 250, TilingPolicy{}).size(), 1u);
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
                const glm::vec2 j = sampling::sample2D(f.sampling.x, f.pixelGrid, pixel, s, sampling::DIM_CAMERA, f.scene.x);
                const float a = f.cameraU.w * ((static_cast<float>(x) + j.x) / static_cast<float>(options.width) - 0.5f);
                const float b = f.cameraV.w * (0.5f - (static_cast<float>(y) + j.y) / static_cast<float>(options.height));
                const glm::vec3 dir = glm::normalize(-f.cameraW.w * glm::vec3(f.cameraW) + a * glm::vec3(f.cameraU) + b * glm::vec3(f.cameraV));
                sum += dir + glm::vec3(0.0f, 0.0f, static_cast<float>(s) / 64.0f);
            }
            image.at(x, y) = sum / static_cast<float>(options.samplesPerPixel);
        }
    return image;
}

GpuRenderSettings fixedTiling(std::uint32_t tileWidth, std::uint32_t tileHeight, std::uint32_t workgroups, std::uint32_t samples) {
    GpuRenderSettings s;
    s.tiling.fixedTileWidth = tileWidth;
    s.tiling.fixedTileHeight = tileHeight;
    s.tiling.fixedWorkgroups = workgroups;
    s.tiling.fixedSamples = samples;
    s.samplesPerDispatch = 1;  // the counts below are of one-sample passes (test_sample_batching.cpp: k > 1)
    return s;
}

TEST_F(VulkanTest, TilingDoesNotChangeTheImageAndMatchesTheHost) {
    TinyScene tiny;
    const RenderOptions options = test::smallRender(70, 45, 5);  // not multiples of 8: 9 x 6 blocks
    GpuRenderer& gpu = renderer({.kernelSpirv = test::testKernel("camera_rays")});

    GpuRenderStats stats;
    const Image adaptive = gpu.render(tiny.scene, tiny.accel, options, &stats);
    std::cout << "adaptive: " << stats.submissions << " submissions, " << stats.dispatches << " dispatches, longest "
              << stats.maxSubmissionSeconds << " s\n";
    const Image small = gpu.render(tiny.scene, tiny.accel, options, &stats, fixedTiling(8, 8, 0, 1));
    EXPECT_EQ(stats.submissions, 9u * 6u * 5u);  // 54 one-block tiles, one pass each
    EXPECT_EQ(stats.dispatches, 9u * 6u * 5u);
    const Image runs = gpu.render(tiny.scene, tiny.accel, options, &stats, fixedTiling(0, 0, 7, 0));
    EXPECT_EQ(stats.submissions, 8u * 5u);  // runs of 7 of the 54 workgroups, pass by pass
    const Image odd = gpu.render(tiny.scene, tiny.accel, options, &stats, fixedTiling(24, 16, 0, 3));
    EXPECT_EQ(stats.submissions, 3u * 3u * 2u);  // 9 tiles, passes 0-2 then 3-4
    const Image whole = gpu.render(tiny.scene, tiny.accel, options, &stats, fixedTiling(0, 0, 0, 5));
    EXPECT_EQ(stats.submissions, 1u);
    EXPECT_EQ(stats.dispatches, 5u);

    EXPECT_EQ(runs.pixels, adaptive.pixels);
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

// Sets an environment variable for its lifetime and restores the previous value, also when the
// test fails halfway (later tests in the same process must not inherit it).
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) previous_ = old;
        setenv(name, value, 1);
    }
    ~ScopedEnv() {
        if (previous_) setenv(name_, previous_->c_str(), 1);
        else unsetenv(name_);
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    const char* name_;
    std::optional<std::string> previous_;
};

// lavapipe (Mesa 22.3) re-inlines uniform values that feed control flow and recompiles the kernel
// whenever push constants or uniform bindings change, i.e. at every submission; the kernels read
// their uniforms so that it cannot (shaders/bindings.glsl). With Mesa's shader disk cache off,
// every such recompile is a full LLVM compile: before the change, 16 submissions took 3.3 s
// against 0.22 s for the warm-up's compile. Now all of them together must take less than making
// the kernel (pipeline creation plus warm-up dispatch: where a driver compiles it, seconds on
// lavapipe) against milliseconds for this tiny render, on any driver.
TEST_F(VulkanTest, SubmissionsDoNotRecompileTheKernel) {
    TinyScene tiny;
    GpuRenderer* gpu = nullptr;
    {
        const ScopedEnv noDiskCache("MESA_SHADER_CACHE_DISABLE", "true");  // read when the device is created
        gpu = &renderer();                                                  // the real render kernel
    }
    GpuRenderStats stats;
    gpu->render(tiny.scene, tiny.accel, test::smallRender(32, 32, 16), &stats, fixedTiling(0, 0, 16, 1));
    ASSERT_EQ(stats.submissions, 16u);  // one per sample pass, each with its own push constants
    const double compile = stats.pipelineSeconds + stats.warmUpSeconds;
    std::cout << "pipeline + warm-up " << compile << " s, 16 submissions " << stats.renderSeconds << " s\n";
    EXPECT_LT(stats.renderSeconds, compile);
}

}  // namespace
}  // namespace vkrt
