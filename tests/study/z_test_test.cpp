// The z-test (host/study/z_test.h) on images whose z values are known by construction, and the
// small numeric pieces the sweep rests on: error metrics and the log-log fit.
#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "convergence_fit.h"
#include "error_metrics.h"
#include "z_test.h"

namespace vkrt::test {
namespace {

Image filled(int w, int h, float v) {
    Image image(w, h);
    for (glm::vec3& p : image.pixels) p = glm::vec3(v);
    return image;
}

TEST(ZTest, SidakLevelAndZLimitFollowTheirDefinitions) {
    const Image a = filled(64, 64, 0.0f);
    const study::ZTestResult r = study::zTest(a, a, filled(64, 64, 1.0f));
    const double n = 64.0 * 64.0 * 3.0;
    EXPECT_EQ(r.values, 64u * 64u * 3u);
    EXPECT_NEAR(r.levelPerValue, 1.0 - std::pow(1.0 - 0.01, 1.0 / n), 1e-12);
    EXPECT_NEAR(std::erfc(r.zLimit / std::sqrt(2.0)), r.levelPerValue, 1e-6 * r.levelPerValue);
    EXPECT_TRUE(r.pass);
    EXPECT_EQ(r.passed, r.values);
}

// 100x100 pixels = 30000 values; 99.75% must pass, i.e. at most 75 may fail.
TEST(ZTest, PassesUpToAQuarterPercentOfFailingValues) {
    const Image reference = filled(100, 100, 0.0f);
    const Image variance = filled(100, 100, 1.0f);
    auto withOutliers = [&](int count) {
        Image a = reference;
        for (int k = 0; k < count; ++k) a.pixels[static_cast<std::size_t>(k)].r = 10.0f;  // z = 10
        return study::zTest(a, reference, variance);
    };
    const study::ZTestResult some = withOutliers(75);
    EXPECT_EQ(some.passed, 30000u - 75u);
    EXPECT_TRUE(some.pass);
    const study::ZTestResult many = withOutliers(76);
    EXPECT_EQ(many.passed, 30000u - 76u);
    EXPECT_FALSE(many.pass);
    EXPECT_EQ(many.map.pixels[0], glm::vec3(1.0f, 0.0f, 0.0f));  // failing values are red in the map
}

TEST(ZTest, EachValueIsJudgedAgainstTheZLimit) {
    const Image reference = filled(8, 8, 0.5f);
    const Image variance = filled(8, 8, 0.04f);  // sd 0.2
    const double limit = study::zTest(reference, reference, variance).zLimit;
    Image inside = reference, outside = reference;
    inside.pixels[3].g += static_cast<float>(0.99 * limit * 0.2);
    outside.pixels[3].g += static_cast<float>(1.01 * limit * 0.2);
    study::ZTestOptions strict;
    strict.passFraction = 1.0;
    EXPECT_TRUE(study::zTest(inside, reference, variance, strict).pass);
    EXPECT_FALSE(study::zTest(outside, reference, variance, strict).pass);
}

TEST(ZTest, VarianceFloorAndNonFiniteValues) {
    const Image reference = filled(4, 4, 0.25f);
    const Image zero = filled(4, 4, 0.0f);
    study::ZTestOptions strict;
    strict.passFraction = 1.0;
    Image rounding = reference;
    rounding.pixels[0].r += 1e-5f;  // float rounding between devices: z = 0.1 with the 1e-8 floor
    EXPECT_TRUE(study::zTest(rounding, reference, zero, strict).pass);
    Image real = reference;
    real.pixels[0].r += 1e-3f;  // z = 10
    EXPECT_FALSE(study::zTest(real, reference, zero, strict).pass);
    Image nan = reference;
    nan.pixels[1].b = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FALSE(study::zTest(nan, reference, filled(4, 4, 1.0f), strict).pass);
    EXPECT_THROW(study::zTest(reference, filled(4, 5, 0.25f), zero), std::invalid_argument);
}

TEST(ZTest, StatisticsOverSeedsAreTheMeanAndTheVarianceOfTheMean) {
    std::vector<Image> renders = {filled(2, 2, 1.0f), filled(2, 2, 2.0f), filled(2, 2, 6.0f)};
    const study::SeedStatistics s = study::statisticsOverSeeds(renders);
    // mean 3, sample variance ((1-3)^2 + (2-3)^2 + (6-3)^2) / 2 = 7, of the mean 7/3.
    EXPECT_FLOAT_EQ(s.mean.pixels[2].g, 3.0f);
    EXPECT_FLOAT_EQ(s.varianceOfMean.pixels[2].g, 7.0f / 3.0f);
    EXPECT_THROW(study::statisticsOverSeeds({filled(2, 2, 1.0f)}), std::invalid_argument);
}

TEST(ErrorMetrics, RmseRelMseAndMaskedRegions) {
    Image reference = filled(2, 2, 0.5f);
    Image image = reference;
    image.pixels[0] += glm::vec3(0.3f, 0.0f, 0.0f);  // one value off by 0.3 among 12
    study::RegionMasks masks;
    masks.width = 2;
    masks.height = 2;
    masks.edge = {1, 0, 0, 0};
    masks.penumbra = {0, 1, 1, 0};
    masks.gloss = {0, 0, 0, 0};
    masks.defocus = {1, 1, 0, 0};
    masks.motion = {0, 0, 0, 1};
    masks.indirect = {1, 0, 0, 1};
    masks.emitter = {0, 0, 0, 0};
    const study::ErrorMetrics e = study::measureError(image, reference, masks);
    EXPECT_NEAR(e.rmse, std::sqrt(0.09 / 12.0), 1e-7);
    EXPECT_NEAR(e.rmseEdge, std::sqrt(0.09 / 3.0), 1e-7);
    EXPECT_EQ(e.rmsePenumbra, 0.0);
    EXPECT_TRUE(std::isnan(e.rmseGloss));
    EXPECT_NEAR(e.rmseDefocus, std::sqrt(0.09 / 6.0), 1e-7);
    EXPECT_EQ(e.rmseMotion, 0.0);
    EXPECT_NEAR(e.rmseIndirect, std::sqrt(0.09 / 6.0), 1e-7);
    EXPECT_TRUE(std::isnan(e.rmseEmitter));
    EXPECT_NEAR(e.relMse, 0.09 / (0.25 + study::kRelMseEpsilon) / 12.0, 1e-7);
}

TEST(ConvergenceFit, RecoversAPowerLawAndRejectsDegenerateInput) {
    std::vector<double> x, y;
    for (double n : {1.0, 4.0, 16.0, 64.0}) {
        x.push_back(n);
        y.push_back(0.3 * std::pow(n, -0.75));
    }
    const study::LogLogFit fit = study::fitLogLog(x, y);
    ASSERT_TRUE(fit.valid);
    EXPECT_NEAR(fit.slope, -0.75, 1e-12);
    EXPECT_NEAR(std::exp(fit.intercept), 0.3, 1e-12);
    EXPECT_FALSE(study::fitLogLog({4.0, 4.0}, {1.0, 2.0}).valid);
    EXPECT_FALSE(study::fitLogLog({4.0, 16.0}, {1.0, 0.0}).valid);  // a zero error has no logarithm
}

}  // namespace
}  // namespace vkrt::test
