#include "kernel_inputs.h"

#include <algorithm>
#include <atomic>
#include <chrono>

#include "frame_params.h"
#include "gpu_build_options.h"
#include "traversal_stack.h"

namespace vkrt {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

GpuSceneData prepareGpuScene(const Scene& scene) {
    const auto start = std::chrono::steady_clock::now();
    SceneAccel accel = buildSceneAccel(scene, gpuBuildOptions());
    const double buildSeconds = secondsSince(start);
    GpuSceneData data = prepareGpuScene(scene, std::move(accel));
    data.buildSeconds = buildSeconds;
    return data;
}

GpuSceneData prepareGpuScene(const Scene& scene, SceneAccel accel) {
    const auto start = std::chrono::steady_clock::now();
    // Before packing: gpuNodes expects every leaf to fit a stack entry (checkLeafEntries).
    checkTraversalStack(accel.bvh, needsTopLevel(accel.bvh));
    GpuSceneData data;
    data.scene = &scene;
    data.accel = std::move(accel);
    data.tables = buildSceneTables(scene, data.accel);
    data.nodes = gpuNodes(data.accel.bvh);
    data.packSeconds = secondsSince(start);
    static std::atomic<std::uint64_t> prepared{0};
    data.uploadKey = ++prepared;
    return data;
}

KernelInputs makeKernelInputs(const GpuSceneData& data, const RenderOptions& options, KernelVariant variant,
                              std::uint32_t forcedSamplesPerDispatch, std::uint64_t lockstepFactor) {
    const Scene& scene = *data.scene;
    const bvh::SceneBvh& bvh = data.accel.bvh;
    KernelInputs in;
    in.frame = makeFrameParams(scene, data.accel, options);  // validates the options
    in.frame.world = data.nodes.world;  // the nodes and primitives walked as the world (node_packing.h)
    const bool general = variant == KernelVariant::General;
    in.features = general ? generalFeatureSet(options, data.nodes.packed)
                          : deriveFeatureSet(scene, data.accel, options, data.nodes.packed);
    // The general kernel walks the top level even where the scene has none: its stack need grows.
    if (in.features.instances != needsTopLevel(bvh)) checkTraversalStack(bvh, in.features.instances);
    const auto samples = static_cast<std::uint32_t>(options.samplesPerPixel);
    in.batching = {samples, samplesPerDispatch(sampleLoopBound(scene, bvh, in.features, options), samples,
                                               forcedSamplesPerDispatch, lockstepFactor)};
    // A progressive render needs a pass boundary at each of its checkpoints: at most rpp / N
    // samples per dispatch (the image does not depend on k: sample_batching.h).
    if (options.checkpoints > 1 && forcedSamplesPerDispatch == 0)
        in.batching.perDispatch = std::clamp(samples / static_cast<std::uint32_t>(options.checkpoints), 1u, in.batching.perDispatch);
    return in;
}

}  // namespace vkrt
