// Descriptor bindings and the scene's feature set (specialization constants), per
// shared/device_host.h. Features switched off are removed by the driver's compiler, so each scene
// runs a kernel with only the paths it needs.
#ifndef VKRT_BINDINGS_GLSL
#define VKRT_BINDINGS_GLSL

#include "motion.h"  // posedInstance below

layout(constant_id = SPEC_HAS_TRIANGLES) const bool HAS_TRIANGLES = true;
layout(constant_id = SPEC_HAS_SPHERES) const bool HAS_SPHERES = true;
layout(constant_id = SPEC_HAS_BOXES) const bool HAS_BOXES = true;
layout(constant_id = SPEC_HAS_INSTANCES) const bool HAS_INSTANCES = true;
layout(constant_id = SPEC_HAS_AREA_LIGHTS) const bool HAS_AREA_LIGHTS = true;
layout(constant_id = SPEC_HAS_SPECULAR) const bool HAS_SPECULAR = true;
layout(constant_id = SPEC_HAS_REFLECTION) const bool HAS_REFLECTION = true;
layout(constant_id = SPEC_HAS_GLOSS) const bool HAS_GLOSS = true;
layout(constant_id = SPEC_HAS_DIELECTRIC) const bool HAS_DIELECTRIC = true;
layout(constant_id = SPEC_HAS_TEXTURES) const bool HAS_TEXTURES = true;
layout(constant_id = SPEC_HAS_COOL_TO_WARM) const bool HAS_COOL_TO_WARM = true;
layout(constant_id = SPEC_MAX_DEPTH) const uint MAX_DEPTH = 4u;
layout(constant_id = SPEC_PATH_STACK_SIZE) const uint PATH_STACK_SIZE = 8u;
layout(constant_id = SPEC_PACKED_NODES) const bool PACKED_NODES = true;  // node layout: device_host.h
layout(constant_id = SPEC_SAMPLER) const uint SAMPLER_KIND = SAMPLER_FROM_FRAME;  // device_host.h
layout(constant_id = SPEC_SAMPLES_PER_DISPATCH) const uint SAMPLES_PER_DISPATCH = 1u;  // render.comp
layout(constant_id = SPEC_HAS_THIN_LENS) const bool HAS_THIN_LENS = true;  // camera.glsl
layout(constant_id = SPEC_HAS_TRANSLUCENCY) const bool HAS_TRANSLUCENCY = true;  // integrator.glsl
layout(constant_id = SPEC_HAS_MOTION) const bool HAS_MOTION = true;  // motion blur: render.comp, traverse.glsl, surface.glsl
layout(constant_id = SPEC_HAS_DIFFUSE) const bool HAS_DIFFUSE = true;  // the path-traced Diffuse: integrator.glsl
layout(constant_id = SPEC_HAS_EMITTERS) const bool HAS_EMITTERS = true;  // shape emitters: emitters.glsl
layout(constant_id = SPEC_HAS_ENVIRONMENT) const bool HAS_ENVIRONMENT = true;  // environment.glsl
layout(constant_id = SPEC_ESTIMATOR) const uint ESTIMATOR_KIND = ESTIMATOR_FROM_FRAME;  // device_host.h
layout(constant_id = SPEC_UNIFORM_INDEX_FROM_GROUPS) const bool UNIFORM_INDEX_FROM_GROUPS = true;  // VKRT_UNIFORM_INDEX
// Adaptive sampling's rounds (host/adaptive): each invocation takes a pixel and its samples from the
// round's work list, and the pixel's odd-numbered samples are also summed (render.comp).
layout(constant_id = SPEC_ADAPTIVE) const bool ADAPTIVE = false;
// WAVEFRONT_OFF: the megakernel (render.comp); else the one stage of the wavefront renderer this
// kernel is (wavefront_<stage>.comp defines VKRT_WAVEFRONT_STAGE before its includes). A constant
// of the module, not a specialisation: each stage's SPIR-V holds only the functions its main
// reaches, so no driver compiles the other stages' code first and drops it later.
#ifdef VKRT_WAVEFRONT_STAGE
const uint WAVEFRONT_STAGE = VKRT_WAVEFRONT_STAGE;
#else
const uint WAVEFRONT_STAGE = WAVEFRONT_OFF;
#endif
const bool WAVEFRONT = WAVEFRONT_STAGE != WAVEFRONT_OFF;
// 0: nothing in the scene pushes (feature_set.cpp), and the path stack's code is compiled out.
const bool HAS_PATH_STACK = PATH_STACK_SIZE > 0u;
const uint PATH_STACK_ENTRIES = HAS_PATH_STACK ? PATH_STACK_SIZE : 1u;  // an array needs one

