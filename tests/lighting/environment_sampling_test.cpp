// Importance sampling of the environment map (shaders/shared/environment_sampling.h over
// host/lighting's tables), against closed forms and statistics: the pdf integrates to 1, a sample
// carries the pdf environmentPdf gives its direction, the samples' histogram is the cells'
// probabilities, those follow luminance times solid angle, and an irradiance estimated with them
// agrees with one from uniform directions. Seeds are fixed: each test is deterministic; the
// statistical bounds are for the chosen seeds as much as for any (4 standard errors: p ~ 6e-5).
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "cube_map.h"
#include "environment_distribution.h"
#include "environment_loading.h"
#include "environment_map.h"
#include "environment_sampling.h"
#include "environment_test_maps.h"
#include "test_paths.h"

namespace vkrt::test {
namespace {

constexpr double kFourPi = 4.0 * std::numbers::pi;

double luminance(glm::vec3 c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

// A map with all a sampler can trip on: texels of random brightness, black patches (a black
// quarter of every face and all of -Z: the floors), and a few bright texels (a 'sun') on +Y.
Environment testMap(int n) {
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> byte(0, 255);
    return syntheticEnvironment(n, [&](int face, int x, int y) {
        if (face == 5 || (x < n / 2 && y < n / 2)) return glm::u8vec3(0);
        if (face == 2 && x >= n / 2 && x < n / 2 + 2 && y >= n / 2 && y < n / 2 + 2) return glm::u8vec3(255);
        const int v = byte(rng) / 8;  // dim: the sun outweighs a face
        return glm::u8vec3(v, byte(rng) / 8, v / 2);
    });
}

glm::vec3 uniformSphere(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float z = 1.0f - 2.0f * u(rng);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * std::numbers::pi_v<float> * u(rng);
    return glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
}

struct Mean {
    double sum = 0.0, sumSquares = 0.0;
    long n = 0;
    void add(double x) {
        sum += x;
        sumSquares += x * x;
        ++n;
    }
    double mean() const { return sum / double(n); }
    double standardError() const { return std::sqrt(std::max(0.0, sumSquares / double(n) - mean() * mean()) / double(n)); }
};

// The maps the tests run on: the synthetic one, and the course's where ../shared has them.
struct NamedMap {
    std::string name;
    EnvironmentTexels texels;
};
std::vector<NamedMap> maps() {
    std::vector<NamedMap> out;
    out.push_back({"synthetic 16", borderedEnvironment(testMap(16))});
    out.push_back({"synthetic 100", borderedEnvironment(testMap(100))});  // C = 64 does not divide N
    EnvironmentProblem problem;
    if (auto reef = loadCubeFaceEnvironment(reef2021Prefix(), NegZRule::Measure, problem))
        out.push_back({"reef 2021", borderedEnvironment(*reef)});
    if (auto uffizi = loadVerticalCrossEnvironment(uffiziCross(), problem)) out.push_back({"uffizi", borderedEnvironment(*uffizi)});
    return out;
}

float cellProbability(const EnvironmentDistribution& d, std::uint32_t row, std::uint32_t col) {
    const std::uint32_t rowCdf = envsampling::envRowCdf(d.cells, row);
    return (d.table[row + 1] - d.table[row]) * (d.table[rowCdf + col + 1] - d.table[rowCdf + col]);
}

TEST(EnvironmentSampling, TheTablesAreCdfsEndingAtOne) {
    for (const NamedMap& map : maps()) {
        SCOPED_TRACE(map.name);
        const EnvironmentDistribution d = environmentDistribution(map.texels);
        ASSERT_EQ(d.cells, std::min<std::uint32_t>(map.texels.faceSize, 64u));
        ASSERT_EQ(d.table.size(), envsampling::envTableSize(d.cells));
        const std::uint32_t rows = 6 * d.cells;
        EXPECT_EQ(d.table[0], 0.0f);
        EXPECT_EQ(d.table[rows], 1.0f);
        for (std::uint32_t r = 0; r < rows; ++r) {
            ASSERT_GT(d.table[r + 1], d.table[r]) << r;  // every row can be picked
            const std::uint32_t first = envsampling::envRowCdf(d.cells, r);
            ASSERT_EQ(d.table[first], 0.0f);
            ASSERT_EQ(d.table[first + d.cells], 1.0f);
            for (std::uint32_t c = 0; c < d.cells; ++c) ASSERT_GT(d.table[first + c + 1], d.table[first + c]) << r << " " << c;
        }
    }
}

// The pdf integrates to 1 over the sphere: exactly by quadrature over the faces' (s, t) (16 points
// per cell; the pdf times the Jacobian is constant in a cell, so only float rounding remains), and
// by Monte Carlo over uniform directions, within 4 of its standard errors.
TEST(EnvironmentSampling, ThePdfIntegratesToOneOverTheSphere) {
    for (const NamedMap& map : maps()) {
        SCOPED_TRACE(map.name);
        const EnvironmentDistribution d = environmentDistribution(map.texels);
        const int grid = 4 * static_cast<int>(d.cells);
        double quadrature = 0.0;
        for (std::uint32_t face = 0; face < 6; ++face) {
            for (int y = 0; y < grid; ++y) {
                for (int x = 0; x < grid; ++x) {
                    const glm::vec2 st((x + 0.5f) / grid, (y + 0.5f) / grid);
                    quadrature += double(environmentPdf(d, cubemap::cubeFaceDirection(face, st))) *
                                  double(cubemap::cubeFaceSolidAngleDensity(st)) / double(grid * grid);
                }
            }
        }
        EXPECT_NEAR(quadrature, 1.0, 1e-4);  // ~1.5e5 float products of relative error ~1e-7 each
        std::mt19937 rng(11);
        Mean mc;
        for (int i = 0; i < 400000; ++i) mc.add(double(environmentPdf(d, uniformSphere(rng))) * kFourPi);
        std::printf("%s: quadrature %.6f, Monte Carlo %.4f +- %.4f\n", map.name.c_str(), quadrature, mc.mean(), mc.standardError());
        EXPECT_NEAR(mc.mean(), 1.0, 4.0 * mc.standardError());
    }
}

// A sample's pdf is environmentPdf of its direction: the same cell, the same Jacobian, to float
// rounding (1e-4 relative: a handful of ulp through a division and the Jacobian's power). The
// exception is a direction within rounding of a cell's edge, which environmentPdf may put in the
// neighbouring cell (a u on a stratum's corner can land exactly on one: a regular 512^2 grid of u,
// u = 0 included, mismatched 0.12% of its samples). For random u that has probability
// ~1e-6 per sample: at most 2 of these 262,144 per map (measured: one, on the reef map, its t
// exactly 9/64, on a row edge).
TEST(EnvironmentSampling, ASampleCarriesThePdfOfItsDirection) {
    for (const NamedMap& map : maps()) {
        SCOPED_TRACE(map.name);
        const EnvironmentDistribution d = environmentDistribution(map.texels);
        std::mt19937 rng(17);
        std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
        int mismatched = 0;
        for (int i = 0; i < 262144; ++i) {
            const EnvironmentSample s = sampleEnvironment(d, glm::vec2(uniform(rng), uniform(rng)));
            ASSERT_NEAR(glm::length(s.direction), 1.0f, 1e-6f);
            ASSERT_GT(s.pdf, 0.0f);
            const float pdf = environmentPdf(d, s.direction);
            if (std::fabs(pdf - s.pdf) > 1e-4f * s.pdf) ++mismatched;
        }
        std::printf("%s: %d of 262144 samples' pdfs differ from environmentPdf's\n", map.name.c_str(), mismatched);
        EXPECT_LE(mismatched, 2);
    }
}

// The samples' histogram over each cell's four quarters (in the face's (s, t)) against the cells'
// probabilities from the tables (a quarter each: uniform in (s, t) inside a cell): Pearson's
// chi-square, quarters expecting fewer than 5 samples pooled, under the 1 - 1e-5 quantile of its
// distribution (Wilson-Hilferty). A wrong face, row, column or in-cell mapping puts samples in
// the wrong quarters and gives a chi-square of many thousands.
TEST(EnvironmentSampling, SampledDirectionsFollowTheCellProbabilities) {
    const EnvironmentDistribution d = environmentDistribution(borderedEnvironment(testMap(16)));
    const std::uint32_t c = d.cells;
    const std::size_t bins = 6u * c * c * 4u;
    std::vector<double> expected(bins), observed(bins, 0.0);
    const long samples = 2000000;
    for (std::uint32_t row = 0; row < 6 * c; ++row)
        for (std::uint32_t col = 0; col < c; ++col)
            for (int q = 0; q < 4; ++q) expected[(row * c + col) * 4 + q] = double(cellProbability(d, row, col)) / 4.0 * samples;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (long i = 0; i < samples; ++i) {
        const EnvironmentSample s = sampleEnvironment(d, glm::vec2(uniform(rng), uniform(rng)));
        const cubemap::CubeFacePoint p = cubemap::cubeFacePoint(s.direction);
        const glm::uvec2 half = glm::min(glm::uvec2(p.st * float(2 * c)), glm::uvec2(2 * c - 1));
        const std::uint32_t row = p.face * c + half.y / 2, col = half.x / 2;
        observed[(row * c + col) * 4 + (half.y % 2) * 2 + half.x % 2] += 1.0;
    }
    double chi2 = 0.0, pooledExpected = 0.0, pooledObserved = 0.0;
    int dof = -1;
    for (std::size_t b = 0; b < bins; ++b) {
        if (expected[b] < 5.0) {
            pooledExpected += expected[b];
            pooledObserved += observed[b];
            continue;
        }
        chi2 += (observed[b] - expected[b]) * (observed[b] - expected[b]) / expected[b];
        ++dof;
    }
    if (pooledExpected > 0.0) {
        chi2 += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
        ++dof;
    }
    const double z = 4.265;  // the standard normal's 1 - 1e-5 quantile
    const double k = dof, h = 2.0 / (9.0 * k);
    const double critical = k * std::pow(1.0 - h + z * std::sqrt(h), 3.0);
    std::printf("chi-square %.1f over %d degrees of freedom (critical %.1f; pooled %.1f expected)\n", chi2, dof, critical, pooledExpected);
    EXPECT_LT(chi2, critical);
}

// The cells' probabilities are luminance (Rec. 709) times solid angle: on a map of flat faces,
// a cell whose lookup reads only its own face's texels has P / solid angle proportional to the
// face's luminance, the same for every such cell; a black face keeps a small floor > 0. Tolerance:
// the floors add about 1e-3 of the mean weight to each cell (up to 0.6% of the dimmest face's,
// blue at 0.0722) and the float solid angles 1e-4.
TEST(EnvironmentSampling, CellProbabilitiesAreLuminanceTimesSolidAngle) {
    const glm::u8vec3 colours[6] = {{0, 255, 0}, {0, 0, 255}, {255, 0, 0}, {255, 255, 255}, {128, 128, 128}, {0, 0, 0}};
    const int n = 256;
    const EnvironmentDistribution d =
        environmentDistribution(borderedEnvironment(syntheticEnvironment(n, [&](int face, int, int) { return colours[face]; })));
    const std::uint32_t c = d.cells;
    ASSERT_EQ(c, 64u);
    const double white = luminance(glm::vec3(1.0f));
    const std::uint32_t middle = c / 2;
    const double whitePerSolidAngle =
        cellProbability(d, 3 * c + middle, middle) /
        cubemap::cubeFaceRectSolidAngle(glm::vec2(middle) / float(c), glm::vec2(middle + 1) / float(c));
    ASSERT_GT(whitePerSolidAngle, 0.0);
    for (std::uint32_t face = 0; face < 6; ++face) {
        const double want = luminance(glm::vec3(colours[face]) / 255.0f) / white;
        for (std::uint32_t cy = 1; cy + 1 < c; ++cy) {
            for (std::uint32_t cx = 1; cx + 1 < c; ++cx) {
                const double solidAngle = cubemap::cubeFaceRectSolidAngle(glm::vec2(cx, cy) / float(c), glm::vec2(cx + 1, cy + 1) / float(c));
                const double ratio = cellProbability(d, face * c + cy, cx) / solidAngle / whitePerSolidAngle;
                if (face == 5) {
                    ASSERT_GT(ratio, 0.0);
                    ASSERT_LT(ratio, 5e-3) << cx << " " << cy;  // the floors only
                } else {
                    ASSERT_NEAR(ratio, want, 0.01 * want + 2e-3) << "face " << face << " cell " << cx << " " << cy;
                }
            }
        }
    }
}

// On a uniform map the pdf is nearly uniform over the sphere: the cell weights carry the solid
// angle (without it a face's corner cells, which see 0.19 of the solid angle of its centre cells
// per unit of (s, t), would be sampled as often, and the pdf would vary 5-fold). What remains is
// the Jacobian's variation inside a cell (up to 6% across a corner cell of a 64-cell face) and
// the floors.
TEST(EnvironmentSampling, AUniformMapIsSampledAlmostUniformly) {
    const EnvironmentDistribution d =
        environmentDistribution(borderedEnvironment(syntheticEnvironment(64, [](int, int, int) { return glm::u8vec3(90); })));
    std::mt19937 rng(5);
    for (int i = 0; i < 100000; ++i) {
        const float pdf = environmentPdf(d, uniformSphere(rng));
        ASSERT_NEAR(pdf * kFourPi, 1.0, 0.07);
    }
}

// The irradiance at a normal, E(n) = integral of L(w) max(0, n.w) dw, estimated from the
// environment's samples (L cos / pdf) and from uniform directions (L cos 4 pi): the two agree
// within 4 of their combined standard errors, for six normals on each map (luminance of L).
TEST(EnvironmentSampling, ImportanceSampledIrradianceAgreesWithUniformSampling) {
    const glm::vec3 normals[] = {{1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, -1}, glm::normalize(glm::vec3(1, 1, 1)),
                                 glm::normalize(glm::vec3(-1, 0.3f, 0.5f))};
    for (const NamedMap& map : maps()) {
        const EnvironmentDistribution d = environmentDistribution(map.texels);
        for (const glm::vec3 n : normals) {
            std::mt19937 rng(13);
            std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
            Mean importance, plain;
            for (int i = 0; i < 200000; ++i) {
                const EnvironmentSample s = sampleEnvironment(d, glm::vec2(uniform(rng), uniform(rng)));
                importance.add(luminance(environmentRadiance(map.texels, s.direction)) * std::max(0.0f, glm::dot(n, s.direction)) / s.pdf);
                const glm::vec3 w = uniformSphere(rng);
                plain.add(luminance(environmentRadiance(map.texels, w)) * std::max(0.0f, glm::dot(n, w)) * kFourPi);
            }
            const double se = std::sqrt(importance.standardError() * importance.standardError() + plain.standardError() * plain.standardError());
            std::printf("%s n=(%.2f %.2f %.2f): importance %.5f +- %.5f, uniform %.5f +- %.5f\n", map.name.c_str(), n.x, n.y, n.z,
                        importance.mean(), importance.standardError(), plain.mean(), plain.standardError());
            EXPECT_NEAR(importance.mean(), plain.mean(), 4.0 * se) << map.name << " normal " << n.x << " " << n.y << " " << n.z;
        }
    }
}

}  // namespace
}  // namespace vkrt::test
