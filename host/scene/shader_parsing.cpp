#include "shader_parsing.h"

#include <algorithm>
#include <optional>
#include <string_view>
#include <vector>

#include "value_parsing.h"

namespace vkrt {

namespace {

// Every parameter element any shader type reads.
constexpr std::string_view kAllParameters[] = {"diffuse",   "diffusetex",      "specular",       "phongExp",
                                               "mirrorCoef", "roughness",      "refractiveIndex", "attenuationCoef"};

std::vector<std::string_view> parametersUsedBy(ShaderType type) {
    switch (type) {
        case ShaderType::Lambertian:
        case ShaderType::CoolToWarm: return {"diffuse", "diffusetex"};
        // BlinnPhong keeps mirrorCoef/roughness: mirrorCoef > 0 makes it BlinnPhongMirrored.
        case ShaderType::BlinnPhong:
        case ShaderType::BlinnPhongMirrored:
            return {"diffuse", "diffusetex", "specular", "phongExp", "mirrorCoef", "roughness"};
        case ShaderType::Mirror: return {"roughness"};
        case ShaderType::Glaze: return {"diffuse", "diffusetex", "mirrorCoef", "roughness"};
        case ShaderType::Dielectric: return {"refractiveIndex", "attenuationCoef"};
    }
    return {};
}

std::optional<ShaderType> shaderTypeFromName(std::string_view name) {
    if (name == "Lambertian" || name == "Diffuse") return ShaderType::Lambertian;
    if (name == "BlinnPhong" || name == "Phong") return ShaderType::BlinnPhong;
    if (name == "Mirror") return ShaderType::Mirror;
    if (name == "Glaze") return ShaderType::Glaze;
    if (name == "BlinnPhongMirrored") return ShaderType::BlinnPhongMirrored;
    if (name == "Dielectric") return ShaderType::Dielectric;
    if (name == "CoolToWarm") return ShaderType::CoolToWarm;
    return std::nullopt;
}

const char* typeName(ShaderType type) {
    switch (type) {
        case ShaderType::Lambertian: return "Lambertian";
        case ShaderType::BlinnPhong: return "BlinnPhong";
        case ShaderType::Mirror: return "Mirror";
        case ShaderType::Glaze: return "Glaze";
        case ShaderType::BlinnPhongMirrored: return "BlinnPhongMirrored";
        case ShaderType::Dielectric: return "Dielectric";
        case ShaderType::CoolToWarm: return "CoolToWarm";
    }
    return "?";
}

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
    return parseVec3(context, element);
}

float parseNonNegative(const ParseContext& context, pugi::xml_node element) {
    const float value = parseScalar(context, element);
    if (value < 0.0f) context.fail(element, "must not be negative", elementText(element));
    return value;
}

}  // namespace

Shader parseShader(const ParseContext& context, pugi::xml_node node, const TextureTable& textures) {
    checkAttributes(context, node, {"type"});
    Shader shader;
    shader.name = node.attribute("name").value();
    shader.where = {context.source.path(), context.source.lineOf(node)};

    const std::string typeText = requireAttribute(context, node, "type");
    const std::optional<ShaderType> known = shaderTypeFromName(typeText);
    if (!known) context.warn(node, "unknown shader type, using Lambertian with its diffuse colour", typeText);
    shader.type = known.value_or(ShaderType::Lambertian);

    // An unknown type's other parameters belong to whatever the author meant; the one warning
    // above covers them. For known types, a parameter the type does not read is worth a warning.
    const std::vector<std::string_view> used = parametersUsedBy(shader.type);
    for (pugi::xml_node child : node.children()) {
        const std::string_view name = child.name();
        if (!known || child.type() != pugi::node_element) continue;
        const bool isParameter = std::find(std::begin(kAllParameters), std::end(kAllParameters), name) != std::end(kAllParameters);
        if (isParameter && std::find(used.begin(), used.end(), name) == used.end())
            context.warn(child, std::string("not used by a ") + typeName(shader.type) + " shader, ignored");
    }
    checkChildren(context, node, {std::begin(kAllParameters), std::end(kAllParameters)});
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
        shader.diffuse = glm::vec3(bindsTexture ? 1.0f : 0.5f);
        if (!bindsTexture && known) context.warn(node, "no <diffuse> colour, using grey 0.5", shader.name);
    }
    if (pugi::xml_node e = parameter("specular")) shader.specular = parseTintedColour(context, e, textures, shader.specularTexture);
    if (pugi::xml_node e = parameter("phongExp")) shader.phongExp = parseNonNegative(context, e);
    if (pugi::xml_node e = parameter("mirrorCoef")) shader.mirrorCoef = parseScalar(context, e);
    if (pugi::xml_node e = parameter("roughness")) shader.roughness = parseNonNegative(context, e);
    if (pugi::xml_node e = parameter("refractiveIndex")) {
        shader.refractiveIndex = parseScalar(context, e);
        if (!(shader.refractiveIndex > 0.0f)) context.fail(e, "must be positive", elementText(e));
    }
    if (pugi::xml_node e = parameter("attenuationCoef")) shader.attenuation = parseVec3(context, e);

    // 2011/12 files write a mirrored Blinn-Phong as BlinnPhong + mirrorCoef (docs/XML_FORMAT.md §6).
    if (shader.type == ShaderType::BlinnPhong && shader.mirrorCoef > 0.0f) shader.type = ShaderType::BlinnPhongMirrored;
    return shader;
}

}  // namespace vkrt
