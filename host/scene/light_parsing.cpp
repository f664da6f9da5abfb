#include "light_parsing.h"

#include <string>

#include "name_suggestion.h"
#include "scene_rules.h"
#include "value_parsing.h"

namespace vkrt {

namespace {
float parseLightSize(const ParseContext& context, pugi::xml_node node, const char* name) {
    const pugi::xml_node element = requireChild(context, node, name);
    const float value = parseScalar(context, element);
    if (const std::string p = rules::lightSizeProblem(value); !p.empty()) context.fail(element, p, elementText(element));
    return value;
}
}  // namespace

std::optional<Light> parseLight(const ParseContext& context, pugi::xml_node node) {
    checkAttributes(context, node, {"type"});
    const std::string type = requireAttribute(context, node, "type");
    Light light;
    light.where = {context.source.path(), context.source.lineOf(node)};
    const std::optional<LightType> known = rules::lightType(type);
    if (!known) {
        context.warn(node, rules::kUnknownLightType, type, didYouMean(type, rules::lightTypeNames()));
        return std::nullopt;
    }
    light.type = *known;
    checkChildren(context, node, {"position", "intensity", "normal", "width", "length"});
    light.position = parsePosition(context, requireChild(context, node, "position"), /*world=*/true);
    light.intensity = parseColour(context, requireChild(context, node, "intensity"));
    if (light.type == LightType::Area) {
        const pugi::xml_node normal = requireChild(context, node, "normal");
        const std::optional<glm::vec3> n = rules::unitNormal(parseVec3(context, normal));
        if (!n) context.fail(normal, rules::kZeroNormal, elementText(normal));
        light.normal = *n;
        light.width = parseLightSize(context, node, "width");
        light.length = parseLightSize(context, node, "length");
    }
    return light;
}

}  // namespace vkrt
