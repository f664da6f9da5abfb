// The wavefront renderer's paths in flight (host/gpu/wavefront_renderer.h): the state one stage
// hands to the next, kept in the accumulation buffer after the pixel sums. A wave is a band of
// pixels (the pass's tile) times a run of samples (pass.x .. pass.x + pass.w - 1); its path slot i
// is sample i / (band pixels) of band pixel i % (band pixels), so neighbouring lanes trace
// neighbouring pixels. Each field of the state is an array of one texel per slot (structure of
// arrays: a stage's lanes read consecutive texels):
//   0 ORIGIN    ray origin, depth (uint bits)        1 DIR      ray direction, bounce pdf
//   2 WEIGHT    ray weight, the sample's time        3 RADIANCE radiance so far, stack top | LIVE
//   4 HIT       t, instance, primitive, found (0/1)  5 BARY     barycentrics, shadow rays recorded
//   6 ..        per shadow ray j: origin and tMax, then direction and visibility (0/1)
//   then        per stack entry e: origin/depth, direction/bounce pdf, weight (integrator.glsl's PathRay)
// After the fields, the queues (one slot index per texel, in x): the live paths of even rounds and
// of odd rounds (a round reads one and SHADE_RESOLVE appends the paths that go on to the other),
// then the round's shadow rays (slot + j * paths). RenderStatus::paths counts them: y and z the
// two path queues, w the shadow rays; x the paths ended (read by the host). Appends go through
// atomics, so a queue's order varies from run to run; the image does not, since every entry names
// its slot and a slot's work depends only on the slot.
// The push constants say which wave: tile = the band (x, y, width, height), pass.x = its first
// sample, pass.w = its samples, pass.y = shadow rays per path (the most one hit can cast), pass.z =
// the round's parity (which path queue it reads).
#ifndef VKRT_WAVEFRONT_STATE_GLSL
#define VKRT_WAVEFRONT_STATE_GLSL

const uint WF_ORIGIN = 0u;
const uint WF_DIR = 1u;
const uint WF_WEIGHT = 2u;
const uint WF_RADIANCE = 3u;
const uint WF_HIT = 4u;
const uint WF_BARY = 5u;
const uint WF_SHADOWS = 6u;
const uint WF_LIVE = 0x80000000u;  // RADIANCE.w: the path has a ray to trace

PassParams g_wave;       // the dispatch's push constants (render.comp sets it)
uint g_wfSlot = 0u;      // this invocation's path slot
uint g_wfShadows = 0u;   // shadow rays recorded (SHADE_RECORD) or read back (SHADE_RESOLVE) at this hit
bool g_shadowRaysMismatch = false;  // SHADE_RESOLVE asked for other rays than SHADE_RECORD recorded
uint g_wfRecorded = 0u;  // SHADE_RESOLVE: the shadow rays SHADE_RECORD recorded at this hit (BARY.z)

uint wfBandPixels() { return passTileSize(g_wave).x * passTileSize(g_wave).y; }
uint wfPaths() { return wfBandPixels() * passSamples(g_wave); }
uint wfShadowsPerPath() { return passStride(g_wave); }
// Adaptive rounds (ADAPTIVE, host/adaptive): the accumulation buffer holds two texels per pixel
// (the sum, the odd samples' sum) and then the round's work list, uvec4(pixel, first sample of the
// round, end, 0) per entry; a wave is entries [tile.x, tile.x + tile.z) (tile.w = 1; tile.y = the
// list's length) times sample offsets pass.x .. pass.x + pass.w - 1 within each entry's range, and
// a slot past its entry's range has no sample.
uint wfWorkListTexel() { return ACCUM_TEXELS_PER_PIXEL * frameWidth() * frameHeight(); }
uvec4 wfWorkEntry(uint slot) { return imageLoad(accumTexels, int(wfWorkListTexel() + passTileOrigin(g_wave).x + slot % wfBandPixels())); }
// The first texel of the state: after the pixel sums (and, adaptive, the work list).
uint wfStateTexel() { return ADAPTIVE ? wfWorkListTexel() + passTileOrigin(g_wave).y : frameWidth() * frameHeight(); }
int wfTexel(uint field, uint slot) { return int(wfStateTexel() + field * wfPaths() + slot); }
uvec4 wfLoad(uint field) { return imageLoad(accumTexels, wfTexel(field, g_wfSlot)); }
void wfStore(uint field, uvec4 value) { imageStore(accumTexels, wfTexel(field, g_wfSlot), value); }
vec4 wfLoadFloats(uint field) { return uintBitsToFloat(wfLoad(field)); }
void wfStoreFloats(uint field, vec4 value) { wfStore(field, floatBitsToUint(value)); }

