#version 460
// The wavefront renderer's EXTEND stage (wavefront.glsl): the closest hit of each live path's ray.
#extension GL_GOOGLE_include_directive : require
#define VKRT_WAVEFRONT_STAGE WAVEFRONT_EXTEND
#include "kernel.glsl"
#include "wavefront.glsl"

void main() {
    g_wfSlot = wfBegin();
    if (g_wfSlot >= wfPaths()) return;
    wfExtend();
    wfReport();
}
