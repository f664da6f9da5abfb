// Every file a loaded scene was read from: the scene file, its meshes, its textures, its
// environment map's faces or cross. Watch mode watches them; a render refuses an output (-o) that
// is one of them (render_steps.cpp), since writing it would destroy the scene's own input.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scene.h"

namespace vkrt {

struct SceneInput {
    std::filesystem::path path;
    std::string kind;  // "the scene file", "a mesh", "a texture", "an environment map face"
};

std::vector<SceneInput> sceneInputs(const Scene& scene);

}  // namespace vkrt
