// The render kernel's variants compiled for statistics, never run: what the driver's compiler
// makes of each (registers, spills, scratch, occupancy; pipeline_statistics.h), for
// `vkrt-bench gpu kernels`. Opens compile-only devices too (RADV's null device: a real GPU
// compiler's verdict without the GPU, docs/BENCHMARKS.md).
#pragma once

#include <memory>
#include <string>

#include "gpu_options.h"
#include "kernel_inputs.h"
#include "render_options.h"

namespace vkrt {

struct KernelVariantReport {
    std::string stage = "render";   // the kernel: the megakernel render.comp is every stage in one
    std::string features;           // FeatureSet::describe()
    std::uint32_t samplesPerDispatch = 1;
    double compileSeconds = 0.0;    // pipeline creation (the driver's compile)
    bool cached = false;            // the same variant was compiled for an earlier scene
    // Of the compute executable, -1 where the driver does not report it.
    double vgprs = -1, sgprs = -1, spilledVgprs = -1, spilledSgprs = -1, scratchBytes = -1, wavesPerSimd = -1;
};

class KernelStatisticsCompiler {
public:
    explicit KernelStatisticsCompiler(const GpuRendererOptions& options = {});
    ~KernelStatisticsCompiler();
    std::string deviceName() const;
    std::string driver() const;
    // Whether the device reports statistics at all (lavapipe does not).
    bool hasStatistics() const;
    // The variant a render of `data` with `options` would use, compiled with statistics.
    // adaptive: the variant of adaptive sampling's rounds (FeatureSet::adaptive, render.comp's work list);
    // wavefrontStage: one stage of the wavefront renderer (gpu::WAVEFRONT_*) instead of the megakernel.
    KernelVariantReport compile(const GpuSceneData& data, const RenderOptions& options,
                                KernelVariant variant = KernelVariant::Specialised, bool adaptive = false,
                                std::uint32_t wavefrontStage = gpu::WAVEFRONT_OFF);
    std::size_t variants() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace vkrt