layout(set = 0, binding = BINDING_NODES, rgba32ui) uniform readonly uimageBuffer bvhNodes;
layout(set = 0, binding = BINDING_PRIMS, rgba32ui) uniform readonly uimageBuffer primitives;
// The scene's tables as texel buffers, each struct its members in order (device_host.h): on
// lavapipe an image load at per-lane indices is an inlined vector gather, while an SSBO load is a
// loop over the lanes with a bounds check and a branch per lane and per word.
layout(set = 0, binding = BINDING_PRIM_INFO, rgba32ui) uniform readonly uimageBuffer primInfoTexels;
layout(set = 0, binding = BINDING_VERTEX_ATTRIBS, rgba32ui) uniform readonly uimageBuffer vertexAttribTexels;
layout(set = 0, binding = BINDING_INSTANCES, rgba32ui) uniform readonly uimageBuffer instanceTexels;
layout(set = 0, binding = BINDING_SHADERS, rgba32ui) uniform readonly uimageBuffer materialTexels;
layout(set = 0, binding = BINDING_LIGHTS, rgba32ui) uniform readonly uimageBuffer lightTexels;
layout(set = 0, binding = BINDING_TEXTURES, rgba32ui) uniform readonly uimageBuffer textureInfoTexels;
layout(set = 0, binding = BINDING_TEXELS, r32ui) uniform readonly uimageBuffer textureTexels;
layout(set = 0, binding = BINDING_EMITTERS, rgba32ui) uniform readonly uimageBuffer emitterTexels;
layout(set = 0, binding = BINDING_EMITTER_TRIANGLES, rgba32ui) uniform readonly uimageBuffer emitterTriangleTexels;
layout(set = 0, binding = BINDING_ENVIRONMENT, r32ui) uniform readonly uimageBuffer environmentTexels;
layout(set = 0, binding = BINDING_ENVIRONMENT_CDF, r32ui) uniform readonly uimageBuffer environmentCdfTexels;
// Uniform values (this block and the push constants) are read at VKRT_UNIFORM_INDEX, which is 0
// but not a compile-time constant. lavapipe (Mesa 22.3, update_inline_shader_state) inlines
// uniforms that feed branches or loop bounds into a copy of the kernel and recompiles it whenever
// push constants or uniform bindings change: here, at every submission. With Mesa's shader disk
// cache those recompiles were cache hits (yet a copy of the kernel each, in memory); without it
// each was a full LLVM compile (host/gpu/README.md, fact 7). The inliner only follows loads at
// constant offsets; an index it cannot fold leaves one compile per pipeline.
// Every dispatch is (n, 1, 1) workgroups (host/gpu/submission_recorder), so gl_NumWorkGroups.z - 1 is 0.
// Only lavapipe needs this: the host sets UNIFORM_INDEX_FROM_GROUPS from the driver
// (kernel_cache.cpp), so every other driver compiles a constant 0 and plain uniform loads.
#define VKRT_UNIFORM_INDEX (UNIFORM_INDEX_FROM_GROUPS ? gl_NumWorkGroups.z - 1u : 0u)
layout(std140, set = 0, binding = BINDING_FRAME) uniform FrameBuffer { FrameParams frames[1]; };
#define frame frames[VKRT_UNIFORM_INDEX]
// FrameParams' lanes by name (device_host.h), each read straight from the block: a function taking
// `frame` would load whole vec4s and keep them live across the kernel's loops.
float framePlaneWidth() { return frame.cameraU.w; }
float framePlaneHeight() { return frame.cameraV.w; }
float frameFocalLength() { return frame.cameraW.w; }
float frameLensRadius() { return frame.cameraPosition.w; }
float frameFocusDistance() { return frame.background.w; }
float frameShutterOpen() { return frame.shutter.x; }
float frameShutterClose() { return frame.shutter.y; }
uint frameWidth() { return frame.image.x; }
uint frameHeight() { return frame.image.y; }
uint frameCameraType() { return frame.image.z; }
uint frameFinalRaysDark() { return frame.image.w; }  // FINAL_*_DARK bits (and PATH_DIELECTRIC_ONE_BRANCH)
bool frameDielectricOneBranch() { return (frame.image.w & PATH_DIELECTRIC_ONE_BRANCH) != 0u; }
uint frameSampler() { return frame.sampling.x; }
uint frameLightSamples() { return frame.sampling.z; }
uint frameGlossSamples() { return frame.sampling.w; }
uint frameSeed() { return frame.scene.x; }
uint frameMaxDepth() { return frame.scene.y; }
uint frameLightCount() { return frame.scene.z; }
uint frameTopLevelRoot() { return frame.scene.w; }
uint frameEmitterCount() { return frame.lighting.x; }
uint frameEstimator() { return frame.lighting.y; }
uint frameEnvironmentFaceSize() { return frame.lighting.z; }
uint frameEnvironmentCells() { return frame.lighting.w; }

