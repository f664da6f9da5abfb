// <light type="point|area"> -> Light (docs/XML_FORMAT.md §3.4).
#pragma once

#include <optional>

#include <pugixml.hpp>

#include "parse_context.h"
#include "scene.h"

namespace vkrt {

// point: position, intensity; area-light children on a point light are ignored without a warning
// (solarSystem.xml, oneSphereUpPt.xml carry them). area: position (the centre), intensity,
// normal (normalised; zero length is an error), width and length (> 0). An unknown type is a
// warning and the light is skipped (nullopt).
std::optional<Light> parseLight(const ParseContext& context, pugi::xml_node node);

}  // namespace vkrt
