// The render kernel's interface (device_host.h) as the test kernels declare it: the same set 0
// bindings, push constants and specialization constants as shaders/bindings.glsl, written
// independently so these tests check the host against the contract, not against the kernel.
#ifndef VKRT_TEST_BINDINGS_GLSL
#define VKRT_TEST_BINDINGS_GLSL

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
layout(constant_id = SPEC_MAX_DEPTH) const uint MAX_DEPTH = 99u;
layout(constant_id = SPEC_PATH_STACK_SIZE) const uint PATH_STACK_SIZE = 99u;
layout(constant_id = SPEC_SAMPLER) const uint SAMPLER_KIND = 99u;

layout(set = 0, binding = BINDING_NODES, rgba32ui) uniform readonly uimageBuffer bvhNodes;
layout(set = 0, binding = BINDING_PRIMS, rgba32ui) uniform readonly uimageBuffer primitives;
layout(set = 0, binding = BINDING_SHADERS, rgba32ui) uniform readonly uimageBuffer materialTexels;
layout(set = 0, binding = BINDING_LIGHTS, rgba32ui) uniform readonly uimageBuffer lightTexels;
layout(std140, set = 0, binding = BINDING_FRAME) uniform FrameBuffer { FrameParams frame; };
layout(set = 0, binding = BINDING_ACCUM, rgba32ui) uniform uimageBuffer accumTexels;

void addToPixel(uint pixel, vec3 value) {
    vec4 sum = uintBitsToFloat(imageLoad(accumTexels, int(pixel)));
    imageStore(accumTexels, int(pixel), floatBitsToUint(vec4(sum.rgb + value, sum.w)));
}
layout(std430, set = 0, binding = BINDING_STATUS) coherent buffer StatusBuffer { RenderStatus status; };

layout(push_constant) uniform PushConstants { PassParams pass; };

// The pixel this invocation computes, by the tile/workgroup mapping of device_host.h's
// PassParams (workgroup g -> 8x8 block (g * stride) % workgroups, row-major in the tile);
// false outside the tile.
bool tilePixel(out uint x, out uint y) {
    uint block = (gl_WorkGroupID.x * pass.pass.y) % pass.pass.z;
    uint blocksX = (pass.tile.z + 7u) / 8u;
    uint localX = (block % blocksX) * 8u + gl_LocalInvocationIndex % 8u;
    uint localY = (block / blocksX) * 8u + gl_LocalInvocationIndex / 8u;
    x = pass.tile.x + localX;
    y = pass.tile.y + localY;
    return localX < pass.tile.z && localY < pass.tile.w;
}

#endif
