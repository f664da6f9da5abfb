// <transform> inside a shape: translate / rotate / scale children composed in listed order.
#pragma once

#include <vector>

#include <pugixml.hpp>

#include "parse_context.h"
#include "scene.h"
#include "scene_rules.h"

namespace vkrt {

// The children in document order; they compose (rules::composeTransform) to M = T0 * T1 * ... *
// Tn-1, so p' = M p applies the LAST listed operation to the object first (docs/XML_FORMAT.md §3.9: JSON-2026 parseTransformData and PT's
// Transform.cpp). Rotation angles are degrees about the axis named by the first character of
// `axis` (X, Y or Z, any case). A zero scale component is an error: the renderers need M^-1.
// `transform` may be empty (no <transform>): no steps, the identity (moved to the local origin under
// LoadOptions::localOrigin). A composed matrix that float cannot hold or invert is a SceneError at
// the <transform>.
rules::Placement parseTransform(const ParseContext& context, pugi::xml_node transform);

}  // namespace vkrt
