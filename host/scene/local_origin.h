// Scenes far from the origin (docs/STABILITY.md "Far from the origin"). A float holds 24 bits, so
// a unit-sized scene placed 1e7 from the origin keeps only whole units of its coordinates once the
// file's numbers are rounded to float. With LoadOptions::localOrigin the loaders read every world
// position in double and store it relative to Scene::origin, the default camera's eye, before the
// one rounding to float: the image then depends on the scene's distances, not on where it is.
// Object-space geometry (prototypes, shapes under a transform) keeps its float values; the
// rebasing goes into the instance's transform, composed in double from the listed steps.
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "scene.h"

namespace vkrt::rules {

// exact - origin rounded once to float; nullopt when that leaves float range (two values of
// opposite sign near 3.4e38).
std::optional<glm::vec3> localPosition(const glm::dvec3& exact, const glm::dvec3& origin);
inline constexpr const char* kBeyondFloatLocally =
    "not a finite 32-bit number once measured from the camera (the local origin)";

// The steps composed in double, translations taken from `exactTranslations` (the text's doubles,
// one per step; only translate steps read theirs), then moved by -origin, rounded once to float.
// The rotations are axisRotation's, the scales the steps' floats.
glm::mat4 placeRelativeTo(const std::vector<TransformStep>& steps, const std::vector<glm::dvec3>& exactTranslations,
                          const glm::dvec3& origin);

// Meshes used in world space (a loose mesh shape, a mesh emitter without a transform) are given
// their own copy with positions moved by -scene.origin in double; a mesh also used as a prototype
// keeps its object-space copy. Does nothing when the origin is zero.
void rebaseWorldMeshes(Scene& scene);

}  // namespace vkrt::rules
