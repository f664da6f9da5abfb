#include "missing_shaders.h"

#include "scene_rules.h"

namespace vkrt {

int MissingShaders::placeholderFor(Scene& scene, const std::string& name, const SourceLocation& where) {
    auto [it, inserted] = indexByName_.try_emplace(name, static_cast<int>(scene.shaders.size()));
    if (inserted) {
        Shader placeholder;
        placeholder.name = name;
        placeholder.diffuse = glm::vec3(rules::kMissingDiffuseGrey);
        placeholder.undefined = true;
        placeholder.where = where;
        scene.shaders.push_back(placeholder);
    }
    return it->second;
}

bool MissingShaders::isPlaceholder(int shader) const {
    for (const auto& [name, index] : indexByName_)
        if (index == shader) return true;
    return false;
}

}  // namespace vkrt
