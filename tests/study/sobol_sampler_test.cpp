// The Owen-scrambled Sobol sampler of shaders/shared/sampling.h, checked against independent
// computations: the Sobol generator by its direction-number recurrence, the (0, m, 2)-net property
// by counting points per elementary interval, the scramble's nesting and randomness by flipping
// bits, and the decorrelation of dimensions by sample correlations.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "sampling.h"

namespace vkrt::test {
namespace {

using gpu::uint;

uint naiveReverse(uint x) {
    uint r = 0;
    for (int b = 0; b < 32; ++b)
        if (x & (1u << b)) r |= 1u << (31 - b);
    return r;
}

TEST(SobolSampler, ReverseBitsMatchesABitLoop) {
    std::mt19937 rng(1);
    for (int i = 0; i < 10000; ++i) {
        const uint x = static_cast<uint>(rng());
        ASSERT_EQ(sampling::reverseBits32(x), naiveReverse(x)) << x;
    }
}

// Sobol dimension 1 (primitive polynomial x + 1, m_1 = 1): direction numbers v_1 = 1/2 and
// v_{k+1} = v_k xor v_k / 2; point i is the xor of v_k over the set bits k of i.
TEST(SobolSampler, DimensionOneMatchesTheDirectionNumberRecurrence) {
    for (uint i = 0; i < (1u << 16); ++i) {
        uint expected = 0, v = 1u << 31;
        for (int b = 0; b < 32; ++b) {
            if ((i >> b) & 1u) expected ^= v;
            v ^= v >> 1;
        }
        ASSERT_EQ(naiveReverse(sampling::sobolDim1Reversed(i)), expected) << "index " << i;
    }
    // And the start of the sequence in natural (not Gray-code) order, by hand from v = 1/2, 3/4, 5/8:
    // 0, v1, v2, v1^v2, v3, v1^v3, v2^v3, v1^v2^v3.
    const double start[8] = {0.0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
    for (uint i = 0; i < 8; ++i) EXPECT_EQ(naiveReverse(sampling::sobolDim1Reversed(i)) / 4294967296.0, start[i]);
}

// The first 2^m samples of any pixel, dimension and seed put exactly one point in every elementary
// interval [a 2^-k, (a+1) 2^-k) x [b 2^-(m-k), (b+1) 2^-(m-k)), for every k: a (0, m, 2)-net.
TEST(SobolSampler, FirstPowerOfTwoSamplesFormA02Net) {
    for (uint m = 0; m <= 8; ++m) {
        const uint n = 1u << m;
        for (uint pixel : {0u, 1u, 77u, 123456u})
            for (uint dim : {sampling::DIM_CAMERA, sampling::dimLight(0, 0), sampling::dimGloss(0), sampling::dimLight(3, 2)})
                for (uint seed : {0u, 12345u}) {
                    std::vector<gpu::vec2> points;
                    for (uint i = 0; i < n; ++i) points.push_back(sampling::sobolSample2D(pixel, i, dim, seed));
                    for (uint k = 0; k <= m; ++k) {
                        std::vector<int> count(n, 0);
                        for (const gpu::vec2& p : points) {
                            ASSERT_GE(p.x, 0.0f);
                            ASSERT_LT(p.x, 1.0f);
                            ASSERT_GE(p.y, 0.0f);
                            ASSERT_LT(p.y, 1.0f);
                            const uint a = static_cast<uint>(std::ldexp(p.x, static_cast<int>(k)));
                            const uint b = static_cast<uint>(std::ldexp(p.y, static_cast<int>(m - k)));
                            ++count[(a << (m - k)) | b];
                        }
                        for (uint c = 0; c < n; ++c)
                            ASSERT_EQ(count[c], 1) << "m " << m << " k " << k << " pixel " << pixel << " dim " << dim
                                                   << " seed " << seed << " interval " << c;
                    }
                }
    }
}

// The index shuffle (Owen scrambling of the index, most significant bit first) maps [0, 2^m) onto
// one aligned block of 2^m indices: the sample sets are nets, in an order private to the pixel.
TEST(SobolSampler, IndexShuffleIsABijectionOntoAnAlignedBlock) {
    std::mt19937 rng(2);
    for (uint m : {1u, 4u, 10u}) {
        for (int trial = 0; trial < 20; ++trial) {
            const uint key = static_cast<uint>(rng());
            std::set<uint> low;
            std::set<uint> high;
            for (uint i = 0; i < (1u << m); ++i) {
                const uint s = sampling::reverseBits32(sampling::owenScrambleReversed(sampling::reverseBits32(i), key));
                low.insert(s & ((1u << m) - 1u));
                high.insert(s >> m);
            }
            EXPECT_EQ(low.size(), 1u << m);
            EXPECT_EQ(high.size(), 1u);
        }
    }
}

// Owen scrambling flips digit k by a random bit chosen per prefix of digits 0..k-1. So flipping
// input digit j must never change output digits before j, must always flip digit j itself, and
// (over random inputs and keys) must flip each later digit with probability 1/2. 20000 trials give
// a standard error of 0.0035 per frequency; 0.02 is ~6 of them (496 pairs checked).
TEST(SobolSampler, ScrambleIsNestedAndItsFlipsAreFair) {
    std::mt19937 rng(3);
    constexpr int kTrials = 20000;
    std::vector<int> flips(32 * 32, 0);
    for (int t = 0; t < kTrials; ++t) {
        const uint x = static_cast<uint>(rng()), key = static_cast<uint>(rng());
        const uint y = sampling::owenScrambleReversed(x, key);
        for (int j = 0; j < 32; ++j) {
            const uint d = y ^ sampling::owenScrambleReversed(x ^ (1u << j), key);
            ASSERT_EQ(d & ((2u << j) - 1u), 1u << j) << "digit " << j << " changed an earlier digit or not itself";
            for (int k = j + 1; k < 32; ++k) flips[j * 32 + k] += (d >> k) & 1u;
        }
    }
    for (int j = 0; j < 32; ++j)
        for (int k = j + 1; k < 32; ++k)
            EXPECT_NEAR(flips[j * 32 + k] / double(kTrials), 0.5, 0.02) << "input digit " << j << ", output digit " << k;
}

// Sample i of two different dimensions of a pixel must be independent (otherwise pixel and light
// samples would be paired, Cook 1984): the correlation of their coordinates over 256k pairs has a
// standard error of 0.002; 0.01 is 5 of them. Neighbouring pixels must not repeat each other either.
TEST(SobolSampler, DimensionsAndPixelsAreDecorrelated) {
    const uint dims[] = {sampling::DIM_CAMERA, sampling::dimLight(0, 0), sampling::dimLight(0, 1), sampling::dimGloss(0), sampling::dimLight(1, 0)};
    constexpr int kPixels = 4096, kSamples = 64;
    auto correlation = [&](auto first, auto second) {
        double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
        const double n = double(kPixels) * kSamples;
        for (uint p = 0; p < kPixels; ++p)
            for (uint i = 0; i < kSamples; ++i) {
                const double a = first(p, i), b = second(p, i);
                sa += a;
                sb += b;
                saa += a * a;
                sbb += b * b;
                sab += a * b;
            }
        return (sab / n - sa / n * sb / n) / std::sqrt((saa / n - sa * sa / n / n) * (sbb / n - sb * sb / n / n));
    };
    for (uint d1 = 0; d1 < 5; ++d1)
        for (uint d2 = d1 + 1; d2 < 5; ++d2) {
            const double rx = correlation([&](uint p, uint i) { return sampling::sobolSample2D(p, i, dims[d1], 7).x; },
                                          [&](uint p, uint i) { return sampling::sobolSample2D(p, i, dims[d2], 7).x; });
            const double ry = correlation([&](uint p, uint i) { return sampling::sobolSample2D(p, i, dims[d1], 7).y; },
                                          [&](uint p, uint i) { return sampling::sobolSample2D(p, i, dims[d2], 7).x; });
            EXPECT_LT(std::abs(rx), 0.01) << "dims " << dims[d1] << ", " << dims[d2];
            EXPECT_LT(std::abs(ry), 0.01) << "dims " << dims[d1] << ", " << dims[d2];
        }
    const double pixels = correlation([&](uint p, uint i) { return sampling::sobolSample2D(p, i, sampling::DIM_CAMERA, 7).x; },
                                      [&](uint p, uint i) { return sampling::sobolSample2D(p + 1, i, sampling::DIM_CAMERA, 7).x; });
    EXPECT_LT(std::abs(pixels), 0.01);
    const double seeds = correlation([&](uint p, uint i) { return sampling::sobolSample2D(p, i, sampling::DIM_CAMERA, 7).x; },
                                     [&](uint p, uint i) { return sampling::sobolSample2D(p, i, sampling::DIM_CAMERA, 8).x; });
    EXPECT_LT(std::abs(seeds), 0.01);
}

// sample2D dispatches SAMPLER_SOBOL to it, for any count (the grid is not used).
TEST(SobolSampler, Sample2DUsesItForTheSobolKind) {
    for (uint count : {1u, 3u, 16u, 48u})
        for (uint i = 0; i < count; ++i) {
            const gpu::vec2 a = sampling::sample2D(gpu::SAMPLER_SOBOL, sampling::makeSampleGrid(count), 5, i, sampling::dimLight(0, 0), 3);
            const gpu::vec2 b = sampling::sobolSample2D(5, i, sampling::dimLight(0, 0), 3);
            EXPECT_EQ(a, b);
        }
}

// Issue 21: the shutter time is a 1D sample (sample1D) every sampler supplies. Jittered and regular
// put exactly one of a pixel's n samples in each of n strata of [0, 1) (not one per grid column),
// in an order shuffled per pixel; sobol's first n = 2^m samples do the same (van der Corput);
// random is uniform (mean 1/2 over many samples); every value is in [0, 1).
TEST(SobolSampler, TheOneDimensionalSampleIsStratifiedForEverySampler) {
    for (const uint kind : {gpu::SAMPLER_JITTERED, gpu::SAMPLER_REGULAR, gpu::SAMPLER_SOBOL}) {
        for (const uint count : {1u, 4u, 16u, 64u, 256u}) {
            const gpu::uvec4 grid = sampling::makeSampleGrid(count);
            for (const uint pixel : {0u, 7u, 12345u}) {
                std::set<uint> strata;
                std::vector<uint> order;
                for (uint i = 0; i < count; ++i) {
                    const float t = sampling::sample1D(kind, grid, pixel, i, sampling::DIM_TIME, 9);
                    ASSERT_GE(t, 0.0f);
                    ASSERT_LT(t, 1.0f);
                    strata.insert(static_cast<uint>(t * static_cast<float>(count)));
                    order.push_back(static_cast<uint>(t * static_cast<float>(count)));
                }
                EXPECT_EQ(strata.size(), count) << "sampler " << kind << ", " << count << " samples, pixel " << pixel;
                if (count >= 16 && kind != gpu::SAMPLER_SOBOL) {
                    // Shuffled: the strata are not visited in index order (the pixel strata's).
                    std::vector<uint> sorted = order;
                    std::sort(sorted.begin(), sorted.end());
                    EXPECT_NE(order, sorted) << "sampler " << kind << ", pixel " << pixel;
                }
            }
        }
    }
    double mean = 0.0;
    for (uint i = 0; i < 65536; ++i) mean += sampling::sample1D(gpu::SAMPLER_RANDOM, sampling::makeSampleGrid(65536), 3, i, sampling::DIM_TIME, 1);
    EXPECT_NEAR(mean / 65536.0, 0.5, 0.005);  // sd of the mean 1/sqrt(12 * 65536) = 0.0011
}

}  // namespace
}  // namespace vkrt::test
