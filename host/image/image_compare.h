// Comparing two images the way users and tests need: in 8-bit steps (what a PNG shows).
#pragma once

#include <string>

#include "image.h"

namespace vkrt {

struct ImageDifference {
    int width = 0, height = 0;
    double maxAbs = 0.0;           // largest |a - b| over channels, in [0,1] units of the 8-bit values
    double meanAbs = 0.0;          // mean |a - b| over all channels
    double fractionOver1 = 0.0;    // pixels with some channel differing by more than 1/255
    double fractionOver2 = 0.0;    // pixels with some channel differing by more than 2/255
    double psnr = 0.0;             // dB, of the 8-bit images; infinity when identical
    Image heatMap;                 // per pixel: differenceColour(max channel difference) (heat_map.h)
};

// Throws std::invalid_argument naming `what` and both sizes unless a and b have the same size.
void requireSameSize(const Image& a, const Image& b, const char* what);

// Compares the 8-bit quantised versions (quantize8) of two same-sized images.
// Throws std::invalid_argument when the sizes differ.
ImageDifference compareImages(const Image& a, const Image& b);

// The rule GPU and CPU renders with the same seed must meet (docs/STABILITY.md): at most 0.5% of
// pixels more than 2/255 apart and a mean difference of at most 0.5/255. The two devices trace the
// same estimator with the same random numbers, so they differ only where float rounding tips a
// ray to another branch (a silhouette, a shadow edge); a real bug moves far more pixels.
bool meetsAgreementRule(const ImageDifference& d);

}  // namespace vkrt
