#include "scene_lighting.h"

namespace vkrt {

SceneLighting buildSceneLighting(const Scene& scene) {
    SceneLighting lighting;
    lighting.emitters = buildEmitterTable(scene);
    lighting.environment = borderedEnvironment(scene.environment);
    lighting.environmentLights = environmentDistribution(lighting.environment);
    return lighting;
}

}  // namespace vkrt
