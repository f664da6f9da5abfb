// Dielectric interfaces (docs/RENDERING.md §6): exact unpolarised Fresnel reflectance, Snell
// refraction and Beer-Lambert attenuation with a per-unit-distance transmittance.
#pragma once

#include <glm/glm.hpp>

namespace vkrt::cpu {

// Reflectance for light arriving at cosine cosIncident (in [0,1]) from index n1 into index n2.
// 1 under total internal reflection; exactly 0 when n1 == n2.
float fresnelDielectric(float cosIncident, float n1, float n2);

// The refracted direction of unit d through a surface with unit normal n facing the incoming ray
// (dot(d, n) <= 0), from index n1 into n2; d itself when n1 == n2. Only valid without total
// internal reflection (fresnelDielectric < 1).
glm::vec3 refractDirection(const glm::vec3& d, const glm::vec3& n, float n1, float n2);

// Transmittance after `distance` inside a medium that transmits `perUnit` over a unit distance.
glm::vec3 beerLambert(const glm::vec3& perUnit, float distance);

}  // namespace vkrt::cpu