// The queues after the fields (WavefrontPathLayout::texelsPerPath on the host counts them too).
uint wfFields() { return WF_SHADOWS + 2u * wfShadowsPerPath() + 3u * PATH_STACK_SIZE; }
int wfQueueTexel(uint queue, uint index) { return int(wfStateTexel() + (wfFields() + queue) * wfPaths() + index); }
uint wfQueueEntry(uint queue, uint index) { return imageLoad(accumTexels, wfQueueTexel(queue, index)).x; }
void wfSetQueueEntry(uint queue, uint index, uint value) { imageStore(accumTexels, wfQueueTexel(queue, index), uvec4(value, 0u, 0u, 0u)); }
const uint WF_SHADOW_QUEUE = 2u;  // queues 0 and 1: the path queues; the shadow queue spans shadowsPerPath
uint wfRoundQueue() { return passWorkgroups(g_wave) & 1u; }  // pass.z: the round's parity

// Entries [first, first + n) were just appended to queue q: one more workgroup for each multiple of
// 64 among them, so that the queue's dispatch (RenderStatus::queueGroups) covers it. A path queue
// starts at one workgroup (its first invocation has work even when the queue is empty: emptying the
// next one), so entry 0 adds none there.
void wfCountGroups(uint q, uint first, uint n) {
    uint base = q == WF_SHADOW_QUEUE ? 0u : 1u;
    uint before = first == 0u ? 0u : (first - 1u) / 64u + 1u;  // multiples of 64 below first
    uint upTo = first + n == 0u ? 0u : (first + n - 1u) / 64u + 1u;  // multiples of 64 below first + n
    uint added = upTo - before;
    if (base == 1u && first == 0u) added -= 1u;  // entry 0: the group the queue starts with
    if (added > 0u) atomicAdd(status.queueGroups[q].x, added);
}

// The pixel and sample of path slot `slot` of the wave; adaptive, `end` is its entry's end (one
// work-list load for all three), else no limit.
struct WfSlotSample {
    uvec2 pixel;
    uint sampleNumber;
    uint end;
};
WfSlotSample wfSlotSample(uint slot) {
    WfSlotSample s;
    s.sampleNumber = passFirstSample(g_wave) + slot / wfBandPixels();
    s.end = 0xffffffffu;
    if (ADAPTIVE) {
        uvec4 entry = wfWorkEntry(slot);
        s.pixel = uvec2(entry.x % frameWidth(), entry.x / frameWidth());
        s.sampleNumber += entry.y;
        s.end = entry.z;
        return s;
    }
    uint p = slot % wfBandPixels();
    s.pixel = passTileOrigin(g_wave) + uvec2(p % passTileSize(g_wave).x, p / passTileSize(g_wave).x);
    return s;
}

// A hit's shadow rays in the two shading stages. SHADE_RECORD stores each ray and answers
// "blocked" (its shading is thrown away); SHADE_RESOLVE runs the same shading, which asks for the
// same rays in the same order, and answers with what the SHADOW stage found. The megakernel
// traces the ray here and now.
bool shadowRayClear(vec3 origin, vec3 dir, float tMax) {
#ifdef VKRT_DEFERRED_SHADOWS  // the shading stages' modules then hold no traversal at all
    {
        uint j = g_wfShadows++;
        if (j >= wfShadowsPerPath()) {
            g_rayStackOverflow = true;  // the host's bound on shadow rays per hit was wrong: reported
            return false;
        }
        uint field = WF_SHADOWS + 2u * j;
        if (WAVEFRONT_STAGE == WAVEFRONT_SHADE_RESOLVE && j >= g_wfRecorded) {
            g_shadowRaysMismatch = true;  // RECORD recorded fewer: this ray's answer is not there
            return false;
        }
        if (WAVEFRONT_STAGE == WAVEFRONT_SHADE_RECORD) {
            wfStoreFloats(field, vec4(origin, tMax));
            wfStoreFloats(field + 1u, vec4(dir, 0.0));
            return false;
        }
        return wfLoad(field + 1u).w != 0u;
    }
#else
    Hit ignored;
    return !traceScene(origin, dir, tMax, true, ignored);
#endif
}

#endif
