#include "lights.h"

#include <cmath>

namespace vkrt::cpu {

glm::vec3 areaLightTangent(const glm::vec3& n) {
    // Any axis not parallel to n gives a tangent; z is swapped for x when n is close to z.
    const glm::vec3 a = std::fabs(n.z) > 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 0.0f, 1.0f);
    return glm::normalize(glm::cross(a, n));
}

std::vector<LightSource> makeLightSources(const Scene& scene) {
    std::vector<LightSource> out;
    unsigned areaCount = 0;
    for (const Light& l : scene.lights) {
        LightSource s;
        s.type = l.type;
        s.position = l.position;
        s.intensity = l.intensity;
        if (l.type == LightType::Area) {
            const glm::vec3 t = areaLightTangent(l.normal);
            const glm::vec3 b = glm::cross(l.normal, t);
            s.edgeU = l.width * t;
            s.edgeV = l.length * b;
            s.areaOrdinal = areaCount++;
        }
        out.push_back(s);
    }
    return out;
}

glm::vec3 lightPoint(const LightSource& light, glm::vec2 sample) {
    if (light.type == LightType::Point) return light.position;
    return light.position + (sample.x - 0.5f) * light.edgeU + (sample.y - 0.5f) * light.edgeV;
}

}  // namespace vkrt::cpu
