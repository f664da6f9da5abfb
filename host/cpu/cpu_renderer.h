// The CPU reference renderer: an independent, plainly written implementation of the image
// defined in docs/RENDERING.md, against which the GPU kernels are checked.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "image.h"
#include "pixel_accumulation.h"
#include "render_options.h"
#include "scene.h"
#include "scene_accel.h"

namespace vkrt {

namespace cpu {
struct RenderContext;  // render_context.h
}

struct RenderStats {
    double seconds = 0.0;
    int threads = 0;
    std::uint64_t cameraRays = 0;
    std::uint64_t shadowRays = 0;
    std::uint64_t reflectionRays = 0;      // mirror, glossy and dielectric reflections
    std::uint64_t refractionRays = 0;
    std::uint64_t bounceRays = 0;          // Diffuse bounces
    std::uint64_t nonFiniteSamples = 0;    // samples replaced by black; any is a bug (RENDERING.md §8)
    std::uint64_t overflowedPixels = 0;    // finite samples summed past float: clamped (float_range.h)
};

// The reference's acceleration structure: the scene's BVH with the CPU traversal's SAH constants
// and its 8-wide copy (bvh::BuildOptions' defaults). The scene must outlive the result.
SceneAccel prepareCpuScene(const Scene& scene);

// Renders options.width x options.height linear radiance. Bit-identical for any thread count.
// Throws std::invalid_argument for bad options, RenderCancelled when *options.cancel becomes true.
// sampleVariance (optional, for statistical tests, host/study): per pixel and channel, the unbiased
// variance of the pixel's rpp sample radiances (0 when rpp = 1); the image itself is unchanged.
Image renderCpu(const Scene& scene, const SceneAccel& accel, const RenderOptions& options,
                RenderStats* stats = nullptr, Image* sampleVariance = nullptr);

// Adaptive sampling's device on the CPU (adaptive_render.h AddSamples): adds samples
// [acc.count[p], next[p]) of each pixel of options' rows, in sample order, as renderCpu computes
// them (a pixel's N samples sum to renderCpu's pixel at N rpp, bit for bit). The options' sampler
// must be one whose first N samples do not depend on the rpp (sobol2 or random).
class CpuSampleRanges {
public:
    CpuSampleRanges(const Scene& scene, const SceneAccel& accel, const RenderOptions& options);
    ~CpuSampleRanges();
    void add(const std::vector<std::uint32_t>& next, adaptive::PixelAccumulation& acc);
    const RenderStats& stats() const { return stats_; }  // all rounds so far

private:
    RenderOptions options_;
    std::unique_ptr<cpu::RenderContext> ctx_;
    glm::ivec2 rows_;
    int threads_;
    RenderStats stats_;
};

}  // namespace vkrt
