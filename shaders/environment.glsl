// The environment map in the kernel (docs/RENDERING.md §10): what a ray that leaves the scene
// sees, and a Diffuse surface's light samples of it (importance sampled by luminance). The cube
// geometry and the sampling are shared with the CPU reference (shared/cube_map.h,
// shared/environment_sampling.h); this file fetches the texels and the distribution.
#ifndef VKRT_ENVIRONMENT_GLSL
#define VKRT_ENVIRONMENT_GLSL

#define VKRT_ENV_CDF(i) uintBitsToFloat(imageLoad(environmentCdfTexels, int(i)).x)
#include "environment_sampling.h"

vec3 environmentTexel(uint i) {
    uint p = imageLoad(environmentTexels, int(i)).x;
    return vec3(float(p & 0xffu), float((p >> 8u) & 0xffu), float((p >> 16u) & 0xffu)) * (1.0 / 255.0);
}

// Bilinear between the four nearest texel centres of the bordered face (cube_map.h), so the
// lookup is continuous across the cube's edges.
vec3 environmentRadiance(vec3 dir) {
    uint faceSize = frameEnvironmentFaceSize();
    CubeTexelFootprint f = cubeTexelFootprint(cubeFacePoint(dir), faceSize);
    uint row = faceSize + 2u;
    vec3 top = mix(environmentTexel(f.first), environmentTexel(f.first + 1u), f.weight.x);
    vec3 bottom = mix(environmentTexel(f.first + row), environmentTexel(f.first + row + 1u), f.weight.x);
    return mix(top, bottom, f.weight.y);
}

// What a ray that left the scene along dir sees: the map, weighted against the light samples of
// the Diffuse surface the ray left, if it left one that took them.
vec3 escapedRadiance(vec3 dir, float bouncePdf) {
    vec3 L = environmentRadiance(dir);
    if (!(bouncePdf > 0.0)) return L;
    uint estimator = estimatorKind();
    if (estimator == ESTIMATOR_NEE) return vec3(0.0);  // next-event estimation counted it already
    float lightPdf = float(frameLightSamples()) * environmentPdf(frameEnvironmentCells(), dir);
    return L * misWeight(bouncePdf, lightPdf, estimator == ESTIMATOR_MIS_POWER);
}

// A Diffuse surface's light samples of the map: kd / pi times the integral of L cos over the
// visible sky, k directions drawn by luminance; none with the plain bounce estimator.
vec3 environmentLighting(Surface s, vec3 N, vec3 kd, uint depth, SampleKey key) {
    uint estimator = estimatorKind();
    if (estimator == ESTIMATOR_BOUNCE) return vec3(0.0);
    bool weighs = estimator == ESTIMATOR_MIS_BALANCE || estimator == ESTIMATOR_MIS_POWER;
    uint k = frameLightSamples();
    uint cells = frameEnvironmentCells();
    vec3 sum = vec3(0.0);
    uint j = 0u;
    for (; j < k; ++j) {
        if (!chargeLoop()) break;
        vec2 u = sample2D(samplerKind(), frame.lightGrid, key.pixel, key.index * k + j, dimEnvironment(depth), key.seed);
        vec4 d = sampleEnvironment(cells, u);
        float cosN = dot(N, d.xyz);
        // No light from inside the surface, as for the bounce (emitBounce).
        if (cosN <= 0.0 || dot(d.xyz, s.geomNormal) <= 0.0) continue;
        float w = weighs ? misWeight(float(k) * d.w, cosinePdf(N, d.xyz), estimator == ESTIMATOR_MIS_POWER) : 1.0;
        if (!(w > 0.0)) continue;
        if (!shadowRayClear(offsetTowards(s, d.xyz), d.xyz, FLT_MAX)) continue;
        sum += environmentRadiance(d.xyz) * (w * cosN * EMITTER_INV_PI / d.w);
    }
    if (j < k) markLoopCutOff();
    return kd * sum / float(k);
}

#endif
