#version 460
// The wavefront renderer's GENERATE stage (wavefront.glsl): the camera rays of a wave's paths.
#extension GL_GOOGLE_include_directive : require
#define VKRT_WAVEFRONT_STAGE WAVEFRONT_GENERATE
#include "kernel.glsl"
#include "wavefront.glsl"

void main() {
    g_wfSlot = wfBegin();
    if (g_wfSlot >= wfPaths()) return;
    wfGenerate();
    wfReport();
}
