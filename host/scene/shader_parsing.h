// <shader name=".." type=".."> definitions -> Shader (docs/XML_FORMAT.md §3.5, defaults of §7).
#pragma once

#include <map>
#include <string>

#include <pugixml.hpp>

#include "parse_context.h"
#include "scene.h"
#include "texture_loading.h"

namespace vkrt {

// Parses a shader definition. Type mapping (scene_rules.h): Phong -> BlinnPhong; BlinnPhong (or
// Phong) with mirrorCoef > 0 -> BlinnPhongMirrored (2011/12 files); Diffuse (JSON era) ->
// Lambertian with diffuseBounce; Emitter -> black Lambertian with its <emission> (shader_emitters.h makes its shapes emitters); any other type
// -> warning, Lambertian with the shader's diffuse (grey 0.5 without one).
// A parameter the type does not use (mirrorCoef on a Lambertian) is a warning. An undefined
// texture name is a SceneError.
Shader parseShader(const ParseContext& context, pugi::xml_node node, const TextureTable& textures);

}  // namespace vkrt
