// Every struct and binding that crosses the host/device boundary, defined once.
// Included by C++ (host/, bvh_builder/) and by GLSL (shaders/*.comp). Layout rules:
//  - SSBO structs follow std430: vec4/uvec4 members only, so C++ and GLSL agree without padding
//    surprises; the static_asserts below pin every size.
//  - BVH nodes and primitives are read through RGBA32UI read-only storage texel buffers
//    (uimageBuffer, imageLoad): on Mesa 22.3 lavapipe texelFetch was faster than SSBO loads
//    (../shared/LAVAPIPE.md), and imageLoad, which its JIT inlines where texelFetch is a call per
//    fetch, faster again (host/gpu/README.md, facts 3 and 4).
//    Integer texels are returned bit-exact, so float fields are stored as their bit patterns and
//    decoded with uintBitsToFloat; no denormal or NaN canonicalisation can touch the integers.
//  - A packed vec4/uvec4 slot (Instance::info, Material::ids, ...) is read through the free
//    function named for its meaning, below its struct (GLSL has no methods; VKRT_FN makes them
//    inline in C++). Each returns one lane of a value the caller holds, so it costs nothing once
//    inlined. A function takes the whole struct, except where the kernel fetches one texel of a
//    larger struct alone (Instance info, a Primitive's first texel): then it takes that texel.
//    The uniform blocks (FrameParams, TraceParams) are the exception: the kernels name their lanes
//    with functions that read the block itself (bindings.glsl, trace_rays.comp; see FrameParams).
#ifndef VKRT_DEVICE_HOST_H
#define VKRT_DEVICE_HOST_H

