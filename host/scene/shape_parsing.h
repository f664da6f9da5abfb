// The geometry of <shape> and <instance> elements: sphere, box, triangle, mesh (docs/XML_FORMAT.md §3.6-3.8).
#pragma once

#include <pugixml.hpp>

#include "mesh_library.h"
#include "parse_context.h"
#include "scene.h"

namespace vkrt {

// Reads the geometry children of `node` into `shape` (type already set). Errors: missing
// elements, a radius <= 0, a box with minPt > maxPt on some axis (equal is allowed: a zero-
// thickness box), a bad mesh file (named at its <file> element). A zero-area triangle is only a
// warning (it is never hit). The rules are scene_rules.h's, shared with the JSON loader.
// `world`: the shape is placed as it stands (not a prototype, no transform), so its points are
// positions (parsePosition).
void parseGeometry(const ParseContext& context, pugi::xml_node node, Shape& shape, MeshLibrary& meshes, bool world);

}  // namespace vkrt
