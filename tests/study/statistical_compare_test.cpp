// The z-test on real renders: two seeds of one scene agree, a scene with a changed light does not
// (CPU); and `vkrt compare --stat`, the GPU (lavapipe, validation on) against the CPU reference.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app.h"
#include "cpu_renderer.h"
#include "scene_accel.h"
#include "statistical_compare.h"
#include "study_scenes.h"
#include "test_paths.h"
#include "z_test.h"

namespace vkrt::test {
namespace {

RenderOptions smallOptions(const Scene& scene, SamplerKind sampler, int rpp, std::uint32_t seed, int width = 48,
                           int height = 36) {
    RenderOptions o;
    o.width = width;
    o.height = height;
    o.camera = scene.defaultCamera;
    o.sampler = sampler;
    o.samplesPerPixel = rpp;
    o.seed = seed;
    o.quiet = true;
    return o;
}

// `test` at 16 rpp (seed 1) against the 512-rpp reference of `reference` (seed 2) with its
// variance, at 48x36 (5184 values, so up to 12 may fail). A sample of probability ~1/1000 (a
// sliver of lit floor seen past a shadow's edge) makes a 16-sample mean far from normal: one such
// pixel failed at |z| = 8 in a 32x24 image with soft_shadows and sobol. The pass fraction is what
// absorbs those few; the image must be large enough for it to.
study::ZTestResult compareWithReference(const Scene& test, const Scene& reference, SamplerKind sampler) {
    const SceneAccel testAccel = prepareCpuScene(test);
    const SceneAccel referenceAccel = prepareCpuScene(reference);
    Image variance;
    const Image ref = renderCpu(reference, referenceAccel, smallOptions(reference, sampler, 512, 2), nullptr, &variance);
    const Image image = renderCpu(test, testAccel, smallOptions(test, sampler, 16, 1));
    return study::zTest(image, ref, study::sumImages(study::varianceOfMean(variance, 16), study::varianceOfMean(variance, 512)));
}

TEST(StatisticalCompare, TwoSeedsOfOneSceneAgree) {
    for (const char* name : {"soft_shadows", "glossy"}) {
        const Scene scene = exampleScene(name);
        for (SamplerKind sampler : {SamplerKind::Random, SamplerKind::Jittered, SamplerKind::Sobol}) {
            const study::ZTestResult r = compareWithReference(scene, scene, sampler);
            std::printf("%s %s: %.3f%% pass, max |z| %.2f\n", name, study::samplerName(sampler).c_str(),
                        100.0 * r.passedFraction(), r.maxAbsZ);
            EXPECT_TRUE(r.pass) << name << ", " << study::samplerName(sampler) << ": " << 100.0 * r.passedFraction() << "%";
        }
    }
}

// A light 10% brighter shifts every pixel it lights by up to 10%, many standard errors at 16 rpp.
TEST(StatisticalCompare, AChangedLightIntensityIsDetected) {
    for (const char* name : {"soft_shadows", "glossy"}) {
        const Scene scene = exampleScene(name);
        Scene brighter = scene;
        brighter.lights[0].intensity *= 1.1f;
        for (SamplerKind sampler : {SamplerKind::Random, SamplerKind::Sobol}) {
            const study::ZTestResult r = compareWithReference(brighter, scene, sampler);
            std::printf("%s %s, light x1.1: %.3f%% pass\n", name, study::samplerName(sampler).c_str(), 100.0 * r.passedFraction());
            EXPECT_FALSE(r.pass) << name << ", " << study::samplerName(sampler);
        }
    }
}

TEST(StatisticalCompare, GpuAgreesWithTheCpuReferenceUpToNoise) {
    study::StudyRenderer renderer(GpuRendererOptions{.validation = true});
    for (const char* name : {"soft_shadows", "glossy"}) {
        const Scene scene = exampleScene(name);
        const study::PreparedScene prepared = renderer.prepare(scene);
        for (SamplerKind sampler : {SamplerKind::Jittered, SamplerKind::Sobol}) {
            const study::StatisticalComparison c =
                study::compareDevicesStatistically(renderer, prepared, smallOptions(scene, sampler, 16, 3, 32, 24));
            EXPECT_NE(c.gpuSeed, c.cpuSeed);
            EXPECT_EQ(c.cpuRpp, 256);
            EXPECT_TRUE(c.test.pass) << name << ", " << study::samplerName(sampler) << ": "
                                     << 100.0 * c.test.passedFraction() << "%";
        }
    }
    ASSERT_NE(renderer.validationLog(), nullptr);
    EXPECT_EQ(renderer.validationLog()->count(), 0u) << renderer.validationLog()->joined();
}

TEST(StatisticalCompare, CommandLineCompareStat) {
    const std::string map = artifactDir() + "/compare_stat_zmap.png";
    std::filesystem::remove(map);
    const std::string scene = sourceDir() + "/scenes/soft_shadows.xml";
    const char* argv[] = {"vkrt", "compare", scene.c_str(), "--stat", "-w", "24", "-h", "18", "-r", "8",
                          "--sampler", "sobol", "--validate", "-o", map.c_str()};
    EXPECT_EQ(runVkrt(static_cast<int>(std::size(argv)), argv), 0);
    const Image z = readImage(map);
    EXPECT_EQ(z.width, 24);
    EXPECT_EQ(z.height, 18);
}

}  // namespace
}  // namespace vkrt::test
