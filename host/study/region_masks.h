// The image regions a sampler study measures error in, found by probing the scene (not by looking
// at a noisy image): geometric edges, shadow penumbrae, glossy reflections, defocus, motion, and
// the path-traced pixels (docs/SAMPLING.md §3).
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
    PixelMask penumbra;  // some light (point, area or shape emitter) is neither fully visible nor fully hidden
                         // from the pixel's primary hits
    PixelMask gloss;     // a primary hit reflects or refracts glossily (a reflecting shader or Dielectric with roughness > 0)
    PixelMask defocus;   // the thin lens blurs the pixel: a primary hit's circle of confusion is >= 1 pixel, or rays
                         // from the lens's rim see different objects
    PixelMask motion;    // a moving instance crosses the pixel: the primary hits at shutter open, middle and close
                         // differ in object, or in position by more than the pixel's footprint
    PixelMask indirect;  // path traced: a primary hit, or the first hit past sharp reflections and refractions,
                         // is a Diffuse surface at a depth below the maximum (its light includes bounces)
    PixelMask emitter;   // an indirect pixel whose Diffuse hit sees a shape emitter (in front of it, unoccluded):
                         // where the estimators (RenderOptions::estimator) differ most
};

struct ProbeOptions {
    int pixelProbes = 4;  // per axis: pixelProbes^2 primary rays per pixel, on a grid from border to border
    int lightProbes = 8;  // per axis: lightProbes^2 points (stratum centres) per area light or shape emitter and hit
    int threads = 0;      // 0 = all hardware threads
};

// Probes every pixel of options.width x options.height with the camera options.camera.
RegionMasks findRegions(const Scene& scene, const SceneAccel& accel, const RenderOptions& options,
                        const ProbeOptions& probe = {});

std::size_t countPixels(const PixelMask& mask);

// The masks as an image, one bit per region in the red channel (value / 255: edge 1, penumbra 2,
// gloss 4, defocus 8, motion 16, indirect 32, emitter 64), and back: the form they are cached in
// (exact through 8-bit PNG).
Image masksToImage(const RegionMasks& masks);
RegionMasks masksFromImage(const Image& image);

// The masks as the sweep shows them (DIR/regions.png): three panels side by side, on the left red
// edge, green penumbra, blue gloss; in the middle red defocus, green motion; on the right red
// indirect, green emitter (so emitter pixels, all of them indirect too, are yellow).
Image regionsPicture(const RegionMasks& masks);

}  // namespace vkrt::study
