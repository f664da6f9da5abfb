// The per-render constants of the kernel (FrameParams, device_host.h): camera basis and image
// plane (docs/RENDERING.md §1), sampling, seed, depth, and the sample grids of sampling.h.
#pragma once

#include "camera_basis.h"
#include "device_host.h"
#include "render_options.h"
#include "scene.h"
#include "scene_accel.h"

namespace vkrt {

// Throws std::invalid_argument for options the kernel cannot honour (no pixels, no samples, a
// camera index the scene does not have).
gpu::FrameParams makeFrameParams(const Scene& scene, const SceneAccel& accel, const RenderOptions& options);

}  // namespace vkrt
