#version 460
// Test kernel for lavapipe's loop limiter (../shared/LAVAPIPE.md): counts the iterations loops
// really run. Increments are read from a buffer so the compiler cannot replace a loop by a closed
// form. One workgroup of 8 invocations = one of lavapipe's 8-lane SIMD groups.
//  mode 0: one loop of n iterations (every lane alike).
//  mode 1: two loops of n iterations one after the other: one budget per loop or per invocation?
//  mode 2: divergence: an outer loop of n iterations; in iteration i only lane i % 8 runs an
//          inner loop of 7 iterations. Each lane runs few iterations itself, but the SIMD group
//          executes an inner loop in every outer iteration.
layout(local_size_x = 8) in;

layout(std430, set = 0, binding = 0) buffer Counts {
    uint step[4];     // all 1, written by the host
    uint first[8];    // per lane: iterations of the (outer) loop that ran
    uint second[8];   // per lane: iterations of the second (mode 1) or inner (mode 2) loop
};
layout(push_constant) uniform Push {
    uint n;
    uint mode;
} pc;

void main() {
    uint lane = gl_LocalInvocationIndex;
    uint count = 0u;
    uint count2 = 0u;
    if (pc.mode == 2u) {
        for (uint i = 0u; i < pc.n; ++i) {
            count += step[i & 3u];
            if ((i & 7u) == lane) {
                for (uint k = 0u; k < 7u + step[k & 3u] - 1u; ++k) count2 += step[k & 3u];
            }
        }
    } else {
        for (uint i = 0u; i < pc.n; ++i) count += step[i & 3u];
        if (pc.mode == 1u) {
            for (uint i = 0u; i < pc.n; ++i) count2 += step[(i + 1u) & 3u];
        }
    }
    first[lane] = count;
    second[lane] = count2;
}
