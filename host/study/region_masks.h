// The image regions a sampler study measures error in, found by probing the scene (not by looking
// at a noisy image): geometric edges, shadow penumbrae and glossy reflections (docs/SAMPLING.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "image.h"
#include "render_options.h"
#include "scene.h"
#include "scene_accel.h"

namespace vkrt::study {

// One byte per pixel (row-major, row 0 = top), 1 = the pixel is in the region.
using PixelMask = std::vector<std::uint8_t>;

struct RegionMasks {
    int width = 0, height = 0;
    PixelMask edge;      // the pixel's primary hits differ in object, or in normal by > kEdgeNormalDegrees, or hit/miss
    PixelMask penumbra;  // some light is neither fully visible nor fully hidden from the pixel's primary hits
    PixelMask gloss;     // a primary hit reflects or refracts glossily (a reflecting shader or Dielectric with roughness > 0)
};

struct ProbeOptions {
    int pixelProbes = 4;  // per axis: pixelProbes^2 primary rays per pixel, on a grid from border to border
    int lightProbes = 8;  // per axis: lightProbes^2 points (stratum centres) per area light and primary hit
    int threads = 0;      // 0 = all hardware threads
};

// Probes every pixel of options.width x options.height with the camera options.camera.
RegionMasks findRegions(const Scene& scene, const SceneAccel& accel, const RenderOptions& options,
                        const ProbeOptions& probe = {});

std::size_t countPixels(const PixelMask& mask);

// The masks as an image (red = edge, green = penumbra, blue = gloss), and back: the form they are
// cached and shown in.
Image masksToImage(const RegionMasks& masks);
RegionMasks masksFromImage(const Image& image);

}  // namespace vkrt::study