// The render's sampler (SAMPLER_*): the specialization constant, or for the general kernel the
// frame's value. Every sample2D call takes it from here.
uint samplerKind() { return SAMPLER_KIND == SAMPLER_FROM_FRAME ? frameSampler() : SAMPLER_KIND; }
// The render's estimator (ESTIMATOR_*) the same way.
uint estimatorKind() { return ESTIMATOR_KIND == ESTIMATOR_FROM_FRAME ? frameEstimator() : ESTIMATOR_KIND; }
// The per-pixel sums, a texel buffer rather than an SSBO: on lavapipe an SSBO load at per-lane
// addresses is a loop over the lanes, one scalar load (and cache miss) at a time, while imageLoad
// is a gather (host/gpu/README.md, fact 3).
layout(set = 0, binding = BINDING_ACCUM, rgba32ui) uniform uimageBuffer accumTexels;
layout(std430, set = 0, binding = BINDING_STATUS) coherent buffer StatusBuffer { RenderStatus status; };

PrimInfo loadPrimInfo(uint i) {
    PrimInfo p;
    p.data = imageLoad(primInfoTexels, int(i));
    return p;
}

// A pixel's running sum (rgb; w unused), read and written by the one invocation that computes the
// pixel's samples of a pass: no race. Adaptive, each pixel has two texels, the sum and the sum of
// its odd-numbered samples, and the round's work list follows the pixels (device_host.h).
const uint ACCUM_TEXELS_PER_PIXEL = ADAPTIVE ? 2u : 1u;
vec4 loadPixelSum(uint pixel) { return uintBitsToFloat(imageLoad(accumTexels, int(pixel * ACCUM_TEXELS_PER_PIXEL))); }
void storePixelSum(uint pixel, vec4 sum) { imageStore(accumTexels, int(pixel * ACCUM_TEXELS_PER_PIXEL), floatBitsToUint(sum)); }
vec4 loadPixelOddSum(uint pixel) { return uintBitsToFloat(imageLoad(accumTexels, int(pixel * 2u + 1u))); }
void storePixelOddSum(uint pixel, vec4 sum) { imageStore(accumTexels, int(pixel * 2u + 1u), floatBitsToUint(sum)); }

VertexAttrib loadVertexAttrib(uint i) {
    int t = int(i * VERTEX_ATTRIB_TEXELS);
    VertexAttrib a;
    a.normalU = uintBitsToFloat(imageLoad(vertexAttribTexels, t));
    a.vPad = uintBitsToFloat(imageLoad(vertexAttribTexels, t + 1));
    return a;
}

// Row `row` (0-8) of an instance's three 3x4 matrices, and its info texel.
vec4 instanceRow(uint i, uint row) { return uintBitsToFloat(imageLoad(instanceTexels, int(i * INSTANCE_TEXELS + row))); }
uvec4 instanceInfo(uint i) { return imageLoad(instanceTexels, int(i * INSTANCE_TEXELS + INSTANCE_INFO_TEXEL)); }

// Motion blur: the time of the camera sample being traced (render.comp sets it per sample when
// HAS_MOTION; every ray of the sample's tree sees the scene at that time).
float sampleTime = 0.0;

