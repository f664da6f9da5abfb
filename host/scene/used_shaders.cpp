#include "used_shaders.h"

namespace vkrt {

std::set<int> usedShaders(const Scene& scene) {
    std::set<int> used;
    for (const Shape& shape : scene.shapes) used.insert(shape.shader);
    for (const Instance& instance : scene.instances)
        used.insert(instance.shaderOverride >= 0 ? instance.shaderOverride : scene.prototypes.at(instance.prototype).shader);
    return used;
}

bool pathTraced(const Scene& scene) {
    for (const int index : usedShaders(scene))
        if (scene.shaders.at(static_cast<std::size_t>(index)).diffuseBounce) return true;
    return false;
}

}  // namespace vkrt
