// --exposure EV: the linear image scaled by 2^EV as it is written, the photographer's stops. It
// is applied where a render's image leaves vkrt (the file, each --progressive pass, the --watch
// preview), never inside a renderer: both renderers keep computing radiance, compare and sweep
// judge radiance, and a --part's EXR already carries it, so `vkrt merge` copies it as it is.
#pragma once

#include "image.h"

namespace vkrt {

// ±20 stops: 2^20 lifts 1e-6 to 1 and 2^-20 brings 1e6 down to 1; beyond that no image of a
// course scene changes meaningfully, and a typo (--exposure 200) would overflow float's range.
inline constexpr float kMaxExposureStops = 20.0f;

// Every channel times 2^ev; ev 0 returns the image unchanged. A whole ev scales by a power of two,
// which is exact in float: an EXR keeps the ratio bit for bit (8-bit output then clamps what
// exceeds 1).
Image withExposure(Image image, float ev);

}  // namespace vkrt
