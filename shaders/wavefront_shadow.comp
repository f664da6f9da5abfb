#version 460
// The wavefront renderer's SHADOW stage (wavefront.glsl): the any-hit traversal of each recorded shadow ray.
#extension GL_GOOGLE_include_directive : require
#define VKRT_WAVEFRONT_STAGE WAVEFRONT_SHADOW
#include "kernel.glsl"
#include "wavefront.glsl"

void main() {
    uint invocation = wfBegin();
    if (invocation >= status.paths.w) return;
    wfShadow(invocation);
    wfReport();
}
