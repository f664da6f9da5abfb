#include "shader_parsing.h"

#include <algorithm>
#include <optional>
#include <string_view>
#include <vector>

#include "name_suggestion.h"
#include "scene_rules.h"
#include "value_parsing.h"

namespace vkrt {

namespace {

int lookUpTexture(const ParseContext& context, pugi::xml_node at, const std::string& name,
                  const TextureTable& textures) {
    const auto found = textures.find(name);
    if (found == textures.end()) context.fail(at, "unresolved texture reference", name);
    return found->second;
}

// The colour of <diffuse>/<specular> and the texture its `tex` attribute binds, if any.
glm::vec3 parseTintedColour(const ParseContext& context, pugi::xml_node element, const TextureTable& textures,
                            int& texture) {
    checkAttributes(context, element, {"tex"});
    if (const pugi::xml_attribute tex = element.attribute("tex"))
        texture = lookUpTexture(context, element, tex.value(), textures);
    return parseColour(context, element);
}

float parseNonNegative(const ParseContext& context, pugi::xml_node element) {
    const float value = parseScalar(context, element);
    if (const std::string p = rules::nonNegativeProblem(value); !p.empty()) context.fail(element, p, elementText(element));
    return value;
}

}  // namespace

Shader parseShader(const ParseContext& context, pugi::xml_node node, const TextureTable& textures) {
    checkAttributes(context, node, {"type"});
    Shader shader;
    shader.name = node.attribute("name").value();
    shader.where = {context.source.path(), context.source.lineOf(node)};

    const std::string typeText = requireAttribute(context, node, "type");
    const std::optional<rules::ShaderTypeName> known = rules::shaderType(typeText);
    if (!known) context.warn(node, rules::kUnknownShaderType, typeText, didYouMean(typeText, rules::shaderTypeNames()));
    const rules::ShaderTypeName type = known.value_or(rules::ShaderTypeName{});
    shader.type = type.type;
    shader.diffuseBounce = type.diffuseBounce;

    // An unknown type's other parameters belong to whatever the author meant; the one warning
    // above covers them. For known types, a parameter the type does not read is worth a warning.
    const std::vector<std::string_view> used = rules::shaderParametersUsedBy(type);
    const std::vector<std::string_view>& all = rules::shaderParameters();
    for (pugi::xml_node child : node.children()) {
        const std::string_view name = child.name();
        if (!known || child.type() != pugi::node_element) continue;
        const bool isParameter = std::find(all.begin(), all.end(), name) != all.end();
        if (isParameter && std::find(used.begin(), used.end(), name) == used.end())
            context.warn(child, rules::unusedParameterProblem(type));
    }
    checkChildren(context, node, all);
    auto parameter = [&](const char* name) -> pugi::xml_node {
        return std::find(used.begin(), used.end(), name) != used.end() ? node.child(name) : pugi::xml_node();
    };

    bool hasDiffuse = false;
    if (pugi::xml_node e = parameter("diffuse")) {
        shader.diffuse = parseTintedColour(context, e, textures, shader.diffuseTexture);
        hasDiffuse = true;
    }
    if (pugi::xml_node e = parameter("diffusetex")) {  // 2012 binding: <diffusetex>textureName</diffusetex>
        checkAttributes(context, e, {});
        if (shader.diffuseTexture == kNoTexture) shader.diffuseTexture = lookUpTexture(context, e, trimmed(elementText(e)), textures);
    }
    const bool usesDiffuse = std::find(used.begin(), used.end(), "diffuse") != used.end();
    const bool bindsTexture = parameter("diffusetex") || (parameter("diffuse") && parameter("diffuse").attribute("tex"));
    if (usesDiffuse && !hasDiffuse) {
        // §7: white under a texture, so the texture shows as it is; grey (as for an unknown
        // type) when there is nothing at all to go on.
        shader.diffuse = glm::vec3(bindsTexture ? 1.0f : rules::kMissingDiffuseGrey);
        if (!bindsTexture && known) context.warn(node, "no <diffuse> colour, using grey 0.5", shader.name);
    }
    if (pugi::xml_node e = parameter("specular")) shader.specular = parseTintedColour(context, e, textures, shader.specularTexture);
    if (pugi::xml_node e = parameter("phongExp")) shader.phongExp = parseNonNegative(context, e);
    if (pugi::xml_node e = parameter("mirrorCoef")) {
        shader.mirrorCoef = parseScalar(context, e);
        if (const std::string p = rules::mirrorCoefProblem(shader.mirrorCoef); !p.empty()) context.warn(e, p, elementText(e));
    }
    if (pugi::xml_node e = parameter("roughness")) shader.roughness = parseNonNegative(context, e);
    if (pugi::xml_node e = parameter("refractiveIndex")) {
        shader.refractiveIndex = parseScalar(context, e);
        if (const std::string p = rules::refractiveIndexProblem(shader.refractiveIndex); !p.empty())
            context.fail(e, p, elementText(e));
    }
    if (pugi::xml_node e = parameter("attenuationCoef")) {
        shader.attenuation = parseVec3(context, e);
        if (const std::string p = rules::attenuationProblem(shader.attenuation); !p.empty())
            context.fail(e, p, elementText(e));
    }
    if (type.emitter) {
        shader.diffuse = glm::vec3(0.0f);  // an emitter reflects nothing (shader_emitters.h)
        if (pugi::xml_node e = parameter("emission")) shader.emission = parseColour(context, e);
    }

    rules::resolveLegacyShaderType(shader);  // docs/XML_FORMAT.md §6
    return shader;
}

}  // namespace vkrt
