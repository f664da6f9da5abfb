#include "exposure.h"

#include <cmath>

namespace vkrt {

Image withExposure(Image image, float ev) {
    if (ev == 0.0f) return image;
    const float scale = std::exp2(ev);
    for (glm::vec3& p : image.pixels) p *= scale;
    return image;
}

}  // namespace vkrt
