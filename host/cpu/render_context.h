// Everything a CPU render needs that is the same for every pixel: the scene, its BVH, the camera
// frame, the lights, and the sample grids (docs/RENDERING.md §2).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "camera.h"
#include <memory>

#include "final_rays.h"
#include "scene_lighting.h"
#include "lights.h"
#include "render_options.h"
#include "scene.h"
#include "scene_accel.h"

namespace vkrt::cpu {

struct RenderContext {
    const Scene* scene = nullptr;
    const SceneAccel* accel = nullptr;
    CameraFrame camera;
    std::vector<LightSource> lights;
    std::shared_ptr<const SceneLighting> lighting;  // emitters and environment map (scene_lighting.h)
    bool environment = false;          // rays that leave see the map (it exists, RenderOptions::environment)
    Estimator estimator = Estimator::MisPower;  // Diffuse: how emitters and the environment are found
    glm::vec3 background{0.0f};
    unsigned sampler = 0;              // gpu::SAMPLER_*
    unsigned seed = 0;
    int maxDepth = 4;
    FinalRays finalRays;               // which rays ending at maxDepth can bring light (final_rays.h)
    bool dielectricOneBranch = false;  // a dielectric hit continues one branch (used_shaders.h pathTraced)
    unsigned samplesPerPixel = 1;
    unsigned lightSamples = 1;         // k per area light per pixel sample
    unsigned glossSamples = 1;         // g per glossy reflection per pixel sample
    glm::uvec4 pixelGrid{0}, lightGrid{0}, glossGrid{0};  // sampling.h grids of rpp, rpp*k, rpp*g strata
    bool motion = false;               // some instance moves: each sample draws a time in the shutter
    glm::vec2 shutter{0.0f, 1.0f};     // open, close (RenderOptions::shutter)
};

// Checks the options against the scene (std::invalid_argument naming the option and value).
RenderContext makeRenderContext(const Scene& scene, const SceneAccel& accel, const RenderOptions& options);

}  // namespace vkrt::cpu
