// The wavefront renderer: render.comp's stages (shaders/wavefront.glsl) over waves of paths
// (wavefront_plan.h) instead of the megakernel's whole path per invocation. GpuRenderer::render
// calls it for GpuKernel::Wavefront; the image is the megakernel's (the same shading code adds the
// same radiance in the same order), but no kernel holds both traversal and shading, so each
// needs far fewer registers on a GPU compiler (docs/BENCHMARKS.md, kernel registers).
#pragma once

#include <span>

#include "commands.h"
#include "compute_pipeline.h"
#include "context.h"
#include "gpu_renderer.h"
#include "kernel_cache.h"
#include "scene_upload.h"

namespace vkrt {

// The device objects a render uses, GpuRenderer's own.
struct GpuRenderDevice {
    const Context& context;
    CommandRunner& runner;
    Transfers& transfers;
    const KernelLayout& layout;
    KernelCache& kernels;
};

// Paths in flight per wave: enough to fill a GPU; lavapipe runs 2-16 CPU threads, where a smaller
// wave keeps the state in cache.
std::uint64_t targetWavePaths(const DeviceInfo& device);

// Renders `options` with the wavefront stages: `sums` gets every pixel's sum of its samples (the
// megakernel's accumulation, in the same order). `gpuScene` holds the prepared scene (uploaded),
// `in` the render's constants, `wavePaths` the paths per wave (0: targetWavePaths). Adds the stages' pipelines, submissions and timings to the stats,
// and calls options.onCheckpoint after the rounds it asks for.
void renderWavefront(const GpuRenderDevice& device, SceneUpload& gpuScene, const GpuSceneData& data, const KernelInputs& in,
                     const RenderOptions& options, std::uint64_t wavePaths, GpuRenderStats& stats, std::vector<glm::vec4>& sums);

// Adaptive sampling's round with the wavefront stages (GpuRenderer::addSampleRanges): `contents`
// is the ADAPTIVE accumulation buffer's (per pixel of `pixels` the sum and the odd samples' sum,
// then the work list, sorted by samples to add); waves are runs of work-list entries times sample
// offsets within each entry's range. The sums are left on the device for the caller to read.
void addSampleRangesWavefront(const GpuRenderDevice& device, SceneUpload& gpuScene, const GpuSceneData& data, const KernelInputs& in,
                              const RenderOptions& options, std::span<const glm::uvec4> contents, std::size_t pixels,
                              GpuRenderStats& stats);

}  // namespace vkrt
