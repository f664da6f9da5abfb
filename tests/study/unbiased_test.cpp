// Every sampler but `regular` is unbiased: the mean over many seeds converges to the exact value.
// Pixel level: exact values (study_scenes.h), the mean's standard error from the seeds' spread.
// Image level: the z-test (z_test.h) of the mean over seeds against a high-rpp CPU reference, with
// Mitsuba 3's variance (the reference's per-sample variance over the samples of each side).
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "cpu_renderer.h"
#include "pixel_study.h"
#include "scene_accel.h"
#include "study_renderer.h"
#include "z_test.h"

namespace vkrt::test {
namespace {

// 4.5 standard errors: a correct sampler passes each of these checks with probability 1 - 7e-6,
// while a bias of a few percent of the pixel value (what a broken stratum map or a sample outside
// [0,1) would give) is many standard errors at 400 seeds.
constexpr double kSigmas = 4.5;
constexpr int kSeeds = 400;

TEST(Unbiased, MeanOverSeedsConvergesToTheExactPixel) {
    const PixelScene edge = edgePixelScene();
    const PixelScene penumbra = penumbraPixelScene();
    for (const PixelScene* scene : {&edge, &penumbra}) {
        const PixelStudy study(*scene);
        for (SamplerKind sampler : {SamplerKind::Random, SamplerKind::Jittered, SamplerKind::Sobol, SamplerKind::Sobol2})
            for (int rpp : {1, 3, 4, 16}) {
                glm::dvec3 sum(0.0), sumSq(0.0);
                for (int s = 0; s < kSeeds; ++s) {
                    const glm::dvec3 v = study.render(sampler, rpp, 5000u + static_cast<std::uint32_t>(s));
                    sum += v;
                    sumSq += v * v;
                }
                const glm::dvec3 mean = sum / double(kSeeds);
                const glm::dvec3 variance = (sumSq - sum * mean) / double(kSeeds - 1);
                for (int c = 0; c < 3; ++c) {
                    const double standardError = std::sqrt(std::max(variance[c], 0.0) / kSeeds);
                    EXPECT_LE(std::abs(mean[c] - study.expected()[c]), kSigmas * standardError + 1e-6)
                        << (scene == &edge ? "edge" : "penumbra") << " pixel, " << study::samplerName(sampler) << ", "
                        << rpp << " rpp, channel " << c << ": mean " << mean[c] << " vs exact " << study.expected()[c];
                }
            }
    }
}

struct ImageCheck {
    double passedFraction = 0.0;
    bool pass = false;
};

// The mean of `seeds` CPU renders at `rpp` against a 1024-rpp sobol reference (other seeds).
ImageCheck meanAgainstReference(const Scene& scene, SamplerKind sampler, int rpp, int seeds) {
    const SceneAccel accel = prepareCpuScene(scene);
    RenderOptions o;
    o.width = 32;
    o.height = 24;
    o.camera = scene.defaultCamera;
    o.quiet = true;
    o.sampler = SamplerKind::Sobol;
    o.samplesPerPixel = 1024;
    o.seed = 999;
    Image sampleVariance;
    const Image reference = renderCpu(scene, accel, o, nullptr, &sampleVariance);

    o.sampler = sampler;
    o.samplesPerPixel = rpp;
    Image mean(o.width, o.height);
    for (int s = 0; s < seeds; ++s) {
        o.seed = static_cast<std::uint32_t>(s);
        const Image image = renderCpu(scene, accel, o);
        for (std::size_t k = 0; k < mean.pixels.size(); ++k) mean.pixels[k] += image.pixels[k] / float(seeds);
    }
    const Image variance =
        study::sumImages(study::varianceOfMean(sampleVariance, rpp * seeds), study::varianceOfMean(sampleVariance, 1024));
    const study::ZTestResult z = study::zTest(mean, reference, variance);
    return {z.passedFraction(), z.pass};
}

TEST(Unbiased, MeanOverSeedsPassesTheZTestOnExampleScenes) {
    for (const char* name : {"soft_shadows", "glossy"}) {
        const Scene scene = exampleScene(name);
        for (SamplerKind sampler : {SamplerKind::Random, SamplerKind::Jittered, SamplerKind::Sobol}) {
            const ImageCheck c = meanAgainstReference(scene, sampler, 4, 16);
            std::printf("%s %s: %.3f%% of values pass\n", name, study::samplerName(sampler).c_str(), 100.0 * c.passedFraction);
            EXPECT_TRUE(c.pass) << name << ", " << study::samplerName(sampler) << ": " << 100.0 * c.passedFraction << "%";
        }
    }
}

// The regular sampler is a fixed pattern (stratum centres), not a random estimator: averaging seeds
// does not remove its error. At 4 rpp the edge pixel's samples are (+-0.25, +-0.25); the line
// y = 0.3 x + 0.1 has the two upper ones above it, so every seed gives 0.5 x background instead of
// the exact 0.4 x background, and the z-test (with the seeds' spread, zero here) must reject it.
TEST(Unbiased, RegularSamplerIsBiasedAndTheZTestSeesIt) {
    const PixelScene edge = edgePixelScene();
    const PixelStudy study(edge);
    std::vector<Image> renders;
    for (int s = 0; s < 16; ++s) {
        Image image(1, 1);
        image.pixels[0] = glm::vec3(study.render(SamplerKind::Regular, 4, 7000u + static_cast<std::uint32_t>(s)));
        renders.push_back(image);
    }
    const study::SeedStatistics stats = study::statisticsOverSeeds(renders);
    const glm::dvec3 regularValue = 0.5 * glm::dvec3(edge.scene.background);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(stats.mean.pixels[0][c], regularValue[c], 1e-6) << "channel " << c;
    Image exact(1, 1);
    exact.pixels[0] = glm::vec3(edge.expected);
    EXPECT_FALSE(study::zTest(stats.mean, exact, stats.varianceOfMean).pass);
}

}  // namespace
}  // namespace vkrt::test
