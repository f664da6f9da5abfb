#version 460
// Test kernel: adds, per pixel and sample, the unit direction of the perspective camera ray
// through the jittered sample point (docs/RENDERING.md §1), plus sample / 64 in blue, so a
// pixel's result depends on its position, on which samples it received and on receiving each
// exactly once. The host recomputes the same sums independently.
#extension GL_GOOGLE_include_directive : require
#include "device_host.h"
#define VKRT_LOOP_CUT_OFF() {}  // sampling.h's limiter report: this test kernel has no status to raise
#include "sampling.h"
#include "test_bindings.glsl"

layout(local_size_x = 64) in;

void main() {
    uint x, y;
    if (!tilePixel(x, y)) return;
    uint pixel = y * frame.image.x + x;
    for (uint j = 0u; j < pass.pass.w; ++j) {  // the pass's samples, in order (device_host.h PassParams)
        uint sampleIndex = pass.pass.x + j;
        vec2 jitter = sample2D(frame.sampling.x, frame.pixelGrid, pixel, sampleIndex, DIM_CAMERA, frame.scene.x);
        float a = frame.cameraU.w * ((float(x) + jitter.x) / float(frame.image.x) - 0.5);
        float b = frame.cameraV.w * (0.5 - (float(y) + jitter.y) / float(frame.image.y));
        vec3 dir = normalize(-frame.cameraW.w * frame.cameraW.xyz + a * frame.cameraU.xyz + b * frame.cameraV.xyz);
        addToPixel(pixel, dir + vec3(0.0, 0.0, float(sampleIndex) / 64.0));
    }
}
