// Checks that catch shadow acne and light leaks specifically, which a whole-image tolerance would
// let through when they are sparse: both show up as isolated wrong pixels inside regions that are
// smooth in the reference, where rounding cannot legitimately move anything.
#pragma once

#include <string>

#include "image.h"

namespace vkrt::stability {

struct SmoothRegionResult {
    int smoothPixels = 0;   // pixels whose 3x3 neighbourhood in the reference is smooth
    int differing = 0;      // of those, pixels where the image differs by more than the tolerance
    std::string worst;      // the worst such pixel, for the failure message
};

// A pixel is smooth when every neighbour in its 3x3 block of `reference` is within
// `smoothSteps`/255 of it in every channel (8-bit values): no silhouette, shadow edge or sampling
// noise passes through it, so a sub-pixel shift of the geometry cannot change it. There `image`
// must match `reference` within `toleranceSteps`/255.
SmoothRegionResult compareSmoothRegions(const Image& reference, const Image& image, int smoothSteps,
                                        int toleranceSteps);

}  // namespace vkrt::stability
