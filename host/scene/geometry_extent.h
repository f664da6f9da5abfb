// Geometry that float intersection cannot handle, warned at load with the element's location
// (docs/STABILITY.md "Beyond float intersection"). Both renderers intersect in float relative to
// the ray's origin, so two things break, silently and on both devices alike:
//   - reach: a triangle's test multiplies three coordinates (the scaled determinant), which
//     overflows past ~3e12 from the ray's origin; a sphere's squared distance and a light's
//     squared direction overflow past ~1.8e19. Beyond that the primitive vanishes or goes black.
//   - span: a triangle whose corners are M from the eye but whose plane passes d from it has hit
//     distances computed to ~2^-24 M, so hits near the camera are garbage once M/d nears 2^24.
// Distances are measured from the default camera's eye, in double, on the coordinates the
// renderers receive (rebased ones when LoadOptions::localOrigin is on).
#pragma once

#include "diagnostics.h"
#include "scene.h"

namespace vkrt::rules {

// Measured (docs/STABILITY.md): triangles 0.2 rad wide render up to 1e13 from the eye and vanish
// at 1e14; spheres, boxes and point lights work at 1e19 and fail at 1e20. The limits keep a 10x margin.
inline constexpr double kTriangleReach = 1e12;
inline constexpr double kQuadricReach = 1e18;  // spheres, boxes, lights
// A 1-unit-high camera over one ground triangle of half-width M: the image holds (within 2/255)
// up to M = 3e6 and breaks at 1e7; 2^20 keeps a 3x margin.
inline constexpr double kTriangleSpanPerDistance = 1048576.0;  // 2^20

// One warning per element (the first offending triangle of a mesh, by index); with `strict` the
// first is thrown as a SceneError (LoadOptions::strict).
void warnGeometryBeyondFloat(const Scene& scene, bool strict, Diagnostics& diagnostics);

}  // namespace vkrt::rules
