#include "shape_parsing.h"

#include <filesystem>
#include <stdexcept>

#include "obj_mesh.h"
#include "value_parsing.h"

namespace vkrt {

std::optional<ShapeType> shapeTypeFromName(std::string_view name) {
    if (name == "sphere") return ShapeType::Sphere;
    if (name == "box") return ShapeType::Box;
    if (name == "triangle") return ShapeType::Triangle;
    if (name == "mesh") return ShapeType::Mesh;
    return std::nullopt;
}

std::vector<std::string_view> geometryChildren(ShapeType type) {
    switch (type) {
        case ShapeType::Sphere: return {"center", "radius"};
        case ShapeType::Box: return {"minPt", "maxPt"};
        case ShapeType::Triangle: return {"v0", "v1", "v2"};
        case ShapeType::Mesh: return {"file"};
    }
    return {};
}

int MeshLibrary::meshFor(const ParseContext& context, pugi::xml_node file) {
    checkAttributes(context, file, {});
    const std::string relative = trimmed(elementText(file));
    if (relative.empty()) context.fail(file, "empty mesh file name");

    const std::filesystem::path resolved = (context.sceneDirectory / relative).lexically_normal();
    const std::string key = std::filesystem::absolute(resolved).lexically_normal().string();
    if (const auto found = indexOfPath_.find(key); found != indexOfPath_.end()) return found->second;

    try {
        meshes_.push_back(loadObjMesh(resolved.string()));
    } catch (const std::runtime_error& error) {
        context.fail(file, error.what(), resolved.string());
    }
    const int index = static_cast<int>(meshes_.size()) - 1;
    indexOfPath_.emplace(key, index);
    return index;
}

void parseGeometry(const ParseContext& context, pugi::xml_node node, Shape& shape, MeshLibrary& meshes) {
    switch (shape.type) {
        case ShapeType::Sphere: {
            shape.center = parseVec3(context, requireChild(context, node, "center"));
            const pugi::xml_node radius = requireChild(context, node, "radius");
            shape.radius = parseScalar(context, radius);
            if (!(shape.radius > 0.0f)) context.fail(radius, "radius must be positive", elementText(radius));
            break;
        }
        case ShapeType::Box: {
            const pugi::xml_node minPt = requireChild(context, node, "minPt");
            const pugi::xml_node maxPt = requireChild(context, node, "maxPt");
            shape.minPt = parseVec3(context, minPt);
            shape.maxPt = parseVec3(context, maxPt);
            for (int axis = 0; axis < 3; ++axis) {
                if (shape.minPt[axis] > shape.maxPt[axis])
                    context.fail(minPt, std::string("greater than maxPt on the ") + "xyz"[axis] + " axis",
                                 elementText(minPt) + " > " + elementText(maxPt));
            }
            break;
        }
        case ShapeType::Triangle: {
            shape.v0 = parseVec3(context, requireChild(context, node, "v0"));
            shape.v1 = parseVec3(context, requireChild(context, node, "v1"));
            shape.v2 = parseVec3(context, requireChild(context, node, "v2"));
            if (glm::length(glm::cross(shape.v1 - shape.v0, shape.v2 - shape.v0)) == 0.0f)
                context.warn(node, "degenerate triangle (zero area), it is never hit", shape.name);
            break;
        }
        case ShapeType::Mesh: shape.mesh = meshes.meshFor(context, requireChild(context, node, "file")); break;
    }
}

}  // namespace vkrt
