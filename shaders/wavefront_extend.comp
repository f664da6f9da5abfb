#version 460
// The wavefront renderer's EXTEND stage (wavefront.glsl): the closest hit of each live path's ray.
#extension GL_GOOGLE_include_directive : require
#define VKRT_WAVEFRONT_STAGE WAVEFRONT_EXTEND
#include "kernel.glsl"
#include "wavefront.glsl"

void main() {
    uint index = wfBegin();
    if (index == 0u) {  // the queues this round appends to start empty (no stage reads them before SHADE_RECORD)
        uint next = 1u - wfRoundQueue();
        if (next == 1u) status.paths.z = 0u;
        else status.paths.y = 0u;
        status.paths.w = 0u;
        status.queueGroups[next].x = 1u;
        status.queueGroups[WF_SHADOW_QUEUE].x = 0u;
    }
    if (index >= wfQueueLength()) return;
    g_wfSlot = wfQueueEntry(wfRoundQueue(), index);
    wfExtend();
    wfReport();
}
