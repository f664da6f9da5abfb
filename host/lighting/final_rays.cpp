#include "final_rays.h"

#include <algorithm>

namespace vkrt {

namespace {

// Lit at every depth: the course's direct-light shaders (a Diffuse surface is Lambertian with
// diffuseBounce set, and black at max-depth; Mirror and Dielectric only pass rays on).
bool shadesLocally(const Shader& shader) {
    switch (shader.type) {
    case ShaderType::Lambertian: return !shader.diffuseBounce;
    case ShaderType::BlinnPhong:
    case ShaderType::Glaze:
    case ShaderType::BlinnPhongMirrored:
    case ShaderType::CoolToWarm: return true;
    case ShaderType::Mirror:
    case ShaderType::Dielectric: return false;
    }
    return true;
}

}  // namespace

FinalRays finalRays(const Scene& scene, const RenderOptions& options) {
    const bool local = std::any_of(scene.shaders.begin(), scene.shaders.end(), shadesLocally);
    const bool environment = options.environment && scene.environment.faceSize > 0;
    const glm::vec3 background = options.background.value_or(scene.background);
    // NaN compares unequal too: only an exactly black background is black.
    const bool blackBackground = background.x == 0.0f && background.y == 0.0f && background.z == 0.0f;
    const bool emitters = !scene.emitters.empty();
    const bool nee = options.estimator == Estimator::Nee;
    FinalRays rays;
    // A bounce that leaves sees the map (weighed against light samples, none under nee) or the
    // background (found only by the bounce, in every estimator); one that reaches an emitter
    // counts it unless light samples alone do.
    rays.bounceSeesLight = local || (environment ? !nee : !blackBackground) || (emitters && !nee);
    // Reflection and refraction rays see the map, the background and emitters in full.
    rays.reflectionSeesLight = local || environment || !blackBackground || emitters;
    return rays;
}

}  // namespace vkrt
