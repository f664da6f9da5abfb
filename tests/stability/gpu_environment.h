// One GpuRenderer for the whole test binary: creating the device, the validation layers and the
// kernel costs far more than the small renders here, so it is made once (a gtest Environment owns
// it; this accessor is the one global the suite needs). Validation is always on, and the
// environment's TearDown fails the run on any validation message.
#pragma once

#include "gpu_renderer.h"

namespace vkrt::stability {

GpuRenderer& sharedGpu();

}  // namespace vkrt::stability
