// Adaptive sampling (host/adaptive, docs/SAMPLING.md §7): a pixel's N adaptive samples are those of
// a uniform N-rpp render bit for bit, the counts do not depend on the threads, the error estimate
// from a pixel's two halves is unbiased against exact pixels and calibrated on an image against a
// high-rpp reference, and the rounds stop where the options say.
#include <cmath>
#include <cstdio>
#include <set>

#include <gtest/gtest.h>

#include "adaptive_render.h"
#include "cpu_renderer.h"
#include "gpu_renderer.h"
#include "image_compare.h"
#include "pixel_study.h"
#include "sample_allocation.h"
#include "study_scenes.h"

namespace vkrt::test {
namespace {

adaptive::AdaptiveResult renderAdaptively(const Scene& scene, const SceneAccel& accel, RenderOptions o,
                                          const adaptive::AdaptiveOptions& a) {
    o.samplesPerPixel = static_cast<int>(a.maxRpp);
    CpuSampleRanges cpu(scene, accel, o);
    return adaptive::renderAdaptive(o.width, o.height, rowsOf(o), a,
                                    [&](const std::vector<std::uint32_t>& next, adaptive::PixelAccumulation& acc) { cpu.add(next, acc); });
}

RenderOptions smallOptions(const Scene& scene, int size) {
    RenderOptions o;
    o.width = size;
    o.height = size;
    o.sampler = SamplerKind::Sobol2;
    o.seed = 3;
    o.camera = scene.defaultCamera;
    o.quiet = true;
    return o;
}

// Rounds toward `target` of at most `maxRpp` samples a pixel; `o` renders up to that many.
adaptive::AdaptiveOptions roundsUpTo(double target, std::uint32_t maxRpp, RenderOptions& o) {
    adaptive::AdaptiveOptions a;
    a.targetError = target;
    a.maxRpp = maxRpp;
    o.samplesPerPixel = static_cast<int>(maxRpp);
    return a;
}

// The rule: a pixel that got N samples holds the first N samples of its sequence, so it is
// that pixel of a uniform N-rpp render, bit for bit (both sum the same floats in the same order).
// Checked for every count the adaptive render used, with both samplers adaptive sampling takes.
TEST(AdaptiveSampling, APixelsSamplesAreAUniformRendersBitForBit) {
    const Scene scene = exampleScene("soft_shadows");
    const SceneAccel accel = prepareCpuScene(scene);
    for (SamplerKind sampler : {SamplerKind::Sobol2, SamplerKind::Random}) {
        RenderOptions o = smallOptions(scene, 40);
        o.sampler = sampler;
        adaptive::AdaptiveOptions a;
        a.targetError = 0.02;
        a.minRpp = 8;
        a.maxRpp = 256;
        const adaptive::AdaptiveResult r = renderAdaptively(scene, accel, o, a);
        std::set<std::uint32_t> counts(r.acc.count.begin(), r.acc.count.end());
        ASSERT_GE(counts.size(), 3u) << samplerName(sampler) << ": the render did not adapt (" << r.last.number << " rounds, "
                                     << adaptive::stopReasonText(r.stop) << "): nothing to compare";
        for (std::uint32_t n : counts) {
            o.samplesPerPixel = static_cast<int>(n);
            const Image uniform = renderCpu(scene, accel, o);
            int checked = 0;
            for (std::size_t p = 0; p < uniform.pixels.size(); ++p)
                if (r.acc.count[p] == n) {
                    ASSERT_EQ(r.acc.mean(p), uniform.pixels[p]) << samplerName(sampler) << " pixel " << p << " at " << n;
                    ++checked;
                }
            EXPECT_GT(checked, 0);
        }
    }
}

// The counts and sums are the same whatever the threads: each round's plan depends only on the
// samples, which do not depend on which thread computed them.
TEST(AdaptiveSampling, CountsAndImageDoNotDependOnTheThreads) {
    const Scene scene = exampleScene("glossy");
    const SceneAccel accel = prepareCpuScene(scene);
    adaptive::AdaptiveOptions a;
    a.targetError = 0.02;
    a.maxRpp = 256;
    RenderOptions one = smallOptions(scene, 48), two = one;
    one.threads = 1;
    two.threads = 2;
    const adaptive::AdaptiveResult r1 = renderAdaptively(scene, accel, one, a), r2 = renderAdaptively(scene, accel, two, a);
    EXPECT_EQ(r1.acc.count, r2.acc.count);
    EXPECT_EQ(r1.acc.sum, r2.acc.sum);
    EXPECT_EQ(r1.last.number, r2.last.number);
    EXPECT_GT(r1.last.number, 1);
}

// Half the difference of a pixel's two halves, d, has E[d^2] = the squared error of the pixel's
// mean: checked on the two pixels with exact values (a triangle edge, a penumbra) over 600 seeds.
// Tolerance: each mean of 600 squared normals has a relative standard deviation
// of sqrt(2/600) = 5.8%, their ratio about 8%; [0.75, 1.33] is 3.5 of those.
TEST(AdaptiveSampling, TheHalvesEstimateTheSquaredErrorOfExactPixels) {
    const std::pair<const char*, PixelScene> pixels[] = {{"edge", edgePixelScene()}, {"penumbra", penumbraPixelScene()}};
    for (const auto& [name, pixel] : pixels) {
        const SceneAccel accel = prepareCpuScene(pixel.scene);
        for (std::uint32_t n : {16u, 64u}) {
            double estimated = 0.0, actual = 0.0;
            const int seeds = 600;
            for (int s = 0; s < seeds; ++s) {
                RenderOptions o;
                o.width = o.height = 1;
                o.sampler = SamplerKind::Sobol2;
                o.samplesPerPixel = static_cast<int>(n);
                o.seed = 7000u + static_cast<std::uint32_t>(s);
                o.threads = 1;
                o.quiet = true;
                CpuSampleRanges cpu(pixel.scene, accel, o);
                adaptive::PixelAccumulation acc(1, 1, {0, 1});
                cpu.add({n}, acc);
                const glm::dvec3 d = adaptive::halfDifference(acc, 0);
                const glm::dvec3 e = glm::dvec3(acc.mean(0)) - pixel.expected;
                estimated += glm::dot(d, d);
                actual += glm::dot(e, e);
            }
            const double ratio = estimated / actual;
            std::printf("%s pixel, %u samples: estimated / actual squared error %.3f\n", name, n, ratio);
            EXPECT_GT(ratio, 0.75) << name << ", " << n;
            EXPECT_LT(ratio, 1.33) << name << ", " << n;
        }
    }
}

// On a whole image the estimated relative RMSE at the stop is within 0.8-1.25 of the true one,
// measured against a 2048-rpp sobol2 render of the same scene (its own error is 1/sqrt(2048/mean
// rpp) of the adaptive render's at most: about 15%, which adds ~1% in quadrature).
TEST(AdaptiveSampling, TheImageErrorEstimateMatchesTheTrueError) {
    const Scene scene = exampleScene("soft_shadows");
    const SceneAccel accel = prepareCpuScene(scene);
    RenderOptions o = smallOptions(scene, 48);
    adaptive::AdaptiveOptions a;
    a.targetError = 0.01;
    a.maxRpp = 1024;
    const adaptive::AdaptiveResult r = renderAdaptively(scene, accel, o, a);
    o.samplesPerPixel = 2048;
    o.seed = 99;
    const Image reference = renderCpu(scene, accel, o);
    double squares = 0.0, lum = 0.0;
    for (std::size_t p = 0; p < reference.pixels.size(); ++p) {
        const glm::dvec3 e = glm::dvec3(r.acc.mean(p)) - glm::dvec3(reference.pixels[p]);
        squares += glm::dot(e, e);
        lum += adaptive::luminance(glm::dvec3(reference.pixels[p]));
    }
    const double trueError = std::sqrt(squares / (3.0 * reference.pixels.size())) / (lum / reference.pixels.size());
    std::printf("estimated %.5f, true %.5f, ratio %.3f after %d rounds\n", r.estimate.relative(), trueError,
                r.estimate.relative() / trueError, r.last.number);
    EXPECT_EQ(r.stop, adaptive::StopReason::TargetMet);
    EXPECT_LE(r.estimate.relative(), 0.01);
    EXPECT_GT(r.estimate.relative() / trueError, 0.8);
    EXPECT_LT(r.estimate.relative() / trueError, 1.25);
}

// A target no pixel budget can reach stops at --max-rpp, every pixel at or under it, and says so.
TEST(AdaptiveSampling, AnUnreachableTargetStopsAtMaxRpp) {
    const Scene scene = exampleScene("soft_shadows");
    const SceneAccel accel = prepareCpuScene(scene);
    adaptive::AdaptiveOptions a;
    a.targetError = adaptive::kMinTargetError;
    a.minRpp = 4;
    a.maxRpp = 16;
    const adaptive::AdaptiveResult r = renderAdaptively(scene, accel, smallOptions(scene, 24), a);
    EXPECT_EQ(r.stop, adaptive::StopReason::MaxRpp);
    EXPECT_GT(r.estimate.relative(), a.targetError.value());
    for (std::uint32_t c : r.acc.count) EXPECT_EQ(c, 16u);
}

// A time budget alone: rounds until the time is spent (each round sized to fit what is left).
TEST(AdaptiveSampling, ATimeBudgetEndsTheRounds) {
    const Scene scene = exampleScene("soft_shadows");
    const SceneAccel accel = prepareCpuScene(scene);
    adaptive::AdaptiveOptions a;
    a.seconds = 0.3;
    a.maxRpp = 1 << 20;
    const adaptive::AdaptiveResult r = renderAdaptively(scene, accel, smallOptions(scene, 32), a);
    EXPECT_EQ(r.stop, adaptive::StopReason::TimeSpent) << adaptive::stopReasonText(r.stop);
    EXPECT_GE(r.last.seconds, 0.3 * 0.5);  // a round is sized from the rate so far; the last may end early
    EXPECT_GT(r.last.number, 1);
    // The samples follow the noise with a time alone too (not uniform doubling until the time binds).
    EXPECT_GE(r.last.maxCount, 4 * r.last.minCount) << r.last.minCount << "-" << r.last.maxCount;
}

// The allocation: even counts, never fewer than a pixel has, at most double, at most maxRpp, a
// noiseless pixel left alone; the budget's scale adds no more samples than the budget.
TEST(AdaptiveSampling, PlansGrowPixelsWithinTheirBounds) {
    adaptive::PixelAccumulation acc(4, 1, {0, 1});
    acc.count = {16, 16, 64, 16};
    const std::vector<double> sigma{0.0, 1.0, 10.0, 100.0};
    const std::vector<std::uint32_t> plan = adaptive::plannedCounts(acc, sigma, 20.0, 100);
    EXPECT_EQ(plan, (std::vector<std::uint32_t>{16, 20, 100, 32}));
    const double scale = adaptive::scaleForBudget(acc, sigma, 1000, 10.0);
    EXPECT_LE(adaptive::addedSamples(acc, adaptive::plannedCounts(acc, sigma, scale, 1000)), 10u);
    EXPECT_GT(adaptive::addedSamples(acc, adaptive::plannedCounts(acc, sigma, scale * 1.01, 1000)), 0u);
}

TEST(AdaptiveSampling, BadOptionsAreRefusedNamingTheValue) {
    const auto refused = [](adaptive::AdaptiveOptions a, const std::string& expected) {
        try {
            adaptive::checkAdaptiveOptions(a);
            ADD_FAILURE() << "accepted; expected " << expected;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        }
    };
    adaptive::AdaptiveOptions a;
    refused(a, "needs --target-error");
    a.targetError = -0.1;
    refused(a, "--target-error -0.1");
    a.targetError = 1e-6;
    refused(a, "at least 0.0001");
    a.targetError = 0.01;
    a.seconds = std::nan("");
    refused(a, "--time nan");
    a.seconds = 0.0;
    refused(a, "--time 0");
    a.seconds.reset();
    a.minRpp = 15;
    refused(a, "--min-rpp 15: must be an even");
    a.minRpp = 64;
    a.maxRpp = 32;
    refused(a, "--max-rpp 32 is below --min-rpp 64");
}

// The GPU's rounds (render.comp's ADAPTIVE kernel, lavapipe, validation on) against the CPU's: the
// same samples, so the same estimates and counts up to float rounding (FMA on the GPU can move a
// ray across an edge, and a pixel's count across an even step: at most 1% of pixels may differ),
// and images that meet the agreement rule of GPU and CPU renders (<= 0.5% of pixels over 2/255,
// mean <= 0.5/255). Scenes with different paths: area lights, gloss, a dielectric and a mesh.
TEST(AdaptiveSampling, TheGpuRoundsAgreeWithTheCpu) {
    GpuRenderer gpu(GpuRendererOptions{.validation = true});
    for (const char* name : {"soft_shadows", "glossy", "glass_and_instances"}) {
        const Scene scene = exampleScene(name);
        const SceneAccel accel = prepareCpuScene(scene);
        const GpuSceneData data = GpuRenderer::prepare(scene);
        RenderOptions o = smallOptions(scene, 48);
        const adaptive::AdaptiveOptions a = roundsUpTo(0.01, 512, o);
        const adaptive::AdaptiveResult onCpu = renderAdaptively(scene, accel, o, a);
        const adaptive::AdaptiveResult onGpu = adaptive::renderAdaptive(
            o.width, o.height, rowsOf(o), a,
            [&](const std::vector<std::uint32_t>& next, adaptive::PixelAccumulation& acc) { gpu.addSampleRanges(data, o, next, acc); });
        std::size_t sameCount = 0;
        Image cpuImage(o.width, o.height), gpuImage(o.width, o.height);
        for (std::size_t p = 0; p < onCpu.acc.pixels(); ++p) {
            sameCount += onCpu.acc.count[p] == onGpu.acc.count[p];
            cpuImage.pixels[p] = onCpu.acc.mean(p);
            gpuImage.pixels[p] = onGpu.acc.mean(p);
        }
        const ImageDifference d = compareImages(gpuImage, cpuImage);
        std::printf("%s: %d/%d rounds, %.2f%% of counts equal, %.3f%% of pixels over 2/255, mean %.4f/255\n", name,
                    onGpu.last.number, onCpu.last.number, 100.0 * sameCount / onCpu.acc.pixels(), 100.0 * d.fractionOver2,
                    d.meanAbs * 255.0);
        EXPECT_GE(sameCount, onCpu.acc.pixels() * 99 / 100) << name;
        EXPECT_TRUE(meetsAgreementRule(d)) << name;
        EXPECT_GT(onGpu.last.maxCount, onGpu.last.minCount) << name << ": nothing adapted";
    }
    ASSERT_NE(gpu.validationLog(), nullptr);
    EXPECT_EQ(gpu.validationLog()->count(), 0u) << gpu.validationLog()->joined();
}

// The wavefront stages' rounds (waves of work-list entries times sample offsets, the odd sums in
// ACCUMULATE) against the megakernel's: the same shading code adds the same samples in the same
// order, so on lavapipe the same sums and counts bit for bit (elsewhere the two compilations may
// round apart: the agreement rule). A scene without a path stack and one with a dielectric's.
TEST(AdaptiveSampling, TheWavefrontRoundsAreTheMegakernels) {
    GpuRenderer gpu(GpuRendererOptions{.validation = true});
    for (const char* name : {"soft_shadows", "glass_and_instances"}) {
        const Scene scene = exampleScene(name);
        const GpuSceneData data = GpuRenderer::prepare(scene);
        RenderOptions o = smallOptions(scene, 40);
        const adaptive::AdaptiveOptions a = roundsUpTo(0.02, 256, o);
        auto rounds = [&](GpuKernel kernel) {
            return adaptive::renderAdaptive(o.width, o.height, rowsOf(o), a,
                                            [&](const std::vector<std::uint32_t>& next, adaptive::PixelAccumulation& acc) {
                                                GpuRenderStats stats;
                                                gpu.addSampleRanges(data, o, next, acc, &stats, kernel);
                                                EXPECT_EQ(stats.wavefront, kernel == GpuKernel::Wavefront);
                                            });
        };
        const adaptive::AdaptiveResult mega = rounds(GpuKernel::Megakernel);
        const adaptive::AdaptiveResult waves = rounds(GpuKernel::Wavefront);
        EXPECT_GT(waves.last.maxCount, waves.last.minCount) << name << ": nothing adapted";
        if (gpu.deviceInfo().lavapipe) {
            EXPECT_EQ(waves.acc.count, mega.acc.count) << name;
            std::size_t differing = 0;
            for (std::size_t p = 0; p < mega.acc.pixels(); ++p)
                differing += waves.acc.sum[p] != mega.acc.sum[p] || waves.acc.oddSum[p] != mega.acc.oddSum[p];
            EXPECT_EQ(differing, 0u) << name;
        } else {
            Image megaImage(o.width, o.height), waveImage(o.width, o.height);
            for (std::size_t p = 0; p < mega.acc.pixels(); ++p) {
                megaImage.pixels[p] = mega.acc.mean(p);
                waveImage.pixels[p] = waves.acc.mean(p);
            }
            EXPECT_TRUE(meetsAgreementRule(compareImages(waveImage, megaImage))) << name;
        }
    }
    ASSERT_NE(gpu.validationLog(), nullptr);
    EXPECT_EQ(gpu.validationLog()->count(), 0u) << gpu.validationLog()->joined();
}

}  // namespace
}  // namespace vkrt::test
