#version 460
// The wavefront renderer's SHADE_RECORD stage (wavefront.glsl): a hit's shading, keeping only the shadow rays it asks for.
#extension GL_GOOGLE_include_directive : require
#define VKRT_DEFERRED_SHADOWS  // shadow rays go to the SHADOW stage (wavefront_state.glsl)
#define VKRT_WAVEFRONT_STAGE WAVEFRONT_SHADE_RECORD
#include "kernel.glsl"
#include "wavefront.glsl"

void main() {
    uint index = wfBegin();
    if (index >= wfQueueLength()) return;
    g_wfSlot = wfQueueEntry(wfRoundQueue(), index);
    wfShade();
    wfReport();
}
