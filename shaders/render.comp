#version 460
// The render kernel: one invocation computes pass.w consecutive samples of one pixel and adds
// them to the pixel's running sum. One dispatch = one pass of samples over one tile; the host
// sizes the pass so that an invocation stays far below lavapipe's loop limit and each submission
// short (host/gpu: sample_batching.h, tile_planner.h).
#extension GL_GOOGLE_include_directive : require

#include "kernel.glsl"

const uint NO_SAMPLE = 0xffffffffu;

// Sample `index` of pixel (x, y), added to the pixel's running sum (and, adaptive, an odd-numbered
// one also to its odd sum); a NaN or Inf sample is counted and added as black, and the first
// sample with a failure is remembered for the host's message.
void addSample(uint x, uint y, uint index, inout SampleKey key, inout vec4 sum, inout vec4 oddSum, inout uint nonFinite,
               inout uint failedSample) {
    CameraRay camera = cameraSample(x, y, index, key);
    vec3 radiance = cameraSampleRadiance(camera.origin, camera.dir, key);
    if (failedSample == NO_SAMPLE && failureFlags() != 0u) failedSample = index;
    if (any(isnan(radiance)) || any(isinf(radiance))) {
        ++nonFinite;
        radiance = vec3(0.0);
    }
    sum.rgb += radiance;
    if (ADAPTIVE && (index & 1u) != 0u) oddSum.rgb += radiance;
}

// The pixel of this invocation in the pass's tile (8x8 blocks of 4x2 lane patches); false outside it.
bool tilePixel(PassParams pass, out uint x, out uint y) {
    uvec2 tileOrigin = passTileOrigin(pass);
    uvec2 tileSize = passTileSize(pass);
    // Workgroups are handed to lavapipe's threads in contiguous chunks; visiting blocks in a
    // strided order spreads expensive regions of the image over all threads.
    // The host keeps groups <= 65536 and stride < groups, so the product fits in 32 bits.
    uint groups = passWorkgroups(pass);
    uint block = (gl_WorkGroupID.x * passStride(pass)) % groups;
    uint blocksX = (tileSize.x + 7u) / 8u;
    uint lane = gl_LocalInvocationIndex;
    uint laneGroup = lane >> 3u;
    uint px = (laneGroup & 1u) * 4u + (lane & 3u);
    uint py = (laneGroup >> 1u) * 2u + ((lane >> 2u) & 1u);
    uint localX = (block % blocksX) * 8u + px;
    uint localY = (block / blocksX) * 8u + py;
    if (localX >= tileSize.x || localY >= tileSize.y) return false;
    x = tileOrigin.x + localX;
    y = tileOrigin.y + localY;
    return true;
}

// Adaptive sampling (host/adaptive): the invocation takes entry `index` of the round's work list
// (after the pixels' sums in the accumulation buffer, device_host.h BINDING_ACCUM): the pixel and
// its samples [first, end) of this round; pass p computes samples first + p k ... of it. False for
// an invocation past the list or a pixel whose samples this round are done.
bool adaptiveWork(PassParams pass, out uint x, out uint y, out uint first, out uint count) {
    uint index = passTileOrigin(pass).x + gl_WorkGroupID.x * 64u + gl_LocalInvocationIndex;
    if (index >= passTileOrigin(pass).x + passTileSize(pass).x) return false;
    uvec4 work = imageLoad(accumTexels, int(ACCUM_TEXELS_PER_PIXEL * frameWidth() * frameHeight() + index));
    first = work.y + passFirstSample(pass);
    if (first >= work.z) return false;
    count = min(passSamples(pass), work.z - first);
    x = work.x % frameWidth();
    y = work.x / frameWidth();
    return true;
}

void main() {
    PassParams pass = passes[VKRT_UNIFORM_INDEX];
    uint x, y, firstSample, samples;
    if (ADAPTIVE) {
        if (!adaptiveWork(pass, x, y, firstSample, samples)) return;
    } else {
        firstSample = passFirstSample(pass);
        samples = passSamples(pass);
        if (!tilePixel(pass, x, y)) return;
    }

    SampleKey key;
    key.pixel = y * frameWidth() + x;
    key.seed = frameSeed();
    // The pixel's sum is loaded once and stored once per pass (each stored word is a loop over
    // the lanes on lavapipe); the samples are added to it one by one in sample order, so the image
    // does not depend on the pass size (sample_batching.h).
    vec4 sum = loadPixelSum(key.pixel);
    vec4 oddSum = ADAPTIVE ? loadPixelOddSum(key.pixel) : vec4(0.0);
    uint nonFinite = 0u;
    uint failedSample = NO_SAMPLE;
    if (SAMPLES_PER_DISPATCH == 1u) {
        // No loop: a loop around the path, even of one pass, made meshes slower
        // (docs/lab/2026-12-02-lavapipe-kernel.md).
        addSample(x, y, firstSample, key, sum, oddSum, nonFinite, failedSample);
    } else {
        uint j = 0u;
        for (; j < samples; ++j) {
            if (!chargeLoop()) break;
            addSample(x, y, firstSample + j, key, sum, oddSum, nonFinite, failedSample);
        }
        if (j < samples) markLoopCutOff();
    }

    reportStatus(key.pixel, failedSample != NO_SAMPLE ? failedSample : firstSample, nonFinite);
    storePixelSum(key.pixel, sum);
    if (ADAPTIVE) storePixelOddSum(key.pixel, oddSum);
}
