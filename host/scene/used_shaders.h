// Which of a scene's shaders are rendered, and whether the scene path-traces: questions both
// renderers and the GPU kernel's feature set ask of the model.
#pragma once

#include <set>

#include "scene.h"

namespace vkrt {

// Shader indices reachable from what is rendered: loose and mesh shapes, and instanced
// prototypes under their instance's override. Unused <shader> elements switch nothing on.
std::set<int> usedShaders(const Scene& scene);

// Some rendered surface is Diffuse: the scene's pixels are Monte Carlo estimates anyway, so a
// dielectric hit continues one branch (docs/RENDERING.md §6); without one, a dielectric splits
// into both and the course's Whitted images stay exact.
bool pathTraced(const Scene& scene);

}  // namespace vkrt
