// What the agreement tests share: one validated GPU device per binary, rendering a scene on both
// devices (each from the tree it prepares itself, as `vkrt` does), and the GPU-vs-CPU rule.
//
// Tolerance (issue 5): >= 99.5% of pixels within 2/255 in every channel and a mean absolute
// difference <= 0.5/255. Both paths compute the same samples from the same random numbers
// (shaders/shared/sampling.h), so the images would be identical but for rounding: the device
// contracts multiply-adds into FMAs and orders a few sums differently, which can tip a ray that
// grazes a silhouette, a shadow terminator or a BVH box to the other side. That flips isolated
// pixels by a large amount, never a region, and shifts smooth regions by < 1/255 after 8-bit
// truncation. A wrong feature (a missing light, a wrong shader, a broken traversal) changes whole
// regions and fails both bounds. On failure the heat map is kept in test_artifacts/.
#pragma once

#include <string>
#include <vector>

#include "gpu_renderer.h"
#include "image.h"
#include "image_compare.h"
#include "render_options.h"
#include "scene.h"

namespace vkrt::test {

// The files in `dir` whose extension is `extension` (".xml", ".json"), sorted.
std::vector<std::string> scenesIn(const std::string& dir, const std::string& extension = ".xml");

// One device for the whole binary, validation on: creating it costs more than a 64x64 render.
GpuRenderer& gpu();

RenderOptions small(int size, int rpp);

struct DeviceImages {
    Image cpu, gpu;
    GpuRenderStats gpuStats;
};

// Renders `scene` on both devices, each from the tree it prepares itself; expects no validation
// message and no non-finite sample on either device.
DeviceImages renderBoth(const Scene& scene, RenderOptions options, KernelVariant variant = KernelVariant::Specialised);

// Pixels of a and b (same size) that differ in any channel, floats compared exactly (bit-identity
// tests: twins, round trips).
std::size_t differingPixels(const Image& a, const Image& b);

struct Agreement {
    ImageDifference diff;
    bool ok = false;
};

// renderBoth, then the rule above; prints one "[agreement]" line and, with `required`, fails the
// test and keeps the heat map when the rule does not hold.
Agreement measureAgreement(const Scene& scene, const std::string& name, RenderOptions options,
                           KernelVariant variant = KernelVariant::Specialised, bool required = true);
// renderBoth, then the rule above; prints one "[agreement]" line and keeps the heat map on failure.
// `name` names the case in the output and the artefacts.
Agreement renderBothAndCompare(const Scene& scene, const std::string& name, RenderOptions options,
                               KernelVariant variant = KernelVariant::Specialised);
// The same for a scene file (loaded with the default options; warnings are not this test's concern).
Agreement renderBothAndCompare(const std::string& path, RenderOptions options,
                               KernelVariant variant = KernelVariant::Specialised);

}  // namespace vkrt::test