// A moving instance's poses (device_host.h InstanceMotion), at `texel` of the instance table.
InstanceMotion loadInstanceMotion(uint texel) {
    InstanceMotion m;
    int t = int(texel);
    m.translation0 = uintBitsToFloat(imageLoad(instanceTexels, t));
    m.translation1 = uintBitsToFloat(imageLoad(instanceTexels, t + 1));
    m.rotation0 = uintBitsToFloat(imageLoad(instanceTexels, t + 2));
    m.rotation1 = uintBitsToFloat(imageLoad(instanceTexels, t + 3));
    for (int k = 0; k < 3; ++k) {
        m.stretch0[k] = uintBitsToFloat(imageLoad(instanceTexels, t + 4 + k));
        m.stretch1[k] = uintBitsToFloat(imageLoad(instanceTexels, t + 7 + k));
    }
    return m;
}

// Instance i's three matrices where it is at sampleTime (motion.h); only for a moving instance.
Instance posedInstance(uint i, uint motionTexel) {
    Instance still;
    still.info = uvec4(0u);
    return instanceAtTime(still, loadInstanceMotion(motionTexel), sampleTime);
}
// The motion record of instance i, or MOTION_NONE (always MOTION_NONE without HAS_MOTION).
uint instanceMotion(uint i) { return HAS_MOTION ? instanceMotionTexel(instanceInfo(i)) : MOTION_NONE; }

Material loadMaterial(uint i) {
    int t = int(i * MATERIAL_TEXELS);
    Material m;
    m.diffuse = uintBitsToFloat(imageLoad(materialTexels, t));
    m.specular = uintBitsToFloat(imageLoad(materialTexels, t + 1));
    m.attenuation = uintBitsToFloat(imageLoad(materialTexels, t + 2));
    m.params = uintBitsToFloat(imageLoad(materialTexels, t + 3));
    m.ids = imageLoad(materialTexels, t + 4);
    return m;
}

Light loadLight(uint i) {
    int t = int(i * LIGHT_TEXELS);
    Light l;
    l.position = uintBitsToFloat(imageLoad(lightTexels, t));
    l.intensity = uintBitsToFloat(imageLoad(lightTexels, t + 1));
    l.edgeU = uintBitsToFloat(imageLoad(lightTexels, t + 2));
    l.edgeV = uintBitsToFloat(imageLoad(lightTexels, t + 3));
    l.info = imageLoad(lightTexels, t + 4);
    return l;
}

EmitterRecord loadEmitter(uint i) {
    int t = int(i * EMITTER_TEXELS);
    EmitterRecord e;
    e.radiance = uintBitsToFloat(imageLoad(emitterTexels, t));
    e.sphere = uintBitsToFloat(imageLoad(emitterTexels, t + 1));
    for (int r = 0; r < 3; ++r) {
        e.toWorld[r] = uintBitsToFloat(imageLoad(emitterTexels, t + 2 + r));
        e.toObject[r] = uintBitsToFloat(imageLoad(emitterTexels, t + 5 + r));
    }
    e.info = imageLoad(emitterTexels, t + 8);
    e.choice = uintBitsToFloat(imageLoad(emitterTexels, t + 9));
    return e;
}
// Only the cumulative choice share, for the binary search.
float emitterChoiceShare(uint i) { return uintBitsToFloat(imageLoad(emitterTexels, int(i * EMITTER_TEXELS) + 9).y); }

EmitterTriangle loadEmitterTriangle(uint i) {
    int t = int(i * EMITTER_TRIANGLE_TEXELS);
    EmitterTriangle tri;
    tri.corner = uintBitsToFloat(imageLoad(emitterTriangleTexels, t));
    tri.edge1 = uintBitsToFloat(imageLoad(emitterTriangleTexels, t + 1));
    tri.edge2 = uintBitsToFloat(imageLoad(emitterTriangleTexels, t + 2));
    return tri;
}
// Only the cumulative share, for the binary search.
float emitterTriangleShare(uint i) { return uintBitsToFloat(imageLoad(emitterTriangleTexels, int(i * EMITTER_TRIANGLE_TEXELS)).w); }

TextureInfo loadTextureInfo(uint i) {
    TextureInfo t;
    t.info = imageLoad(textureInfoTexels, int(i));
    return t;
}

#endif
