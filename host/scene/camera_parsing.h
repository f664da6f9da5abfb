// <camera name=".." type="perspective|orthographic"> -> Camera (docs/XML_FORMAT.md §3.3).
#pragma once

#include <pugixml.hpp>

#include "parse_context.h"
#include "scene.h"

namespace vkrt {

// position is required; the gaze is lookatPoint - position when lookatPoint is given (it overrides
// viewDir, as in LIB-boost), else viewDir. A zero gaze, focalLength <= 0 (perspective) or
// imagePlaneWidth <= 0 is a SceneError, and so is an <up> (vkrt's
// addition) that upProblem refuses. Defaults: focalLength 1, imagePlaneWidth 0.5. A missing
// type means perspective; an unknown type is a warning and perspective.
// `exactPosition`, when given, receives the eye in double (the local origin, local_origin.h).
Camera parseCamera(const ParseContext& context, pugi::xml_node node, glm::dvec3* exactPosition = nullptr);

}  // namespace vkrt
