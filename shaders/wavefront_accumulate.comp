#version 460
// The wavefront renderer's ACCUMULATE stage (wavefront.glsl): the wave's path radiances into the pixel sums, in sample order.
#extension GL_GOOGLE_include_directive : require
#define VKRT_WAVEFRONT_STAGE WAVEFRONT_ACCUMULATE
#include "kernel.glsl"
#include "wavefront.glsl"

void main() {
    uint invocation = wfBegin();
    if (invocation >= wfBandPixels()) return;
    uint nonFinite = 0u;
    uint first;
    uint pixel = wfAccumulate(invocation, nonFinite, first);
    reportStatus(pixel, first, nonFinite);
}
