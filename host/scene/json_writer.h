// Scene -> the course's current (G2) JSON form (docs/JSON_FORMAT.md): {"scene": {...}} with
// underscore attribute keys, vectors as "x y z" strings, transforms as ordered xform arrays.
// Loading the text back gives the same scene model (scene_compare.h), the rules in
// docs/SCENE_CONVERSION.md.
#pragma once

#include <filesystem>
#include <string>

#include "scene.h"

namespace vkrt {

// `outputDirectory`: where the file will be written; paths are made relative to it.
std::string jsonSceneText(const Scene& scene, const std::filesystem::path& outputDirectory);

}  // namespace vkrt
