// Numbers in XML element text (number_text.h reads them; this reports at the element).
// Values are read the way the course's C++ read them (istream >> float, one after the other), so
// that the real files load; anything the course code would have read differently from what the
// text says is an error, and anything it silently repaired is a warning (an error when strict).
#pragma once

#include <string>

#include <glm/glm.hpp>
#include <pugixml.hpp>

#include "parse_context.h"

namespace vkrt {

// Errors: a missing component, a non-number, NaN/Inf, a value outside float range.
// Warnings (istream-compatible recovery): a number running into the next one ("2.5.0" reads as
// 2.5 then .0), extra tokens after the expected count.
float parseScalar(const ParseContext& context, pugi::xml_node element);
// `exact`, when given, receives the numbers in double before their rounding to float.
glm::vec3 parseVec3(const ParseContext& context, pugi::xml_node element, glm::dvec3* exact = nullptr);

// A point: in world space (`world`) under LoadOptions::localOrigin, read in double and stored
// relative to context.origin (local_origin.h); otherwise parseVec3.
glm::vec3 parsePosition(const ParseContext& context, pugi::xml_node element, bool world);

// A colour (diffuse, specular, intensity, background, emission): parseVec3, and a warning for a
// negative component (rules::negativeColourProblem), the value kept.
glm::vec3 parseColour(const ParseContext& context, pugi::xml_node element);

// The same for text that is not an element's own (an attribute such as <scene bgColor="...">);
// `owner` gives the line and `label` names the attribute in the message.
glm::vec3 parseVec3Text(const ParseContext& context, pugi::xml_node owner, const std::string& label,
                        const std::string& text);

}  // namespace vkrt
