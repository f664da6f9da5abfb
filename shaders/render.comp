#version 460
// The render kernel: one invocation computes one sample of one pixel and adds it to the pixel's
// running sum. One dispatch = one sample pass over one tile, which keeps each invocation far below
// lavapipe's loop limit and each submission short (host/vulkan dispatches tiles x passes).
#extension GL_GOOGLE_include_directive : require

#include "device_host.h"
#include "bindings.glsl"
#include "budget.glsl"  // before sampling.h, whose loop reports through it
#include "sampling.h"
#include "intersect.glsl"
#include "traverse.glsl"
#include "surface.glsl"
#include "ray_offset.glsl"
#include "texture.glsl"
#include "shading.glsl"
#include "integrator.glsl"
#include "camera.glsl"

layout(push_constant) uniform PushConstants { PassParams passes[1]; };  // read at VKRT_UNIFORM_INDEX (bindings.glsl)

// 64 invocations = one 8x8 pixel block; each group of 8 lanes (lavapipe's subgroup) is a 4x2
// patch, so lanes that run in lockstep trace neighbouring, coherent rays.
layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

void main() {
    PassParams pass = passes[VKRT_UNIFORM_INDEX];
    uvec4 tile = pass.tile;
    // Workgroups are handed to lavapipe's threads in contiguous chunks; visiting blocks in a
    // strided order spreads expensive regions of the image over all threads.
    // The host keeps groups <= 65536 and stride < groups, so the product fits in 32 bits.
    uint groups = pass.pass.z;
    uint block = (gl_WorkGroupID.x * pass.pass.y) % groups;
    uint blocksX = (tile.z + 7u) / 8u;
    uint lane = gl_LocalInvocationIndex;
    uint laneGroup = lane >> 3u;
    uint px = (laneGroup & 1u) * 4u + (lane & 3u);
    uint py = (laneGroup >> 1u) * 2u + ((lane >> 2u) & 1u);
    uint localX = (block % blocksX) * 8u + px;
    uint localY = (block / blocksX) * 8u + py;
    if (localX >= tile.z || localY >= tile.w) return;
    uint x = tile.x + localX;
    uint y = tile.y + localY;

    SampleKey key;
    key.pixel = y * frame.image.x + x;
    key.index = pass.pass.x;
    key.seed = frame.scene.x;
    vec2 subPixel = sample2D(samplerKind(), frame.pixelGrid, key.pixel, key.index, DIM_CAMERA, key.seed);
    CameraRay camera = cameraRay(x, y, subPixel);
    vec3 radiance = cameraSampleRadiance(camera.origin, camera.dir, key);

    // One atomic site for every failure (each inlined atomic is a per-lane loop that runs whether
    // or not a lane takes it); the first failing pixel and sample are recorded for the message.
    uint failures = failureFlags();
    if (failures != 0u) {
        atomicOr(status.flags.x, failures);
        if (atomicCompSwap(status.flags.y, 0u, key.pixel + 1u) == 0u) status.flags.z = key.index;
    }
    if (any(isnan(radiance)) || any(isinf(radiance))) {
        atomicAdd(status.flags.w, 1u);
        radiance = vec3(0.0);
    }
    accumulate(key.pixel, radiance);
}
