#version 460
// Ray-throughput kernel for the benchmarks: trace a list of rays (closest or any hit) through the
// same traversal the render kernel uses, and write each hit. The host builds the rays with the
// Embree peer's camera rule, so both trace the same rays.
#extension GL_GOOGLE_include_directive : require

#include "device_host.h"
#include "bindings.glsl"
#include "budget.glsl"  // before sampling.h (if ever included), whose loop reports through it
#include "intersect.glsl"
#include "traverse.glsl"

// Rays through a texel buffer, like the BVH (bindings.glsl): on lavapipe an SSBO load at a
// per-lane address is a scalar loop over the lanes (host/gpu/README.md, fact 3).
layout(set = 0, binding = BINDING_RAYS, rgba32ui) uniform readonly uimageBuffer rays;
layout(set = 0, binding = BINDING_HITS, r32ui) uniform writeonly uimageBuffer hits;  // device_host.h: TRACE_HIT_WORDS
layout(push_constant) uniform TracePush { TraceParams traces[1]; };
#define trace traces[VKRT_UNIFORM_INDEX]  // bindings.glsl: why not a plain member
// TraceParams' lanes by name (device_host.h), read straight from the push constants like
// bindings.glsl's frame lanes: a function taking `trace` loads the whole uvec4 at the bounds check,
// and the any-hit flag then stays live (and spilled) through the traversal.
uint traceRayCount() { return trace.rays.x; }
bool traceAnyHit() { return trace.rays.y != 0u; }

layout(local_size_x = 64, local_size_y = 1, local_size_z = 1) in;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= traceRayCount()) return;
    vec4 origin = uintBitsToFloat(imageLoad(rays, int(2u * i)));  // TraceRayInput: origin + tMax, direction
    vec3 direction = uintBitsToFloat(imageLoad(rays, int(2u * i + 1u)).xyz);
    Hit hit;
    bool found = traceScene(origin.xyz, direction, origin.w, traceAnyHit(), hit);
    // Failures travel in the hit's words (TRACE_FAILED and the STATUS_* bits), read by the host
    // with the hits: no atomics, which would be a per-lane loop for every ray on lavapipe. Each
    // word stored is such a loop too, so a BVH without a top level stores no instance.
    uint failures = failureFlags();
    uint word0 = failures != 0u ? TRACE_FAILED : found ? floatBitsToUint(hit.t) : TRACE_MISS;
    uint word1 = failures != 0u ? failures : hit.prim;
    uint words = HAS_INSTANCES ? TRACE_HIT_WORDS_INSTANCED : TRACE_HIT_WORDS;
    int base = int(i * words);
    imageStore(hits, base, uvec4(word0));
    imageStore(hits, base + 1, uvec4(word1));
    if (HAS_INSTANCES) imageStore(hits, base + 2, uvec4(hit.instance));
}