#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
namespace vkrt::gpu {
using uint = std::uint32_t;
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec2 = glm::uvec2;
using uvec3 = glm::uvec3;
using uvec4 = glm::uvec4;
using ivec4 = glm::ivec4;
#define VKRT_CONST static constexpr
#define VKRT_FN inline
#else
#define VKRT_CONST const
#define VKRT_FN
#endif

// ---------------------------------------------------------------------------------------------
// Descriptor set 0 bindings.
VKRT_CONST uint BINDING_NODES = 0;         // readonly uimageBuffer RGBA32UI, GpuBvhNode or GpuExactBvhNode
VKRT_CONST uint BINDING_PRIMS = 1;         // readonly uimageBuffer RGBA32UI, PRIM_TEXELS texels per primitive
// The read-only tables below are RGBA32UI texel buffers too (uimageBuffer): each struct is its
// vec4/uvec4 members in order, one texel each (the *_TEXELS counts, pinned by static_asserts).
VKRT_CONST uint BINDING_PRIM_INFO = 2;     // PrimInfo[], parallel to the primitive array
VKRT_CONST uint BINDING_VERTEX_ATTRIBS = 3;// VertexAttrib[] (mesh normals and uvs)
VKRT_CONST uint BINDING_INSTANCES = 4;     // Instance[]
VKRT_CONST uint BINDING_SHADERS = 5;       // Material[]
VKRT_CONST uint BINDING_LIGHTS = 6;        // Light[]
VKRT_CONST uint BINDING_TEXTURES = 7;      // TextureInfo[]
VKRT_CONST uint BINDING_TEXELS = 8;        // readonly uimageBuffer R32UI: RGBA8 packed texels of all textures
VKRT_CONST uint BINDING_FRAME = 9;         // UBO FrameParams
VKRT_CONST uint BINDING_ACCUM = 10;        // uimageBuffer RGBA32UI: per-pixel radiance sum (rgb float bits), w unused;
                                           // adaptive (SPEC_ADAPTIVE): per pixel the sum and the odd samples' sum,
                                           // then the round's work list, AdaptiveWork per entry
VKRT_CONST uint BINDING_STATUS = 11;       // SSBO RenderStatus
VKRT_CONST uint BINDING_EMITTERS = 12;     // EmitterRecord[] (shape emitters)
VKRT_CONST uint BINDING_EMITTER_TRIANGLES = 13;  // EmitterTriangle[]
VKRT_CONST uint BINDING_ENVIRONMENT = 14;  // readonly uimageBuffer R32UI: the environment map's bordered cube faces, RGBA8
VKRT_CONST uint BINDING_ENVIRONMENT_CDF = 15;  // readonly uimageBuffer R32UI: its luminance distribution (float bits)
VKRT_CONST uint RENDER_BINDING_COUNT = 16; // render.comp declares bindings 0 .. 15
VKRT_CONST uint BINDING_RAYS = 16;         // trace_rays.comp only: readonly uimageBuffer RGBA32UI, TraceRayInput = 2 texels
VKRT_CONST uint BINDING_HITS = 17;         // trace_rays.comp only: writeonly uimageBuffer R32UI, TRACE_HIT_WORDS(_INSTANCED) per ray

// ---------------------------------------------------------------------------------------------
// BVH node as the kernels read it: 48 bytes = 3 RGBA32UI texels, both children's boxes side by
// side (Aila & Laine 2009), so one contiguous fetch per inner step decides both children. The host
// makes one per node of the builder's tree (bvh::BinaryNode, bvh_builder/node_layout.h), in the
// same order (host/gpu/node_packing.h).
//   texel 0: child 0 box  lo.x hi.x lo.y hi.y   (float bits)
//   texel 1: child 1 box  lo.x hi.x lo.y hi.y   (float bits)
//   texel 2: lo0.z hi0.z lo1.z hi1.z            (float bits)
// Each child's link and count travel as its ready stack entry (traverse.glsl: an inner node's first
// texel, index * GPU_NODE_TEXELS, so the walk's fetch waits on no multiply;
// ENTRY_LEAF_BIT | first << 4 | count for a bottom-level leaf, ENTRY_INSTANCE_BIT | instance for a
// top-level leaf, ENTRY_NONE for an empty child) in the low bits of the child's own box floats:
// NODE_ENTRY_XY_BITS bits in each of lo.x hi.x lo.y hi.y (entry bits 0-23), NODE_ENTRY_Z_BITS in
// lo.z and hi.z (bits 24-31). The host rounds each bound outward to the nearest float with those
// low bits, so the box the kernel reads contains the builder's box (looser by at most
// 2 * 2^6 ulp = 2^-16 of the bound's magnitude in x and y, 2^-18 in z).
// Why: lavapipe fetches a texel per lane (an address extract, a load and a transpose: about 40
// instructions per texel), and the walk fetches one node per pass; the fourth texel cost
// more than the bit unpacking.
// The looseness is relative to a bound's magnitude, so geometry far from its origin compared with
// its size (a mesh modelled at x = 10^4) would get boxes far larger than its triangles. The host
// packs only when that costs little (node_packing.h: the child boxes' total surface area grows by
// at most 1%) and otherwise uploads GpuExactBvhNode: the builder's boxes unchanged, with the two
// ready entries in a fourth texel (x, y; z and w zero). SPEC_PACKED_NODES tells the kernel which.
// An empty child's box is inverted (lo = +FLT_MAX, hi = -FLT_MAX), which the kernel's min/max slab
// test accepts as everything: the walk skips an empty child by its entry, never by its box.
VKRT_CONST uint GPU_NODE_TEXELS = 3;
VKRT_CONST uint GPU_EXACT_NODE_TEXELS = 4;
VKRT_CONST uint NODE_ENTRY_XY_BITS = 6u;
VKRT_CONST uint NODE_ENTRY_Z_BITS = 4u;
VKRT_CONST uint ENTRY_INSTANCE_BIT = 0x80000000u;
VKRT_CONST uint ENTRY_NONE = 0xfffffffeu;
// traverse.glsl keeps a bottom-level leaf on its stack as one 32-bit entry: ENTRY_LEAF_BIT, the
// first primitive in bits 4..29 and the count in bits 0..3 (an inner node's entry is its first
// texel, below 2^30). The host refuses a BVH with a leaf that does not fit (host/gpu/traversal_stack.h);
// the builder's leaves hold at most 8 primitives and a 128 MiB buffer at most 2.8M primitives.
VKRT_CONST uint ENTRY_LEAF_BIT = 0x40000000u;
VKRT_CONST uint LEAF_ENTRY_MAX_COUNT = 15u;
VKRT_CONST uint LEAF_ENTRY_MAX_FIRST = 0x3ffffffu;
struct GpuBvhNode {
    uvec4 xy0;
    uvec4 xy1;
    uvec4 z01;
};
struct GpuExactBvhNode {
    uvec4 xy0;
    uvec4 xy1;
    uvec4 z01;
    uvec4 entries;
};

// ---------------------------------------------------------------------------------------------
// Primitive: 48 bytes = 3 RGBA32UI texels; the leaf ranges of every bottom-level BVH index this
// array directly (primitives are reordered so each leaf is contiguous).
//   triangle: a = v0.xyz | tag, b = v1.xyz | 0, c = v2.xyz | 0
//   sphere:   a = centre.xyz | tag, b = (radius, 0, 0) | 0, c = 0
//   box:      a = lo.xyz | tag, b = hi.xyz | 0, c = 0
// tag = kind (PRIM_KIND_*) in the low 2 bits; the rest is unused by traversal.
VKRT_CONST uint PRIM_TEXELS = 3;
VKRT_CONST uint PRIM_KIND_TRIANGLE = 0u;
VKRT_CONST uint PRIM_KIND_SPHERE = 1u;
VKRT_CONST uint PRIM_KIND_BOX = 2u;
VKRT_CONST uint PRIM_KIND_MASK = 3u;
struct Primitive {
    uvec4 a;
    uvec4 b;
    uvec4 c;
};
// PRIM_KIND_* of the primitive whose first texel (Primitive::a) is `a`.
VKRT_FN uint primitiveKind(uvec4 a) { return a.w & PRIM_KIND_MASK; }

// Per primitive, fetched once at the closest hit (never during traversal). 16 bytes.
//   x: material index (the prototype's or the loose shape's own; an instance override wins)
//   y, z, w: vertex attribute indices of a mesh triangle's corners, or ATTRIB_NONE (flat normal)
VKRT_CONST uint ATTRIB_NONE = 0xffffffffu;
struct PrimInfo {
    uvec4 data;
};
VKRT_FN uint primitiveMaterial(PrimInfo p) { return p.data.x; }
// The vertex attributes of corners 0, 1, 2 (ATTRIB_NONE: a flat normal).
VKRT_FN uvec3 primitiveCornerAttribs(PrimInfo p) { return uvec3(p.data.y, p.data.z, p.data.w); }
VKRT_CONST uint PRIM_INFO_TEXELS = 1;

// Mesh vertex attributes: normal.xyz + u, then v. 32 bytes.
struct VertexAttrib {
    vec4 normalU;
    vec4 vPad;
};
VKRT_FN vec3 vertexNormal(VertexAttrib v) { return vec3(v.normalU.x, v.normalU.y, v.normalU.z); }
VKRT_FN vec2 vertexUv(VertexAttrib v) { return vec2(v.normalU.w, v.vPad.x); }
VKRT_CONST uint VERTEX_ATTRIB_TEXELS = 2;

// ---------------------------------------------------------------------------------------------
// Instance: one bottom-level BVH placed by an affine transform. 160 bytes.
// Rays are transformed into object space without renormalising the direction, so hit distances
// t are the same in both spaces (world units).
VKRT_CONST uint MATERIAL_NONE = 0xffffffffu;
struct Instance {
    vec4 worldToObject[3];  // rows of the 3x4 inverse affine transform
    vec4 objectToWorld[3];  // rows of the 3x4 affine transform
    vec4 normalToWorld[3];  // rows of the inverse transpose of the 3x3 part (w unused)
    uvec4 info;             // x: root node of the bottom-level BVH, y: material override or
                            // MATERIAL_NONE, z: geometry group, w: the first texel of the
                            // instance's InstanceMotion in the same table, or MOTION_NONE
};
VKRT_CONST uint INSTANCE_TEXELS = 10;     // worldToObject rows at texels 0-2, objectToWorld 3-5, normalToWorld 6-8
VKRT_CONST uint INSTANCE_INFO_TEXEL = 9;
// Of an Instance::info texel (the kernels fetch it alone: bindings.glsl instanceInfo).
VKRT_FN uint instanceRootNode(uvec4 info) { return info.x; }
VKRT_FN uint instanceMaterialOverride(uvec4 info) { return info.y; }
VKRT_FN uint instanceGroup(uvec4 info) { return info.z; }
VKRT_FN uint instanceMotionTexel(uvec4 info) { return info.w; }

// A moving instance's two poses (motion blur, docs/RENDERING.md §9), decomposed once on the host
// (bvh_builder/instance_motion.h) as M = T * R * S: translation, unit quaternion (x, y, z, w) and
// the 3x3 stretch (rows). Time 0 is the instance's transform, time 1 its end transform; motion.h
// interpolates T and S linearly and R by slerp. The records follow the instances in the instance
// table (Instance::info.w names the first texel). 160 bytes.
VKRT_CONST uint MOTION_NONE = 0u;  // texel 0 is instance 0's: never a motion record's
struct InstanceMotion {
    vec4 translation0;  // xyz, w = the angle between the rotations (radians, 0..pi)
    vec4 translation1;  // xyz, w = 1 / sin(angle), 0 where the rotations are too close to slerp
    vec4 rotation0;     // unit quaternion (x, y, z, w)
    vec4 rotation1;     // the same, on rotation0's side (dot >= 0)
    vec4 stretch0[3];   // rows of S at time 0 (w unused)
    vec4 stretch1[3];   // rows of S at time 1
};
VKRT_CONST uint MOTION_TEXELS = 10;

// ---------------------------------------------------------------------------------------------
// Material (the format's <shader>). 80 bytes.
VKRT_CONST uint SHADER_LAMBERTIAN = 0u;
VKRT_CONST uint SHADER_BLINN_PHONG = 1u;
VKRT_CONST uint SHADER_MIRROR = 2u;
VKRT_CONST uint SHADER_GLAZE = 3u;
VKRT_CONST uint SHADER_BLINN_PHONG_MIRRORED = 4u;
VKRT_CONST uint SHADER_DIELECTRIC = 5u;
VKRT_CONST uint SHADER_COOL_TO_WARM = 6u;
VKRT_CONST uint SHADER_DIFFUSE = 7u;   // the course's path-traced Diffuse (Lambertian plus the diffuse bounce)
VKRT_CONST uint SHADER_EMITTER = 8u;   // a shape emitter's surface: radiance ids.w's EmitterRecord, reflects nothing
VKRT_CONST uint TEXTURE_NONE = 0xffffffffu;
struct Material {
    vec4 diffuse;      // rgb diffuse (tint when textured), w unused
    vec4 specular;     // rgb specular, w = phongExp
    vec4 attenuation;  // rgb transmittance per unit distance (dielectric), w = refractive index
    vec4 params;       // x = mirrorCoef, y = roughness, z, w unused
    uvec4 ids;         // x = SHADER_* type, y = diffuse texture, z = specular texture,
                       // w = the EmitterRecord of a SHADER_EMITTER (its radiance is in diffuse.rgb)
};
VKRT_CONST uint MATERIAL_TEXELS = 5;
VKRT_FN uint materialType(Material m) { return m.ids.x; }
VKRT_FN uint materialDiffuseTexture(Material m) { return m.ids.y; }
VKRT_FN uint materialSpecularTexture(Material m) { return m.ids.z; }
VKRT_FN float materialPhongExponent(Material m) { return m.specular.w; }
VKRT_FN float materialRefractiveIndex(Material m) { return m.attenuation.w; }
VKRT_FN float materialMirrorCoef(Material m) { return m.params.x; }
VKRT_FN float materialRoughness(Material m) { return m.params.y; }
VKRT_FN uint materialEmitter(Material m) { return m.ids.w; }

// ---------------------------------------------------------------------------------------------
// Light. 80 bytes. A point light has zero edges; an area light is the rectangle
// centre + s*edgeU + t*edgeV, s,t in [-1/2, 1/2]. No falloff, no emitter cosine (course convention).
VKRT_CONST uint LIGHT_POINT = 0u;
VKRT_CONST uint LIGHT_AREA = 1u;
struct Light {
    vec4 position;   // xyz: point position or area centre
    vec4 intensity;  // rgb
    vec4 edgeU;      // xyz: width  * tangent
    vec4 edgeV;      // xyz: length * bitangent
    uvec4 info;      // x: LIGHT_* type, y: area-light ordinal (sampling dimension), z, w unused
};
VKRT_CONST uint LIGHT_TEXELS = 5;
VKRT_FN uint lightType(Light l) { return l.info.x; }
VKRT_FN uint lightAreaOrdinal(Light l) { return l.info.y; }

// ---------------------------------------------------------------------------------------------
// Shape emitters (a JSON `light` of `_type: "shape"`; docs/RENDERING.md §4): geometry that is
// visible with radiance L and lights the scene as a continuum of course point lights, sampled by
// shaders/shared/emitter_sampling.h. Built on the host from the scene (host/lighting/emitter_table.h)
// in Scene::emitters order; EMITTER_TEXELS texels each, then the world-space triangles of every
// EMITTER_TRIANGLES emitter in their own table.
//  - EMITTER_SPHERE: a sphere placed by a similarity (uniform scale, rotation, mirror), sampled
//    by the solid angle it subtends (a cone of directions), over its whole area from inside it;
//  - EMITTER_ELLIPSOID: a sphere under any other affine map, sampled uniformly over the object
//    sphere's area and mapped by the transform (its world area density varies over the surface);
//  - EMITTER_TRIANGLES: a triangle, a box's twelve or a mesh's triangles in world space, sampled
//    by world area (a triangle by its cumulative area share, then uniformly inside it).
VKRT_CONST uint EMITTER_SPHERE = 0u;
VKRT_CONST uint EMITTER_ELLIPSOID = 1u;
VKRT_CONST uint EMITTER_TRIANGLES = 2u;
struct EmitterRecord {
    vec4 radiance;     // rgb emitted radiance (both sides); w: the area density, 1 / total world
                       // area (TRIANGLES), or 1 / (4 pi r^2 |det M|) (ELLIPSOID, emitter_sampling.h)
    vec4 sphere;       // xyz centre, w radius: in world space (SPHERE), in object space (ELLIPSOID),
                       // the triangles' world bounding sphere (TRIANGLES: emitter_sampling.h solidAngleNear)
    vec4 toWorld[3];   // ELLIPSOID: rows of the 3x4 object-to-world transform
    vec4 toObject[3];  // ELLIPSOID: rows of its inverse
    uvec4 info;        // x: EMITTER_* kind, y: first EmitterTriangle, z: triangle count,
                       // w: light ordinal (its sampling dimension, after the area lights)
    vec4 choice;       // x: the probability that a light sample goes to this emitter (its share
                       // of the emitters' estimated power), y: the cumulative share up to and
                       // including it (the last is exactly 1), z: 1 for a convex emitter (a box),
                       // whose light samples seen from outside go to the faces in front
                       // (emitter_sampling.h triangleFacesPoint), else 0
};
VKRT_CONST uint EMITTER_TEXELS = 10;
VKRT_FN uint emitterKind(EmitterRecord e) { return e.info.x; }
VKRT_FN uint emitterFirstTriangle(EmitterRecord e) { return e.info.y; }
VKRT_FN uint emitterTriangleCount(EmitterRecord e) { return e.info.z; }
VKRT_FN uint emitterLightOrdinal(EmitterRecord e) { return e.info.w; }
VKRT_FN float emitterAreaPdf(EmitterRecord e) { return e.radiance.w; }
VKRT_FN float emitterChoicePdf(EmitterRecord e) { return e.choice.x; }
VKRT_FN bool emitterConvex(EmitterRecord e) { return e.choice.z != 0.0f; }
struct EmitterTriangle {
    vec4 corner;  // xyz v0 (world), w: the emitter's area share of its triangles up to and including this one
    vec4 edge1;   // xyz v1 - v0
    vec4 edge2;   // xyz v2 - v0
};
VKRT_CONST uint EMITTER_TRIANGLE_TEXELS = 3;
VKRT_FN float emitterTriangleCdf(EmitterTriangle t) { return t.corner.w; }

// Texture: texels[offset .. offset + width*height), row 0 = top row of the image, RGBA8 packed
// little-endian (r in the low byte), values used linearly (no sRGB decode, like the course).
struct TextureInfo {
    uvec4 info;  // x: offset, y: width, z: height, w: unused
};
VKRT_CONST uint TEXTURE_INFO_TEXELS = 1;
VKRT_FN uint textureFirstTexel(TextureInfo t) { return t.info.x; }
VKRT_FN uint textureWidth(TextureInfo t) { return t.info.y; }
VKRT_FN uint textureHeight(TextureInfo t) { return t.info.z; }

// ---------------------------------------------------------------------------------------------
// Per-render constants (UBO, std140-compatible because every member is a 16-byte vector).
VKRT_CONST uint CAMERA_PERSPECTIVE = 0u;
VKRT_CONST uint CAMERA_ORTHOGRAPHIC = 1u;
// FrameParams::image.w: a Diffuse bounce (1) / a reflection or refraction ray (2) that would end
// at the maximum depth finds no light there, so it is not traced (the image is the same).
VKRT_CONST uint FINAL_BOUNCE_DARK = 1u;
VKRT_CONST uint FINAL_REFLECTION_DARK = 2u;
// FrameParams::image.w, too: a Diffuse surface is rendered (used_shaders.h pathTraced), so a
// dielectric hit continues one branch, reflection with probability F (docs/RENDERING.md §6).
VKRT_CONST uint PATH_DIELECTRIC_ONE_BRANCH = 4u;
VKRT_CONST uint SAMPLER_JITTERED = 0u;
VKRT_CONST uint SAMPLER_REGULAR = 1u;
VKRT_CONST uint SAMPLER_RANDOM = 2u;
VKRT_CONST uint SAMPLER_SOBOL = 3u;
// Two independently scrambled Sobol sequences interleaved (sampling.h, replicaSeed): the two halves
// of a pixel's samples are independent, so their difference measures the error (adaptive sampling).
VKRT_CONST uint SAMPLER_SOBOL2 = 4u;
// SPEC_SAMPLER's value for "any": the kernel reads the sampler from FrameParams::sampling.x (the
// general kernel). A specialised kernel gets the render's sampler as a constant instead, so only
// that sampler's code is compiled: sample2D's branches on the kind are not skipped on lavapipe,
// which runs every path for all 8 lanes (host/gpu/README.md, fact 2).
VKRT_CONST uint SAMPLER_FROM_FRAME = 0xffffffffu;
// How a Diffuse surface's light from emitters and the environment map is estimated
// (docs/RENDERING.md §5, RenderOptions::estimator): the expectation is the same for all four.
//  BOUNCE: only the cosine-weighted bounce ray finds them (the course's week-6 shader);
//  NEE: only light samples (next-event estimation): a bounce ray that hits them adds nothing;
//  MIS_BALANCE, MIS_POWER: both, weighted by Veach's balance or power heuristic.
VKRT_CONST uint ESTIMATOR_BOUNCE = 0u;
VKRT_CONST uint ESTIMATOR_NEE = 1u;
VKRT_CONST uint ESTIMATOR_MIS_BALANCE = 2u;
VKRT_CONST uint ESTIMATOR_MIS_POWER = 3u;
VKRT_CONST uint ESTIMATOR_FROM_FRAME = 0xffffffffu;  // the general kernel: FrameParams::lighting.y
struct FrameParams {
    vec4 cameraPosition;  // xyz eye, w = lens radius (aperture / 2; 0 for a pinhole)
    vec4 cameraU;         // xyz unit right vector, w = image plane width
    vec4 cameraV;         // xyz unit up vector,    w = image plane height
    vec4 cameraW;         // xyz unit backward vector (-gaze), w = focal length
    vec4 background;      // rgb, w = focus distance (0 for a pinhole)
    uvec4 image;          // x width, y height, z camera type, w FINAL_*_DARK bits: rays ending at
                          // the maximum depth that cannot bring light (host/lighting/final_rays.h),
                          // and PATH_DIELECTRIC_ONE_BRANCH
    uvec4 sampling;       // x sampler, y samples per pixel, z light samples, w gloss samples
    uvec4 scene;          // x seed, y max depth, z light count, w top-level root node
    uvec4 pixelGrid;      // SampleGrid of the rpp pixel samples (see sampling.h)
    uvec4 lightGrid;      // SampleGrid of the rpp * lightSamples area-light samples
    uvec4 glossGrid;      // SampleGrid of the rpp * glossSamples glossy directions
    uvec4 world;          // the world group walked as part of the top level (node_packing.h,
                          // InlinedWorld): x its first node texel, y its node texels, z its first
                          // primitive, w its primitive count; y = w = 0 when none is
    vec4 shutter;         // x open, y close: a camera sample's time is open + (close - open) * u,
                          // in the instances' motion time (0: transform, 1: transformEnd); zw unused
    uvec4 lighting;       // x shape emitters, y ESTIMATOR_*, z environment face size (0: none),
                          // w environment distribution cells per face side
};
// The kernels read these lanes straight from the uniform block, one lane each, through
// bindings.glsl's frameSeed(), frameMaxDepth(), ...: passing the block's struct to a function makes
// lavapipe load whole vec4s and keep them live (the traversal's JIT loops grew). The host's reads:
#ifdef __cplusplus
inline uint frameWidth(const FrameParams& f) { return f.image.x; }
inline uint frameHeight(const FrameParams& f) { return f.image.y; }
#endif
// Whether a node entry / a primitive belongs to the inlined world group (FrameParams::world):
// unsigned differences, so each range test is one compare.
VKRT_FN bool worldHoldsNodeEntry(uvec4 world, uint entry) { return entry - world.x < world.y; }
VKRT_FN bool worldHoldsPrimitive(uvec4 world, uint prim) { return prim - world.z < world.w; }

// Written by the kernel, read by the host after each submission.
VKRT_CONST uint STATUS_LOOP_BUDGET_EXCEEDED = 1u;
VKRT_CONST uint STATUS_RAY_STACK_OVERFLOW = 2u;
VKRT_CONST uint STATUS_LOOP_CUT_OFF = 4u;  // a loop ended before its work was done (a driver's loop limiter)
VKRT_CONST uint STATUS_SHADOW_RAYS_MISMATCH = 8u;  // wavefront: a hit's shading asked SHADE_RECORD and SHADE_RESOLVE
                                                   // for different shadow rays (their compilations disagree)
struct RenderStatus {
    uvec4 flags;       // x: STATUS_* bits, y: first offending pixel index + 1 (0: none), z: its sample,
                       // w: number of samples whose radiance was NaN/Inf (replaced by black)
    uvec4 paths;       // wavefront kernels (WAVEFRONT_*): x counts the paths that ended since the render
                       // began (the host's waves are done when it reaches their paths); y, z the
                       // lengths of the two path queues, w of the shadow-ray queue (wavefront_state.glsl)
    // The dispatches of the queues' stages (VkDispatchIndirectCommand in xyz; w unused), sized by
    // the stages that append: [0], [1] the path queues' (at least one workgroup, whose first
    // invocation empties the next queue), [2] the shadow queue's.
    uvec4 queueGroups[3];
};
// The host's reads (render.comp writes the lanes with atomics, which need the member itself).
VKRT_FN uint statusFailures(RenderStatus s) { return s.flags.x; }
VKRT_FN uint statusPixelPlusOne(RenderStatus s) { return s.flags.y; }
VKRT_FN uint statusSample(RenderStatus s) { return s.flags.z; }
VKRT_FN uint statusNonFiniteSamples(RenderStatus s) { return s.flags.w; }

// Push constants: which pixels and which samples this dispatch computes.
// Dispatches may cover a run of the tile's workgroups only (vkCmdDispatchBase offsets
// gl_WorkGroupID). A tile of width 0 (z = 0, pass.z = 1) must compute nothing: the host's
// warm-up dispatch, which makes lavapipe compile the kernel before the first timed submission.
struct PassParams {
    uvec4 tile;        // x, y origin, z width, w height (pixels)
    uvec4 pass;        // x first sample index, y workgroup interleave stride, z workgroups,
                       // w samples per pixel this dispatch computes (x .. x + w - 1; sample_batching.h)
};
VKRT_FN uvec2 passTileOrigin(PassParams p) { return uvec2(p.tile.x, p.tile.y); }
VKRT_FN uvec2 passTileSize(PassParams p) { return uvec2(p.tile.z, p.tile.w); }
VKRT_FN uint passFirstSample(PassParams p) { return p.pass.x; }
VKRT_FN uint passStride(PassParams p) { return p.pass.y; }
VKRT_FN uint passWorkgroups(PassParams p) { return p.pass.z; }
VKRT_FN uint passSamples(PassParams p) { return p.pass.w; }
// Adaptive sampling (SPEC_ADAPTIVE): a pass's tile is a range of the work list instead,
// tile.x its first entry and tile.z its length, and pass.x the samples the earlier passes of the
// round computed of each entry's range.
// One entry of the work list: uvec4(pixel index, first sample of the round, end of the round's samples, 0).

// Ray-throughput benchmark (shaders/trace_rays.comp, tools/bench): rays in, hits out, so the GPU
// traces exactly the rays the CPU traversal and the Embree peer trace.
struct TraceRayInput {
    vec4 origin;     // xyz origin, w = tMax (hits need 0 < t < tMax, t in units of |dir|)
    vec4 direction;  // xyz direction, w unused
};
// A traced ray's outcome as GpuRayTracer::trace returns it (the host expands the kernel's words
// into it).
struct TraceHitOutput {
    uvec4 hit;       // x = floatBits(t) or TRACE_MISS, y = primitive, z = instance, w = STATUS_* failures
};
VKRT_FN uint traceHitTBits(TraceHitOutput h) { return h.hit.x; }
VKRT_FN uint traceHitPrimitive(TraceHitOutput h) { return h.hit.y; }
VKRT_FN uint traceHitInstance(TraceHitOutput h) { return h.hit.z; }
VKRT_FN uint traceHitFailures(TraceHitOutput h) { return h.hit.w; }
// What trace_rays.comp writes per ray: 32-bit words in an R32UI texel buffer, as few as the BVH
// needs, because lavapipe stores a texel one component at a time, each a loop over the 8 lanes
// (profile_jit.py: the four-word hit was 5% of a primary-ray trace on buddha).
//   word 0: floatBits(t), TRACE_MISS, or TRACE_FAILED (never a t: both are negative NaNs)
//   word 1: the primitive, or for TRACE_FAILED the STATUS_* failure bits
//   word 2: the instance, only when the BVH has a top level (SPEC_HAS_INSTANCES; else instance 0)
VKRT_CONST uint TRACE_MISS = 0xffffffffu;
VKRT_CONST uint TRACE_FAILED = 0xfffffffeu;
VKRT_CONST uint TRACE_HIT_WORDS = 2u;            // BVHs without a top level
VKRT_CONST uint TRACE_HIT_WORDS_INSTANCED = 3u;  // with one
struct TraceParams {
    uvec4 rays;      // x = ray count, y = 1 for any-hit (shadow) queries, 0 for closest hit, z, w unused
};
// Read in trace_rays.comp straight from the push constants (traceRayCount(), traceAnyHit()), as
// FrameParams is; the host only writes it.

// Specialization constant ids: the scene's feature set (the kernel is specialised per scene).
VKRT_CONST uint SPEC_HAS_TRIANGLES = 0;
VKRT_CONST uint SPEC_HAS_SPHERES = 1;
VKRT_CONST uint SPEC_HAS_BOXES = 2;
VKRT_CONST uint SPEC_HAS_INSTANCES = 3;     // a top-level BVH is traversed
VKRT_CONST uint SPEC_HAS_AREA_LIGHTS = 4;
VKRT_CONST uint SPEC_HAS_SPECULAR = 5;      // Blinn-Phong highlights
VKRT_CONST uint SPEC_HAS_REFLECTION = 6;    // Mirror, Glaze, BlinnPhongMirrored
VKRT_CONST uint SPEC_HAS_GLOSS = 7;         // roughness > 0 somewhere
VKRT_CONST uint SPEC_HAS_DIELECTRIC = 8;
VKRT_CONST uint SPEC_HAS_TEXTURES = 9;
VKRT_CONST uint SPEC_HAS_COOL_TO_WARM = 10;
VKRT_CONST uint SPEC_MAX_DEPTH = 11;        // recursion depth the scene can use
VKRT_CONST uint SPEC_PATH_STACK_SIZE = 12;   // pending reflection/refraction rays (maxDepth + glossSamples)
VKRT_CONST uint SPEC_PACKED_NODES = 13;     // the nodes are GpuBvhNode (3 texels), else GpuExactBvhNode (4)
VKRT_CONST uint SPEC_SAMPLER = 14;          // SAMPLER_*, or SAMPLER_FROM_FRAME
VKRT_CONST uint SPEC_SAMPLES_PER_DISPATCH = 15;  // a render's k (sample_batching.h): 1 compiles no sample loop
VKRT_CONST uint SPEC_HAS_THIN_LENS = 16;    // the camera has depth of field (Camera::thinLens)
VKRT_CONST uint SPEC_HAS_TRANSLUCENCY = 17; // a used Dielectric has roughness > 0
VKRT_CONST uint SPEC_HAS_MOTION = 18;       // an instance moves during the shutter (InstanceMotion)
VKRT_CONST uint SPEC_HAS_DIFFUSE = 19;      // a used shader is the course's path-traced Diffuse
VKRT_CONST uint SPEC_HAS_EMITTERS = 20;     // the scene has shape emitters (EmitterRecord)
VKRT_CONST uint SPEC_HAS_ENVIRONMENT = 21;  // the scene has an environment map
VKRT_CONST uint SPEC_ESTIMATOR = 22;        // ESTIMATOR_*, or ESTIMATOR_FROM_FRAME
VKRT_CONST uint SPEC_UNIFORM_INDEX_FROM_GROUPS = 23;  // lavapipe's recompile workaround (bindings.glsl); set per device
VKRT_CONST uint SPEC_ADAPTIVE = 24;         // adaptive sampling's rounds: a work list of pixels and sample ranges
VKRT_CONST uint SPEC_COUNT = 25;

// The wavefront renderer's stages (shaders/wavefront.glsl, host/gpu/wavefront_renderer.h), each a
// kernel of its own (shaders/wavefront_<stage>.comp) with the megakernel's constants.
VKRT_CONST uint WAVEFRONT_OFF = 0u;            // the megakernel: a sample's whole path per invocation
VKRT_CONST uint WAVEFRONT_GENERATE = 1u;       // camera rays into the wave's path slots
VKRT_CONST uint WAVEFRONT_EXTEND = 2u;         // closest hit of each live path's ray
VKRT_CONST uint WAVEFRONT_SHADE_RECORD = 3u;   // the hit's shading, keeping only its shadow rays
VKRT_CONST uint WAVEFRONT_SHADOW = 4u;         // any hit of each shadow ray
VKRT_CONST uint WAVEFRONT_SHADE_RESOLVE = 5u;  // the hit's shading with those visibilities: radiance, next ray
VKRT_CONST uint WAVEFRONT_ACCUMULATE = 6u;     // the wave's path radiances into the pixel sums, in sample order
VKRT_CONST uint WAVEFRONT_STAGE_COUNT = 7u;

// Entries of the kernel's BVH traversal stack. The host refuses a BVH whose top-level depth plus
// deepest bottom-level depth exceeds it, so the stack can never overflow at run time.
VKRT_CONST uint TRAVERSAL_STACK_SIZE = 48u;

// Per invocation, the kernel counts loop iterations and stops at this many (setting
// STATUS_LOOP_BUDGET_EXCEEDED). That bounds one sample's work on every driver, but cannot keep
// Mesa's silent 65,535-pass loop limiter from firing first (its counter is shared by 8 lanes and
// charged for the slowest one): every loop therefore also checks that it finished (budget.glsl,
// STATUS_LOOP_CUT_OFF).
VKRT_CONST uint LOOP_BUDGET = 60000u;

#ifdef __cplusplus
static_assert(sizeof(GpuBvhNode) == 16 * GPU_NODE_TEXELS);
static_assert(sizeof(GpuExactBvhNode) == 16 * GPU_EXACT_NODE_TEXELS);
static_assert(4 * NODE_ENTRY_XY_BITS + 2 * NODE_ENTRY_Z_BITS == 32);
static_assert(sizeof(Primitive) == 48);
static_assert(sizeof(PrimInfo) == 16 * PRIM_INFO_TEXELS);
static_assert(sizeof(VertexAttrib) == 16 * VERTEX_ATTRIB_TEXELS);
static_assert(sizeof(Instance) == 16 * INSTANCE_TEXELS);
static_assert(offsetof(Instance, info) == 16 * INSTANCE_INFO_TEXEL);
static_assert(sizeof(InstanceMotion) == 16 * MOTION_TEXELS);
static_assert(offsetof(Instance, info) == 144);
static_assert(sizeof(Material) == 16 * MATERIAL_TEXELS);
static_assert(sizeof(Light) == 16 * LIGHT_TEXELS);
static_assert(sizeof(TextureInfo) == 16 * TEXTURE_INFO_TEXELS);
static_assert(sizeof(EmitterRecord) == 16 * EMITTER_TEXELS);
static_assert(sizeof(EmitterTriangle) == 16 * EMITTER_TRIANGLE_TEXELS);
static_assert(sizeof(FrameParams) == 224);
static_assert(sizeof(RenderStatus) == 80);
static_assert(sizeof(PassParams) == 32);
static_assert(sizeof(TraceRayInput) == 32);
static_assert(sizeof(TraceHitOutput) == 16);
static_assert(sizeof(TraceParams) == 16);
}  // namespace vkrt::gpu
#endif

#endif  // VKRT_DEVICE_HOST_H
