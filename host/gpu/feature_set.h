// What a scene uses, as the specialization constants of the render kernel (SPEC_* in
// shaders/shared/device_host.h): the driver's compiler removes every path a scene cannot reach.
#pragma once

#include <array>
#include <compare>
#include <cstdint>
#include <string>

#include "device_host.h"
#include "render_options.h"
#include "scene.h"
#include "scene_accel.h"

namespace vkrt {

struct FeatureSet {
    bool triangles = true;
    bool spheres = true;
    bool boxes = true;
    bool instances = true;      // anything but one identity instance: traverse the top level
    bool areaLights = true;
    bool specular = true;       // Blinn-Phong highlights
    bool reflection = true;     // Mirror, Glaze, BlinnPhongMirrored
    bool gloss = true;          // roughness > 0 on a used shader
    bool dielectric = true;
    bool textures = true;
    bool coolToWarm = true;
    std::uint32_t maxDepth = 4;        // 0 when nothing reflects or refracts, else options.maxDepth
    std::uint32_t pathStackSize = 5;   // pending rays: maxDepth + glossSamples (integrator.glsl); 0 when
                                       // nothing pushes (no dielectric, or glass in a scene with Diffuse
                                       // surfaces, which continues one branch; no gloss fan-out): no stack code
    bool packedNodes = true;           // the BVH nodes' layout (GpuNodes::packed, node_packing.h)
    std::uint32_t sampler = gpu::SAMPLER_FROM_FRAME;  // the render's SamplerKind, compiled in; the
                                                      // general kernel reads it from the frame
    bool thinLens = true;              // the render's camera has depth of field
    bool translucency = true;          // a used Dielectric has roughness > 0 (glossy refraction)
    bool motion = true;                // some instance moves (motion blur: a time per sample)
    bool diffuse = true;               // a used shader is the course's path-traced Diffuse
    bool emitters = true;              // the scene has shape emitters
    bool environment = true;           // the scene has an environment map
    std::uint32_t estimator = gpu::ESTIMATOR_FROM_FRAME;  // the render's Estimator when the scene has
                                                          // Diffuse surfaces, else ESTIMATOR_BOUNCE
    // Not a feature of the scene but the render's mode, off in every kernel but adaptive sampling's
    // rounds (GpuRenderer::addSampleRanges): a work list of pixels and odd sums (render.comp).
    bool adaptive = false;
    // Not a feature of the scene either: gpu::WAVEFRONT_OFF for the megakernel, else the one stage
    // of the wavefront renderer the kernel runs (shaders/wavefront.glsl).
    std::uint32_t wavefrontStage = gpu::WAVEFRONT_OFF;

    auto operator<=>(const FeatureSet&) const = default;

    // Values indexed by SPEC_* id. samplesPerDispatch is the render's k (sample_batching.h): not a
    // feature of the scene, but a constant of the same kernel; 1 compiles render.comp without its
    // sample loop.
    std::array<std::uint32_t, gpu::SPEC_COUNT> specializationValues(std::uint32_t samplesPerDispatch = 1) const;
    // "triangles spheres area-lights reflection sampler=jittered depth=4 stack=5", for logs and
    // benchmark tables (no sampler= when the kernel reads it from the frame).
    std::string describe() const;
};

// "generate", "extend", "shade-rec", "shadow", "shade-res", "accum" for gpu::WAVEFRONT_*; "render"
// for the megakernel.
std::string wavefrontStageName(std::uint32_t stage);

// Whether traversal must walk the top level: anything but one identity instance. With one
// identity instance the kernel starts at that instance's bottom-level root in world space,
// which skips the per-ray instance transform and the top-level nodes.
bool needsTopLevel(const bvh::SceneBvh& bvh);

// The features the scene's shapes, instances, shaders and lights actually use; packedNodes is the
// layout the nodes go up in (GpuNodes::packed).
FeatureSet deriveFeatureSet(const Scene& scene, const SceneAccel& accel, const RenderOptions& options, bool packedNodes);

// Every feature on (the general kernel of the specialisation benchmark), at the depth and
// gloss-sample count of `options`; the sampler is read from the frame.
FeatureSet generalFeatureSet(const RenderOptions& options, bool packedNodes);

// Traversal only (trace_rays.comp): primitive kinds and instancing from the BVH, no shading paths.
FeatureSet traversalFeatureSet(const bvh::SceneBvh& bvh, bool packedNodes);

}  // namespace vkrt
