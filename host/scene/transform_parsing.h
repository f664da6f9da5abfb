// <transform> inside a shape: translate / rotate / scale children composed in listed order.
#pragma once

#include <glm/glm.hpp>
#include <pugixml.hpp>

#include "parse_context.h"

namespace vkrt {

// M = T0 * T1 * ... * Tn-1 for the children in document order, so p' = M p applies the LAST
// listed operation to the object first (docs/XML_FORMAT.md §3.9: JSON-2026 parseTransformData and PT's
// Transform.cpp). Rotation angles are degrees about the axis named by the first character of
// `axis` (X, Y or Z, any case). A zero scale component is an error: the renderers need M^-1.
glm::mat4 parseTransform(const ParseContext& context, pugi::xml_node transform);

}  // namespace vkrt
