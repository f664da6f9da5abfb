#version 460
// Test kernel: adds, per pixel and sample, the Owen-scrambled Sobol points of three dimensions
// (sampling.h sobolSample2D: the camera's, a bounce's and a light's) for the point number
// 37 * pixel + sample, so that one sample per pixel covers thousands of point numbers, and the
// GPU's integer hashing, bit reversal (bitfieldReverse here, a ladder of swaps on the host) and
// float conversion can be compared with the host's bit for bit.
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
        uint index = 37u * pixel + pass.pass.x + j;
        vec2 camera = sobolSample2D(pixel, index, DIM_CAMERA, frame.scene.x);
        vec2 bounce = sobolSample2D(pixel, index, dimBounce(2u), frame.scene.x);
        vec2 light = sobolSample2D(pixel, index, dimLight(1u, 3u), frame.scene.x);
        addToPixel(pixel, vec3(camera.x + bounce.y, camera.y + light.x, bounce.x + light.y));
    }
}
