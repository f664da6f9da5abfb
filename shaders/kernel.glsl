// What every kernel of the renderer shares: the scene's bindings and feature constants, the shading
// code, the push constants and the status report. render.comp (the megakernel) and the wavefront
// stages (wavefront_*.comp, which define VKRT_WAVEFRONT_STAGE first) include it after #version.
#ifndef VKRT_KERNEL_GLSL
#define VKRT_KERNEL_GLSL

#include "device_host.h"
#include "bindings.glsl"
#include "budget.glsl"  // before sampling.h, whose loop reports through it
#include "sampling.h"
#include "emitter_sampling.h"
#include "intersect.glsl"
#include "traverse.glsl"
#include "surface.glsl"
#include "ray_offset.glsl"
#include "texture.glsl"
#include "emitters.glsl"
#include "wavefront_state.glsl"  // before shading.glsl, whose shadow rays it may defer
#include "shading.glsl"
#include "environment.glsl"
#include "integrator.glsl"
#include "camera.glsl"

layout(push_constant) uniform PushConstants { PassParams passes[1]; };  // read at VKRT_UNIFORM_INDEX (bindings.glsl)

// 64 invocations: the megakernel's 8x8 pixel block (render.comp), a wavefront stage's 64 path slots.
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

// One atomic site for every failure (each inlined atomic is a per-lane loop that runs whether
// or not a lane takes it); the first failing pixel and sample are recorded for the message.
void reportStatus(uint pixel, uint failedSample, uint nonFinite) {
    uint failures = failureFlags() | (WAVEFRONT && g_shadowRaysMismatch ? STATUS_SHADOW_RAYS_MISMATCH : 0u);
    if (failures != 0u) {
        atomicOr(status.flags.x, failures);
        if (atomicCompSwap(status.flags.y, 0u, pixel + 1u) == 0u) status.flags.z = failedSample;
    }
    if (nonFinite != 0u) atomicAdd(status.flags.w, nonFinite);
}

#endif
