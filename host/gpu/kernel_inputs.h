// Everything the render kernel reads (shaders/shared/device_host.h), computed on the host with no
// device: a scene is prepared once (its own BVH, tables and packed nodes), then each render adds
// its constants (frame parameters, the kernel variant, the sample batching). Uploading these is
// scene_upload.h's job; dispatching them is gpu_renderer.h's.
#pragma once

#include <cstdint>

#include "device_host.h"
#include "feature_set.h"
#include "node_packing.h"
#include "render_options.h"
#include "sample_batching.h"
#include "scene.h"
#include "scene_accel.h"
#include "scene_tables.h"

namespace vkrt {

// A prepared scene: the arrays of every binding but the frame, accumulation and status. Holds
// pointers into the scene (SceneAccel's PrimOrigin), which must outlive it. Render it as often as
// needed: nothing in it depends on the render options.
struct GpuSceneData {
    const Scene* scene = nullptr;
    SceneAccel accel;    // the GPU's own tree (gpu_build_options.h) and the way back to the scene
    SceneTables tables;  // materials, lights, primitive info, vertex attributes, textures
    GpuNodes nodes;      // accel's BVH nodes as the kernel reads them
    double buildSeconds = 0.0;  // building accel
    double packSeconds = 0.0;   // the tables and the node packing
    // Unique to each prepare (copies share it): GpuRenderer keeps the device buffers of the last
    // prepared scene it rendered and uploads again only for another key. A prepared scene is not
    // to be changed after prepare.
    std::uint64_t uploadKey = 0;
};

// Builds the GPU's tree, then the tables and nodes. Throws DeviceLimitExceeded when the tree could
// overflow the kernel's traversal stack or a leaf does not fit a stack entry (traversal_stack.h).
GpuSceneData prepareGpuScene(const Scene& scene);
// The same over a tree built elsewhere (tests' hand-made trees; the benchmarks' SAH studies).
GpuSceneData prepareGpuScene(const Scene& scene, SceneAccel accel);

enum class KernelVariant {
    Specialised,  // only the paths the scene uses (the default)
    General       // every feature on: the specialisation benchmark's baseline
};

// One render's constants: the frame (camera, image, sampling, seed), the kernel variant and how
// many samples each dispatch computes.
struct KernelInputs {
    gpu::FrameParams frame{};
    FeatureSet features;
    SampleBatching batching;
};

// Throws std::invalid_argument for options the kernel cannot honour (frame_params.h), and
// DeviceLimitExceeded when the general kernel's top-level walk could overflow the traversal stack.
// forcedSamplesPerDispatch: 0 lets the scene's loop bound choose (sample_batching.h); tests force one.
KernelInputs makeKernelInputs(const GpuSceneData& data, const RenderOptions& options,
                              KernelVariant variant = KernelVariant::Specialised,
                              std::uint32_t forcedSamplesPerDispatch = 0, std::uint64_t lockstepFactor = kLockstepFactor);

}  // namespace vkrt
