#version 460
// Test kernel: writes the specialization constants it was built with into every pixel:
// x = the eleven feature flags as a bit mask (bit = SPEC_* id) plus SAMPLER_KIND + 1 from bit 11
// (0 for SAMPLER_FROM_FRAME), y = MAX_DEPTH, z = PATH_STACK_SIZE.
#extension GL_GOOGLE_include_directive : require
#include "device_host.h"
#include "test_bindings.glsl"

layout(local_size_x = 64) in;

uint bitIf(bool on, uint id) { return on ? (1u << id) : 0u; }

void main() {
    uint x, y;
    if (!tilePixel(x, y)) return;
    uint mask = bitIf(HAS_TRIANGLES, SPEC_HAS_TRIANGLES) | bitIf(HAS_SPHERES, SPEC_HAS_SPHERES) |
                bitIf(HAS_BOXES, SPEC_HAS_BOXES) | bitIf(HAS_INSTANCES, SPEC_HAS_INSTANCES) |
                bitIf(HAS_AREA_LIGHTS, SPEC_HAS_AREA_LIGHTS) | bitIf(HAS_SPECULAR, SPEC_HAS_SPECULAR) |
                bitIf(HAS_REFLECTION, SPEC_HAS_REFLECTION) | bitIf(HAS_GLOSS, SPEC_HAS_GLOSS) |
                bitIf(HAS_DIELECTRIC, SPEC_HAS_DIELECTRIC) | bitIf(HAS_TEXTURES, SPEC_HAS_TEXTURES) |
                bitIf(HAS_COOL_TO_WARM, SPEC_HAS_COOL_TO_WARM);
    mask |= (SAMPLER_KIND == SAMPLER_FROM_FRAME ? 0u : SAMPLER_KIND + 1u) << 11u;
    addToPixel(y * frame.image.x + x, vec3(float(mask), float(MAX_DEPTH), float(PATH_STACK_SIZE)));
}
