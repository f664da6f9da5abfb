// Rendering one scene on both paths (CPU reference and GPU kernel) with the checks every stability
// image must pass, and the image distances the tests assert and docs/STABILITY.md reports.
#pragma once

#include <string>

#include "cpu_renderer.h"
#include "gpu_renderer.h"
#include "image.h"
#include "render_options.h"
#include "scene.h"

namespace vkrt::stability {

struct BothImages {
    Image cpu, gpu;
    RenderStats cpuStats;
    GpuRenderStats gpuStats;
};

// Builds the BVH, renders on the CPU and on the shared GPU renderer, and checks (non-fatally, so a
// test can report more) that neither path replaced a non-finite sample, that no pixel is NaN or
// Inf, and that the validation layers stayed silent. cpuSampleVariance (optional): the CPU's
// per-pixel sample variance (renderCpu's), for tolerances derived from the noise.
BothImages renderBoth(const Scene& scene, const RenderOptions& options, Image* cpuSampleVariance = nullptr);

// A feature's code costs a scene that does not use it nothing but time: the general kernel (every
// feature compiled in, `feature` named in its summary) renders `scene` bit for bit as the
// specialised kernel (without `feature`) does. Fatal on the first differing pixel.
void expectGeneralKernelRendersItBitForBit(const Scene& scene, const RenderOptions& options, const std::string& feature);

// GPU images of one scene from differently compiled kernel variants (samples per dispatch, the
// specialisation, the Diffuse or estimator code compiled in or out). On lavapipe, where it is
// measured, they are bit for bit alike; a GPU compiler may contract or reorder float operations
// differently in each variant, so on other drivers the rule is the CPU/GPU agreement rule
// (agrees()), and a failure there is a real difference, not an optimiser's rounding.
void expectSameGpuImage(const Image& a, const Image& b, const std::string& what);

// Small images, few samples: what every test here uses unless it studies the options themselves.
RenderOptions smallOptions(int width, int height, int samplesPerPixel);

// The 8-bit distance between two images (image_compare.h), in steps of 1/255.
struct Distance {
    int maxSteps = 0;             // worst pixel, worst channel
    double fractionWithin2 = 1.0; // pixels whose every channel is within 2/255
    double meanSteps = 0.0;       // mean |difference| over all channels
    std::string describe() const;
};
Distance distance(const Image& a, const Image& b);

// How far one path's pixels are from what a closed form or an exact identity says they must be.
struct Deviation {
    double worst = 0.0;  // largest |got - expected|, linear radiance
    int checked = 0;
    int wrong = 0;       // pixels outside the test's tolerance
    std::string first;   // the first wrong pixel, for the failure message
    void add(double error, bool ok, const std::string& where);
    Distance asDistance() const;  // worst in 8-bit steps, share of pixels within tolerance
};

// The project's CPU/GPU agreement rule (tests/vulkan and `vkrt compare`): >= 99.5% of pixels within
// 2/255 and a mean difference <= 0.5/255. The two paths round differently (FMA contraction on the
// GPU, the order of a few sums), which may tip a ray at a silhouette or a shadow edge to the other
// side: a few isolated pixels, never a region.
bool agrees(const Distance& d);

// Writes one row of the measured table (docs/STABILITY.md) to test_artifacts/stability_table.tsv
// and to the test's log.
void recordRow(const std::string& caseName, const Distance& cpuVsReference, const Distance& gpuVsReference,
               const Distance& gpuVsCpu);
void recordRow(const std::string& caseName, const Distance& gpuVsCpu);
// A CPU-only case (intersection routines called directly): its measurement in words.
void recordNote(const std::string& caseName, const std::string& cpuMeasurement);

}  // namespace vkrt::stability
