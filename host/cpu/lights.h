// Light sampling (docs/RENDERING.md §4): point lights, and area lights as rectangles of point
// lights with no falloff and no emitter cosine (the course's convention), so a 0x0 area light is
// exactly a point light.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scene.h"

namespace vkrt::cpu {

struct LightSource {
    LightType type = LightType::Point;
    glm::vec3 position{0.0f};   // point position or rectangle centre
    glm::vec3 intensity{0.0f};
    glm::vec3 edgeU{0.0f};      // width  * tangent
    glm::vec3 edgeV{0.0f};      // length * bitangent
    unsigned areaOrdinal = 0;   // index among the scene's area lights: its sampling dimension
};

// The area light's tangent T (width direction) for a unit normal n; the bitangent is cross(n, T).
glm::vec3 areaLightTangent(const glm::vec3& n);

// The scene's lights in scene order, area-light rectangles precomputed.
std::vector<LightSource> makeLightSources(const Scene& scene);

// The point of the light for the 2D light sample (su, sv) in [0,1)^2 (the position for a point light).
glm::vec3 lightPoint(const LightSource& light, glm::vec2 sample);

}  // namespace vkrt::cpu
