#version 460
// Test kernel: copies every RGBA32UI texel of a read-only storage texel buffer (imageLoad, the
// path the kernels read BVH nodes, primitives and rays through) into a storage buffer.
layout(local_size_x = 64) in;

layout(set = 0, binding = 0, rgba32ui) uniform readonly uimageBuffer texels;
layout(std430, set = 0, binding = 1) writeonly buffer Out { uvec4 copied[]; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < uint(imageSize(texels))) copied[i] = imageLoad(texels, int(i));
}
