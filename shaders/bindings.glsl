// Descriptor bindings and the scene's feature set (specialization constants), per
// shared/device_host.h. Features switched off are removed by the driver's compiler, so each scene
// runs a kernel with only the paths it needs.
#ifndef VKRT_BINDINGS_GLSL
#define VKRT_BINDINGS_GLSL

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

layout(set = 0, binding = BINDING_NODES, rgba32ui) uniform readonly uimageBuffer bvhNodes;
layout(set = 0, binding = BINDING_PRIMS, rgba32ui) uniform readonly uimageBuffer primitives;
layout(std430, set = 0, binding = BINDING_PRIM_INFO) readonly buffer PrimInfoBuffer { PrimInfo primInfos[]; };
layout(std430, set = 0, binding = BINDING_VERTEX_ATTRIBS) readonly buffer VertexAttribBuffer { VertexAttrib vertexAttribs[]; };
layout(std430, set = 0, binding = BINDING_INSTANCES) readonly buffer InstanceBuffer { Instance instances[]; };
layout(std430, set = 0, binding = BINDING_SHADERS) readonly buffer MaterialBuffer { Material materials[]; };
layout(std430, set = 0, binding = BINDING_LIGHTS) readonly buffer LightBuffer { Light lights[]; };
layout(std430, set = 0, binding = BINDING_TEXTURES) readonly buffer TextureInfoBuffer { TextureInfo textureInfos[]; };
layout(std430, set = 0, binding = BINDING_TEXELS) readonly buffer TexelBuffer { uint texels[]; };
layout(std140, set = 0, binding = BINDING_FRAME) uniform FrameBuffer { FrameParams frame; };
layout(std430, set = 0, binding = BINDING_ACCUM) buffer AccumBuffer { vec4 accum[]; };
layout(std430, set = 0, binding = BINDING_STATUS) coherent buffer StatusBuffer { RenderStatus status; };

#endif
