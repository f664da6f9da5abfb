// `vkrt scene.xml --target-error E` / `--time SECONDS`: adaptive sampling (adaptive_render.h) on the
// device --device picks, with a line per round, the error and sample-count maps, and the summary.
#pragma once

#include "adaptive_render.h"
#include "command_line.h"
#include "gpu_renderer.h"
#include "render_steps.h"

namespace vkrt {

int runAdaptiveRender(CommandLine& cl);

// An adaptive render of a prepared scene (watch mode): on the GPU when `gpu` and `gpuData` are
// given, else on the CPU reference from `accel`. After every round (the last included),
// options.onCheckpoint (if set) gets the image so far with its mean rpp. The result's `device`
// also gives the estimated error, why the rounds stopped, and the counts. `kernel`: --gpu-kernel.
DeviceRender renderAdaptivePrepared(GpuRenderer* gpu, const GpuSceneData* gpuData, const Scene& scene, const SceneAccel* accel,
                                    const RenderOptions& options, const adaptive::AdaptiveOptions& adaptiveOptions,
                                    GpuKernel kernel = GpuKernel::Auto);

}  // namespace vkrt
