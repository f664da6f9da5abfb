#version 460
// Test kernel: copies every RGBA32UI texel of a uniform texel buffer (texelFetch, the path the
// render kernel reads BVH nodes and primitives through) into a storage buffer.
layout(local_size_x = 64) in;

layout(set = 0, binding = 0) uniform usamplerBuffer texels;
layout(std430, set = 0, binding = 1) writeonly buffer Out { uvec4 copied[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < uint(textureSize(texels))) copied[i] = texelFetch(texels, int(i));
}
