// A whole scene moved by a similarity transform x -> s*x + T (uniform scale, then translation),
// camera and lights included, so the image it defines is the same as the original's
// (docs/RENDERING.md has no distance falloff and no absolute length anywhere else).
#pragma once

#include <ostream>
#include <string>

#include <glm/glm.hpp>

#include "scene.h"

namespace vkrt::stability {

struct Similarity {
    double scale = 1.0;
    glm::dvec3 translation{0.0};
};

// A similarity with the names a parametrised test and docs/STABILITY.md's table use.
struct Placement {
    std::string id;    // the test's name
    std::string name;  // the table's
    Similarity transform;
};
std::ostream& operator<<(std::ostream& os, const Placement& p);

// A translation by `distance` along a diagonal, so all three coordinates are large.
glm::dvec3 away(double distance);

// Every world-space position, radius, size and instance transform mapped by `t`, computed in double
// and rounded once to float: the rounding is that of a user who typed the scaled scene.
// Dielectric attenuation is per world unit, so it becomes a^(1/s); callers that scale by 1e-4 must
// use a = 1 (a^(1e4) is below float range for any visible tint).
Scene transformed(const Scene& scene, const Similarity& t);

// objectToWorld of the similarity itself.
glm::dmat4 matrixOf(const Similarity& t);

}  // namespace vkrt::stability
