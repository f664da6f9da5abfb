// The geometry of <shape> and <instance> elements: sphere, box, triangle, mesh (docs/XML_FORMAT.md §3.6-3.8).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <pugixml.hpp>

#include "parse_context.h"
#include "scene.h"

namespace vkrt {

std::optional<ShapeType> shapeTypeFromName(std::string_view name);

// The child element names a geometry type reads (for checkChildren).
std::vector<std::string_view> geometryChildren(ShapeType type);

// Loads each distinct OBJ file once, however many shapes and prototypes use it.
class MeshLibrary {
public:
    explicit MeshLibrary(std::vector<Mesh>& meshes) : meshes_(meshes) {}
    // Index into the scene's meshes for the <file> element's path (relative to the scene file).
    // A missing or unreadable file is a SceneError naming the <file> element.
    int meshFor(const ParseContext& context, pugi::xml_node file);

private:
    std::vector<Mesh>& meshes_;
    std::map<std::string, int> indexOfPath_;  // key: the absolute, normalised path
};

// Reads the geometry children of `node` into `shape` (type already set). Errors: missing
// elements, a radius <= 0, a box with minPt > maxPt on some axis (equal is allowed: a zero-
// thickness box), a bad mesh file. A zero-area triangle is only a warning (it is never hit).
void parseGeometry(const ParseContext& context, pugi::xml_node node, Shape& shape, MeshLibrary& meshes);

}  // namespace vkrt
