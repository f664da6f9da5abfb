#include "shape_parsing.h"

#include <stdexcept>

#include "scene_rules.h"
#include "value_parsing.h"

namespace vkrt {

namespace {

int meshOf(const ParseContext& context, pugi::xml_node file, MeshLibrary& meshes) {
    checkAttributes(context, file, {});
    const std::string relative = trimmed(elementText(file));
    if (relative.empty()) context.fail(file, "empty mesh file name");
    const std::string path = rules::resolveScenePath(context.sceneDirectory, relative);
    try {
        return meshes.meshFor(path);
    } catch (const std::runtime_error& error) {
        context.fail(file, error.what(), path);
    }
}

}  // namespace

void parseGeometry(const ParseContext& context, pugi::xml_node node, Shape& shape, MeshLibrary& meshes, bool world) {
    switch (shape.type) {
        case ShapeType::Sphere: {
            shape.center = parsePosition(context, requireChild(context, node, "center"), world);
            const pugi::xml_node radius = requireChild(context, node, "radius");
            shape.radius = parseScalar(context, radius);
            if (const std::string p = rules::radiusProblem(shape.radius); !p.empty()) context.fail(radius, p, elementText(radius));
            break;
        }
        case ShapeType::Box: {
            const pugi::xml_node minPt = requireChild(context, node, "minPt");
            const pugi::xml_node maxPt = requireChild(context, node, "maxPt");
            shape.minPt = parsePosition(context, minPt, world);
            shape.maxPt = parsePosition(context, maxPt, world);
            if (const std::string p = rules::orderBoxCorners(shape.minPt, shape.maxPt); !p.empty())
                context.warn(minPt, p, elementText(minPt) + " > " + elementText(maxPt));
            break;
        }
        case ShapeType::Triangle: {
            shape.v0 = parsePosition(context, requireChild(context, node, "v0"), world);
            shape.v1 = parsePosition(context, requireChild(context, node, "v1"), world);
            shape.v2 = parsePosition(context, requireChild(context, node, "v2"), world);
            if (rules::isDegenerateTriangle(shape.v0, shape.v1, shape.v2)) context.warn(node, rules::kDegenerateTriangle, shape.name);
            break;
        }
        case ShapeType::Mesh: shape.mesh = meshOf(context, requireChild(context, node, "file"), meshes); break;
    }
}

}  // namespace vkrt
