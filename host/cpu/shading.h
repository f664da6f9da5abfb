// The local (direct-light) terms of the shaders and the reflection directions
// (docs/RENDERING.md §5). Pure functions: visibility and recursion live in the integrator.
#pragma once

#include <glm/glm.hpp>

namespace vkrt::cpu {

// kd * I * max(0, N.L)
glm::vec3 lambertian(const glm::vec3& kd, const glm::vec3& intensity, const glm::vec3& n, const glm::vec3& l);

// ks * I * max(0, N.H)^phongExp with H = normalize(L + V); phongExp 0 gives exactly ks * I.
glm::vec3 blinnPhongSpecular(const glm::vec3& ks, float phongExp, const glm::vec3& intensity, const glm::vec3& n,
                             const glm::vec3& l, const glm::vec3& v);

// Gooch cool-to-warm: t = (1 + N.L)/2, I * (t*kwarm + (1-t)*kcool).
glm::vec3 coolToWarm(const glm::vec3& kd, const glm::vec3& intensity, const glm::vec3& n, const glm::vec3& l);

// The mirror direction of d about n: d - 2 (d.n) n.
glm::vec3 mirrorDirection(const glm::vec3& d, const glm::vec3& n);

// The glossy perturbation of the (unit) mirror direction r by roughness a for the 2D sample (su, sv):
// normalize(r + a(su - 1/2) U + a(sv - 1/2) V'), with (U, V') the basis of r built from the
// coordinate axis least aligned with r. Roughness 0 returns r itself, bit for bit.
glm::vec3 glossyDirection(const glm::vec3& r, float roughness, glm::vec2 sample);

}  // namespace vkrt::cpu
