// The GPU kernel and the CPU reference draw the same samples for every sampler: sampling.h is
// compiled into both, and this is where a GLSL/C++ difference in the Sobol hash (or in the light
// and gloss sample counts) would show. 64x64 on lavapipe with the validation layers on.
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "cpu_renderer.h"
#include "gpu_renderer.h"
#include "image_compare.h"
#include "scene_accel.h"
#include "study_renderer.h"
#include "study_scenes.h"

namespace vkrt::test {
namespace {

struct Config {
    const char* scene;
    int lightSamples, glossSamples;
};

// Both renderers compute identical sample positions; only float rounding (FMA contraction on the
// GPU) differs, which can move a single ray across an edge. So almost every pixel must match its
// 8-bit value exactly, and the image on average to a tiny fraction of a step; a different sample
// pattern would change most noisy pixels by many steps.
TEST(GpuAgreement, EverySamplerMatchesTheCpuReference) {
    GpuRenderer gpu(GpuRendererOptions{.validation = true});
    for (const Config& config : {Config{"soft_shadows", 1, 1}, Config{"glossy", 1, 1}, Config{"glossy", 3, 2},
                                 Config{"soft_shadows", 2, 1}}) {
        const Scene scene = exampleScene(config.scene);
        const SceneAccel cpuAccel = prepareCpuScene(scene);
        const GpuSceneData gpuData = GpuRenderer::prepare(scene);
        Image previous;
        for (SamplerKind sampler :
             {SamplerKind::Jittered, SamplerKind::Regular, SamplerKind::Random, SamplerKind::Sobol, SamplerKind::Sobol2}) {
            RenderOptions o;
            o.width = 64;
            o.height = 64;
            o.samplesPerPixel = 16;
            o.lightSamples = config.lightSamples;
            o.glossSamples = config.glossSamples;
            o.sampler = sampler;
            o.seed = 11;
            o.camera = scene.defaultCamera;
            o.quiet = true;
            const Image onGpu = gpu.render(gpuData, o);
            const Image onCpu = renderCpu(scene, cpuAccel, o);
            const ImageDifference d = compareImages(onGpu, onCpu);
            const std::string what = std::string(config.scene) + " k=" + std::to_string(config.lightSamples) +
                                     " g=" + std::to_string(config.glossSamples) + " " + study::samplerName(sampler);
            std::printf("%s: max %.4f mean %.6f over1 %.4f%%\n", what.c_str(), d.maxAbs, d.meanAbs, 100.0 * d.fractionOver1);
            EXPECT_LE(d.fractionOver1, 0.005) << what;
            EXPECT_LE(d.meanAbs, 0.5 / 255.0 / 16.0) << what;
            // The sampler reaches the renderers: each one's image differs from the previous one's.
            if (!previous.pixels.empty()) {
                EXPECT_GT(compareImages(onCpu, previous).fractionOver1, 0.01) << what;
            }
            previous = onCpu;
        }
    }
    ASSERT_NE(gpu.validationLog(), nullptr);
    EXPECT_EQ(gpu.validationLog()->count(), 0u) << gpu.validationLog()->joined();
}

}  // namespace
}  // namespace vkrt::test
