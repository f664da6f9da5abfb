// The CPU reference renderer: an independent, plainly written implementation of the image
// defined in docs/RENDERING.md, against which the GPU kernels are checked.
#pragma once

#include <cstdint>

#include "image.h"
#include "render_options.h"
#include "scene.h"
#include "scene_accel.h"

namespace vkrt {

struct RenderStats {
    double seconds = 0.0;
    int threads = 0;
    std::uint64_t cameraRays = 0;
    std::uint64_t shadowRays = 0;
    std::uint64_t reflectionRays = 0;      // mirror, glossy and dielectric reflections
    std::uint64_t refractionRays = 0;
    std::uint64_t nonFiniteSamples = 0;    // samples replaced by black; any is a bug (RENDERING.md §8)
    std::uint64_t overflowedPixels = 0;    // finite samples summed past float: clamped (float_range.h)
};

// The reference's acceleration structure: the scene's BVH with the CPU traversal's SAH constants
// and its 4-wide copy (bvh::BuildOptions' defaults). The scene must outlive the result.
SceneAccel prepareCpuScene(const Scene& scene);

// Renders options.width x options.height linear radiance. Bit-identical for any thread count.
// Throws std::invalid_argument for bad options, RenderCancelled when *options.cancel becomes true.
// sampleVariance (optional, for statistical tests, host/study): per pixel and channel, the unbiased
// variance of the pixel's rpp sample radiances (0 when rpp = 1); the image itself is unchanged.
Image renderCpu(const Scene& scene, const SceneAccel& accel, const RenderOptions& options,
                RenderStats* stats = nullptr, Image* sampleVariance = nullptr);

}  // namespace vkrt
