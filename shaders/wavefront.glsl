// The wavefront renderer's stages (host/gpu/wavefront_renderer.h drives them): each stage is
// render.comp compiled with its SPEC_WAVEFRONT_STAGE, one invocation per path slot of the wave
// (wavefront_state.glsl), so no kernel holds both the traversal and the shading: EXTEND and SHADOW
// trace, the shading stages do not. A wave runs GENERATE, then EXTEND, SHADE_RECORD, SHADOW,
// SHADE_RESOLVE until every path has ended, then ACCUMULATE. The shading is shadeRay
// (integrator.glsl), the megakernel's own, so a path adds the same radiance in the same order.
#ifndef VKRT_WAVEFRONT_GLSL
#define VKRT_WAVEFRONT_GLSL

SampleKey wfSampleKey(uvec2 pixel, uint sampleNumber) {
    SampleKey key;
    key.pixel = pixel.y * frameWidth() + pixel.x;
    key.index = sampleIndex(samplerKind(), sampleNumber);
    key.seed = sampleSeed(samplerKind(), frameSeed(), sampleNumber);
    return key;
}

PathRay wfLoadRay() {
    vec4 a = wfLoadFloats(WF_ORIGIN);
    vec4 b = wfLoadFloats(WF_DIR);
    vec4 c = wfLoadFloats(WF_WEIGHT);
    sampleTime = c.w;
    return PathRay(a.xyz, b.xyz, c.xyz, floatBitsToUint(a.w), b.w);
}

void wfStoreRay(PathRay r) {
    wfStoreFloats(WF_ORIGIN, vec4(r.origin, uintBitsToFloat(r.depth)));
    wfStoreFloats(WF_DIR, vec4(r.dir, r.bouncePdf));
    wfStoreFloats(WF_WEIGHT, vec4(r.weight, sampleTime));
}

// GENERATE: the camera ray of the slot's sample; no radiance yet, an empty stack. Round 0's queue
// is every slot in order (its length and dispatch set by the host, StageRecorder::resetQueues);
// adaptive, the slots with a sample, appended (the rest end here).
void wfGenerate() {
    WfSlotSample slot = wfSlotSample(g_wfSlot);
    uvec2 pixel = slot.pixel;
    uint sampleNumber = slot.sampleNumber;
    if (ADAPTIVE && sampleNumber >= slot.end) {
        wfStore(WF_RADIANCE, uvec4(0u));
        atomicAdd(status.paths.x, 1u);
        return;
    }
    SampleKey key;
    key.pixel = pixel.y * frameWidth() + pixel.x;
    CameraRay camera = cameraSample(pixel.x, pixel.y, sampleNumber, key);
    wfStoreRay(PathRay(camera.origin, camera.dir, vec3(1.0), 0u, 0.0));
    wfStore(WF_RADIANCE, uvec4(floatBitsToUint(vec3(0.0)), WF_LIVE));
    if (ADAPTIVE) {
        uint index = atomicAdd(status.paths.y, 1u);
        wfSetQueueEntry(0u, index, g_wfSlot);
        wfCountGroups(0u, index, 1u);
        return;
    }
    wfSetQueueEntry(0u, g_wfSlot, g_wfSlot);
}

// Round r's queue of live paths and its length.
uint wfQueueLength() { return wfRoundQueue() == 0u ? status.paths.y : status.paths.z; }

// EXTEND: the closest hit of a live path's ray (wavefront_extend.comp's first invocation also
// empties the queues this round appends to).
void wfExtend() {
    PathRay ray = wfLoadRay();
    Hit hit;
    bool found = traceScene(ray.origin, ray.dir, FLT_MAX, false, hit);
    wfStore(WF_HIT, uvec4(floatBitsToUint(hit.t), hit.instance, hit.prim, found ? 1u : 0u));
    wfStore(WF_BARY, uvec4(floatBitsToUint(hit.bary), 0u, 0u));
}

