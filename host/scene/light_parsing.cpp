#include "light_parsing.h"

#include <cmath>
#include <string>

#include "value_parsing.h"

namespace vkrt {

namespace {
float parseLightSize(const ParseContext& context, pugi::xml_node node, const char* name) {
    const pugi::xml_node element = requireChild(context, node, name);
    const float value = parseScalar(context, element);
    // Zero is allowed: a 0x0 area light is exactly its point light (docs/RENDERING.md; tested in
    // tests/stability), so a user can shrink a light to nothing without rewriting it.
    if (!(value >= 0.0f)) context.fail(element, "must not be negative", elementText(element));
    return value;
}
}  // namespace

std::optional<Light> parseLight(const ParseContext& context, pugi::xml_node node) {
    checkAttributes(context, node, {"type"});
    const std::string type = requireAttribute(context, node, "type");
    Light light;
    light.where = {context.source.path(), context.source.lineOf(node)};
    if (type == "point") {
        light.type = LightType::Point;
    } else if (type == "area") {
        light.type = LightType::Area;
    } else {
        context.warn(node, "unknown light type, light skipped", type);
        return std::nullopt;
    }
    checkChildren(context, node, {"position", "intensity", "normal", "width", "length"});
    light.position = parseVec3(context, requireChild(context, node, "position"));
    light.intensity = parseVec3(context, requireChild(context, node, "intensity"));
    if (light.type == LightType::Area) {
        const pugi::xml_node normal = requireChild(context, node, "normal");
        const glm::vec3 n = parseVec3(context, normal);
        const float length = glm::length(n);
        if (!(length > 0.0f) || !std::isfinite(length)) context.fail(normal, "normal has zero length", elementText(normal));
        light.normal = n / length;
        light.width = parseLightSize(context, node, "width");
        light.length = parseLightSize(context, node, "length");
    }
    return light;
}

}  // namespace vkrt
