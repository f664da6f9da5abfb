#version 460
// Test kernel: reports a failure the way render.comp does, at pixel (5, 3), sample 1: the loop
// budget flag, or the ray-stack flag when the scene uses gloss (so one kernel tests both).
#extension GL_GOOGLE_include_directive : require
#include "device_host.h"
#include "test_bindings.glsl"

layout(local_size_x = 64) in;

void main() {
    uint x, y;
    if (!tilePixel(x, y)) return;
    uint pixel = y * frame.image.x + x;
    for (uint j = 0u; j < pass.pass.w; ++j) {  // the pass's samples (device_host.h PassParams)
        uint sampleIndex = pass.pass.x + j;
        if (x == 5u && y == 3u && sampleIndex == 1u) {
            atomicOr(status.flags.x, HAS_GLOSS ? STATUS_RAY_STACK_OVERFLOW : STATUS_LOOP_BUDGET_EXCEEDED);
            if (atomicCompSwap(status.flags.y, 0u, pixel + 1u) == 0u) status.flags.z = sampleIndex;
        }
        addToPixel(pixel, vec3(1.0));
    }
}