// SHADE_RECORD and SHADE_RESOLVE: shadeRay at the hit EXTEND found. RECORD keeps only the shadow
// rays it asks for (and their number, BARY.z); RESOLVE adds the radiance and moves the path to
// its next ray (the hit's first child, else the top of its stack), or ends it.
void wfShade() {
    uvec4 state = wfLoad(WF_RADIANCE);
    if ((state.w & WF_LIVE) == 0u) return;
    PathRay ray = wfLoadRay();
    uvec4 h = wfLoad(WF_HIT);
    uvec4 b = wfLoad(WF_BARY);
    g_wfRecorded = b.z;
    Hit hit;
    hit.t = uintBitsToFloat(h.x);
    hit.instance = h.y;
    hit.prim = h.z;
    hit.bary = uintBitsToFloat(b.xy);
    WfSlotSample slot = wfSlotSample(g_wfSlot);
    SampleKey key = wfSampleKey(slot.pixel, slot.sampleNumber);
    g_pathTop = state.w & 0xffffu;
    vec3 radiance = uintBitsToFloat(state.xyz);
    PathQueue q;
    q.hasNext = false;
    q.hasExtra = false;
    shadeRay(ray, h.w != 0u, hit, key, radiance, q);
    flushQueue(q);
    if (WAVEFRONT_STAGE == WAVEFRONT_SHADE_RECORD) {
        // At most the slots there are (more is an error shadowRayClear reported): the queue's room.
        uint recorded = min(g_wfShadows, wfShadowsPerPath());
        wfStore(WF_BARY, uvec4(b.xy, recorded, 0u));
        if (recorded > 0u) {
            uint first = atomicAdd(status.paths.w, recorded);
            for (uint j = 0u; j < recorded; ++j) wfSetQueueEntry(WF_SHADOW_QUEUE, first + j, g_wfSlot + j * wfPaths());
            wfCountGroups(WF_SHADOW_QUEUE, first, recorded);
        }
        return;
    }
    // RESOLVE must have asked for exactly the rays RECORD recorded; a driver that compiled the two
    // stages' float decisions apart would otherwise read other rays' answers silently.
    if (g_wfShadows != b.z) g_shadowRaysMismatch = true;
    bool live = !g_budgetExceeded;
    if (live && q.hasNext) {
        ray = q.next;
    } else if (live && HAS_PATH_STACK && g_pathTop > 0u) {
        ray = loadStackEntry(--g_pathTop);
    } else {
        live = false;
    }
    if (live) wfStoreRay(ray);
    wfStore(WF_RADIANCE, uvec4(floatBitsToUint(radiance), g_pathTop | (live ? WF_LIVE : 0u)));
    if (!live) {
        atomicAdd(status.paths.x, 1u);
    } else {
        uint next = 1u - wfRoundQueue();
        uint index = next == 0u ? atomicAdd(status.paths.y, 1u) : atomicAdd(status.paths.z, 1u);
        wfSetQueueEntry(next, index, g_wfSlot);
        wfCountGroups(next, index, 1u);
    }
}

// SHADOW: invocation i traces the round's shadow ray i (slot + j * paths, SHADE_RECORD's queue).
void wfShadow(uint invocation) {
    uint entry = wfQueueEntry(WF_SHADOW_QUEUE, invocation);
    uint paths = wfPaths();
    g_wfSlot = entry % paths;
    uint j = entry / paths;
    sampleTime = wfLoadFloats(WF_WEIGHT).w;
    uint field = WF_SHADOWS + 2u * j;
    vec4 a = wfLoadFloats(field);
    vec4 d = wfLoadFloats(field + 1u);
    Hit ignored;
    bool blocked = traceScene(a.xyz, d.xyz, a.w, true, ignored);
    wfStore(field + 1u, uvec4(floatBitsToUint(d.xyz), blocked ? 0u : 1u));
}

// ACCUMULATE: invocation p adds the wave's samples of band pixel p (adaptive: of work-list entry p,
// those within its range; odd-numbered ones also to its odd sum) to its sum, in sample order (the
// megakernel's order), a NaN or Inf sample counted and added as black. Returns the pixel; `first`
// gets the first sample it added (for a failure's report).
uint wfAccumulate(uint p, inout uint nonFinite, out uint first) {
    uint index;
    first = passFirstSample(g_wave);
    uint samples = passSamples(g_wave);
    if (ADAPTIVE) {
        uvec4 entry = wfWorkEntry(p);
        index = entry.x;
        first += entry.y;
        samples = first < entry.z ? min(samples, entry.z - first) : 0u;
    } else {
        uvec2 pixel = passTileOrigin(g_wave) + uvec2(p % passTileSize(g_wave).x, p / passTileSize(g_wave).x);
        index = pixel.y * frameWidth() + pixel.x;
    }
    vec4 sum = loadPixelSum(index);
    vec4 oddSum = ADAPTIVE ? loadPixelOddSum(index) : vec4(0.0);
    uint j = 0u;
    for (; j < samples; ++j) {
        if (!chargeLoop()) break;
        g_wfSlot = j * wfBandPixels() + p;
        vec3 radiance = uintBitsToFloat(wfLoad(WF_RADIANCE).xyz);
        if (any(isnan(radiance)) || any(isinf(radiance))) {
            ++nonFinite;
            radiance = vec3(0.0);
        }
        sum.rgb += radiance;
        if (ADAPTIVE && ((first + j) & 1u) != 0u) oddSum.rgb += radiance;
    }
    if (j < samples) markLoopCutOff();
    storePixelSum(index, sum);
    if (ADAPTIVE) storePixelOddSum(index, oddSum);
    return index;
}

// The stages' entry (each wavefront_<stage>.comp's main): the wave's push constants, and this
// invocation's index (a path slot, SHADOW's shadow ray, ACCUMULATE's band pixel).
uint wfBegin() {
    g_wave = passes[VKRT_UNIFORM_INDEX];
    return gl_WorkGroupID.x * 64u + gl_LocalInvocationIndex;
}

// The stage's failures, if any, reported for the slot's pixel and sample.
void wfReport() {
    WfSlotSample slot = wfSlotSample(g_wfSlot);
    reportStatus(slot.pixel.y * frameWidth() + slot.pixel.x, slot.sampleNumber, 0u);
}

#endif
