// Convergence of the samplers on pixels with exact values (study_scenes.h), CPU reference.
// Each RMSE pools 400 seeds: its relative standard error is about 1/sqrt(2*400) = 3.5%, so the
// tolerances below (a slope within 0.1, ratios with 25%+ margins) hold with a wide margin for any
// correct sampler, and the fixed seeds make every run identical.
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "convergence_fit.h"
#include "pixel_study.h"
#include "study_renderer.h"

namespace vkrt::test {
namespace {

constexpr int kSeeds = 400;

TEST(SamplerConvergence, RandomErrorOnAnEdgePixelFallsAsOneOverSqrtN) {
    const PixelScene scene = edgePixelScene();
    const PixelStudy study(scene);
    std::vector<double> rpps, errors;
    for (int rpp : {1, 4, 16, 64, 256, 1024}) {
        rpps.push_back(rpp);
        errors.push_back(study.rmse(SamplerKind::Random, rpp, kSeeds));
        std::printf("random edge %5d rpp: rmse %.5f\n", rpp, errors.back());
    }
    const study::LogLogFit fit = study::fitLogLog(rpps, errors);
    ASSERT_TRUE(fit.valid);
    std::printf("random edge slope %.3f\n", fit.slope);
    EXPECT_NEAR(fit.slope, -0.5, 0.1);
}

// Jittered sampling stratifies the pixel (edge) and the light (penumbra): at equal rpp its error
// must be clearly below random's (theory: ~N^-0.75 vs N^-0.5, a ratio of 0.5 at 16 rpp).
TEST(SamplerConvergence, JitteredBeatsRandomOnEdgeAndPenumbraPixels) {
    const PixelScene edge = edgePixelScene();
    const PixelScene penumbra = penumbraPixelScene();
    for (const PixelScene* scene : {&edge, &penumbra}) {
        const PixelStudy study(*scene);
        for (int rpp : {16, 64}) {
            const double random = study.rmse(SamplerKind::Random, rpp, kSeeds);
            const double jittered = study.rmse(SamplerKind::Jittered, rpp, kSeeds);
            std::printf("%s %3d rpp: random %.5f jittered %.5f (ratio %.2f)\n", scene == &edge ? "edge" : "penumbra", rpp,
                        random, jittered, jittered / random);
            EXPECT_LT(jittered, 0.75 * random) << (scene == &edge ? "edge" : "penumbra") << " pixel, " << rpp << " rpp";
        }
    }
}

// Owen-scrambled Sobol points are (0,m,2)-nets: at least as stratified as a jittered grid, so at
// equal rpp the error must not exceed jittered's (beyond the ratio's ~5% noise; measured: 0.9).
TEST(SamplerConvergence, SobolIsNotWorseThanJittered) {
    const PixelScene edge = edgePixelScene();
    const PixelScene penumbra = penumbraPixelScene();
    for (const PixelScene* scene : {&edge, &penumbra}) {
        const PixelStudy study(*scene);
        for (int rpp : {16, 64, 256}) {
            const double jittered = study.rmse(SamplerKind::Jittered, rpp, kSeeds);
            const double sobol = study.rmse(SamplerKind::Sobol, rpp, kSeeds);
            std::printf("%s %3d rpp: jittered %.5f sobol %.5f (ratio %.2f)\n", scene == &edge ? "edge" : "penumbra", rpp,
                        jittered, sobol, sobol / jittered);
            EXPECT_LE(sobol, 1.15 * jittered) << (scene == &edge ? "edge" : "penumbra") << " pixel, " << rpp << " rpp";
        }
    }
}

// The slopes of every sampler on both pixels, for docs/SAMPLING.md; asserted loosely: stratified
// samplers must converge faster than random's -0.5.
TEST(SamplerConvergence, StratifiedSamplersConvergeFasterThanRandom) {
    const PixelScene edge = edgePixelScene();
    const PixelScene penumbra = penumbraPixelScene();
    for (const PixelScene* scene : {&edge, &penumbra}) {
        const PixelStudy study(*scene);
        for (SamplerKind sampler : {SamplerKind::Random, SamplerKind::Jittered, SamplerKind::Sobol}) {
            std::vector<double> rpps, errors;
            for (int rpp : {4, 16, 64, 256}) {
                rpps.push_back(rpp);
                errors.push_back(study.rmse(sampler, rpp, 100));
            }
            const study::LogLogFit fit = study::fitLogLog(rpps, errors);
            ASSERT_TRUE(fit.valid);
            std::printf("%s %s slope %.3f\n", scene == &edge ? "edge" : "penumbra", study::samplerName(sampler).c_str(), fit.slope);
            if (sampler != SamplerKind::Random) {
                EXPECT_LT(fit.slope, -0.6);
            }
        }
    }
}

}  // namespace
}  // namespace vkrt::test
