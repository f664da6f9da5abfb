// Scale and translation invariance (issue 7): the invariance scene moved with its camera by
// x -> s*x + T must render the image it renders at s = 1, T = 0, on the CPU and on the GPU.
//
// Tolerance, and why. Moving the scene rounds every coordinate once (a user typing the scaled
// scene), and the camera basis and every intersection are then computed on different floats, so a
// sample that lies within a few ULPs of a silhouette, a shadow edge or a refracted edge may fall on
// the other side. Such a flip changes one of the 4 samples of a pixel: up to 1/4 of the contrast
// across that edge (35/255 here), in isolated pixels. So, as for CPU vs GPU: >= 99.5% of pixels
// within 2/255 and a mean difference <= 0.5/255; and, to catch shadow acne and light leaks, which
// are sparse too but appear where nothing moves, no pixel may differ by more than 2/255 inside
// regions that are smooth in the reference (region_checks.h).
//
// What is representable. Two float limits bound the transforms that can keep the image:
//   - the resolution of a coordinate, 2^-24 |T| (half an ULP), must stay far below a pixel's
//     footprint (~0.1 s here): always true for T/s <= 1e5;
//   - the ray offset, 2^-20 of the hit's magnitude ~ 1e-6 (T + 5 s) (RENDERING.md §6), must stay
//     below the smallest gap the image depends on (0.05 s here: the block before its wall, the
//     tile above the floor) and must not visibly move refractions: true for T/s <= 1e3.
// So every scale is tested at T = 0, and translations are combined with scales up to T/s = 1e3
// (1e5 from the origin needs s >= 1e2; a 1e-4-sized scene can move at most 0.1). Beyond that
// (T/s = 1e4 and 1e5, e.g. this unit-sized scene 1e5 from the origin, where a float step is 1/128
// of a unit) the image is not expected to match: those cases are still rendered and checked for
// NaN/Inf and gross breakage, and the acne test (acne_test.cpp) holds there too.
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "both_paths.h"
#include "invariance_scene.h"
#include "region_checks.h"
#include "scene_transform.h"

namespace vkrt::stability {
namespace {

// 64x64 at 4 samples: enough pixels for silhouettes, shadows, a glossy and a refracted image.
RenderOptions invarianceOptions() { return smallOptions(64, 64, 4); }

// The reference image on both paths, rendered once per process (each test here is its own process
// under ctest; the reference costs ~0.3 s).
const BothImages& reference() {
    static const BothImages images = renderBoth(invarianceScene(), invarianceOptions());
    return images;
}

struct Comparison {
    Distance cpu, gpu, gpuVsCpu;
    SmoothRegionResult cpuSmooth, gpuSmooth;
};

Comparison renderMoved(const Placement& p) {
    const BothImages& ref = reference();
    const BothImages moved = renderBoth(transformed(invarianceScene(), p.transform), invarianceOptions());
    Comparison c;
    c.cpu = distance(moved.cpu, ref.cpu);
    c.gpu = distance(moved.gpu, ref.gpu);
    c.gpuVsCpu = distance(moved.gpu, moved.cpu);
    // Smooth: every 3x3 neighbour within 3/255 of the centre in the reference.
    c.cpuSmooth = compareSmoothRegions(ref.cpu, moved.cpu, 3, 2);
    c.gpuSmooth = compareSmoothRegions(ref.gpu, moved.gpu, 3, 2);
    recordRow("invariance " + p.name, c.cpu, c.gpu, c.gpuVsCpu);
    return c;
}

TEST(ScaleInvariance, ReferenceAgreesAcrossPaths) {
    const Distance d = distance(reference().gpu, reference().cpu);
    recordRow("invariance reference s=1 T=0", d);
    EXPECT_TRUE(agrees(d)) << d.describe();
}

class Representable : public ::testing::TestWithParam<Placement> {};

TEST_P(Representable, RendersTheSameImage) {
    const Comparison c = renderMoved(GetParam());
    EXPECT_TRUE(agrees(c.cpu)) << "CPU vs s=1: " << c.cpu.describe();
    EXPECT_TRUE(agrees(c.gpu)) << "GPU vs s=1: " << c.gpu.describe();
    EXPECT_TRUE(agrees(c.gpuVsCpu)) << "GPU vs CPU: " << c.gpuVsCpu.describe();
    EXPECT_GT(c.cpuSmooth.smoothPixels, 2000);  // the check looked at most of the image
    EXPECT_EQ(c.cpuSmooth.differing, 0) << "CPU: " << c.cpuSmooth.worst;
    EXPECT_EQ(c.gpuSmooth.differing, 0) << "GPU: " << c.gpuSmooth.worst;
}

INSTANTIATE_TEST_SUITE_P(
    Scales, Representable,
    ::testing::Values(Placement{"Scale1em4", "s=1e-4", {1e-4, {}}}, Placement{"Scale1em2", "s=1e-2", {1e-2, {}}}, Placement{"Scale1e2", "s=1e2", {1e2, {}}},
                      Placement{"Scale1e4", "s=1e4", {1e4, {}}}, Placement{"Scale1e5", "s=1e5", {1e5, {}}}),
    [](const auto& info) { return info.param.id; });

INSTANTIATE_TEST_SUITE_P(
    Translations, Representable,
    ::testing::Values(Placement{"Scale1Away1e2", "s=1 T=1e2", {1.0, away(1e2)}}, Placement{"Scale1Away1e3", "s=1 T=1e3", {1.0, away(1e3)}},
                      Placement{"Scale1em4Away0p1", "s=1e-4 T=0.1", {1e-4, away(0.1)}}, Placement{"Scale1em2Away10", "s=1e-2 T=10", {1e-2, away(10.0)}},
                      Placement{"Scale1e2Away1e5", "s=1e2 T=1e5", {1e2, away(1e5)}}, Placement{"Scale1e4Away1e5", "s=1e4 T=1e5", {1e4, away(1e5)}},
                      Placement{"Scale1e5Away1e5", "s=1e5 T=1e5", {1e5, away(1e5)}}),
    [](const auto& info) { return info.param.id; });

// T/s >= 1e4: below what float32 world coordinates can hold for this scene's 0.05 gaps (see the top
// of the file). The image must still be the same scene (>= 90% of pixels within 2/255: a broken
// intersection or a black image fails that), finite, and the two paths must be close (>= 97%).
class BeyondFloatPrecision : public ::testing::TestWithParam<Placement> {};

TEST_P(BeyondFloatPrecision, StaysSane) {
    const Comparison c = renderMoved(GetParam());
    EXPECT_GE(c.cpu.fractionWithin2, 0.90) << "CPU vs s=1: " << c.cpu.describe();
    EXPECT_GE(c.gpu.fractionWithin2, 0.90) << "GPU vs s=1: " << c.gpu.describe();
    EXPECT_GE(c.gpuVsCpu.fractionWithin2, 0.97) << "GPU vs CPU: " << c.gpuVsCpu.describe();
}

INSTANTIATE_TEST_SUITE_P(
    Far, BeyondFloatPrecision,
    ::testing::Values(Placement{"Scale1Away1e4", "s=1 T=1e4", {1.0, away(1e4)}}, Placement{"Scale1Away1e5", "s=1 T=1e5", {1.0, away(1e5)}},
                      Placement{"Scale1em4Away1", "s=1e-4 T=1", {1e-4, away(1.0)}}),
    [](const auto& info) { return info.param.id; });

}  // namespace
}  // namespace vkrt::stability
