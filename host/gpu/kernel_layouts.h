// The descriptor and pipeline layouts of vkrt's two kernels: the bindings of
// shaders/shared/device_host.h that each one declares (shaders/bindings.glsl).
#pragma once

#include "compute_pipeline.h"
#include "context.h"

namespace vkrt {

// render.comp: its RENDER_BINDING_COUNT bindings BINDING_NODES .. BINDING_ENVIRONMENT_CDF, PassParams.
KernelLayout renderLayout(const Context& context);
// trace_rays.comp: nodes, primitives, instances, frame, status, rays, hits; TraceParams.
KernelLayout traceLayout(const Context& context);

}  // namespace vkrt
