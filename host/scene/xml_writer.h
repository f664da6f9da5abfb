// Scene -> the course's XML form (docs/XML_FORMAT.md), with vkrt's additions for what only JSON
// could say (a shape light as <light type="shape">, §3.4). Loading the text back gives the same
// scene model (scene_compare.h), the rules in docs/SCENE_CONVERSION.md.
#pragma once

#include <filesystem>
#include <string>

#include "scene.h"

namespace vkrt {

// `outputDirectory`: where the file will be written; paths are made relative to it.
std::string xmlSceneText(const Scene& scene, const std::filesystem::path& outputDirectory);

}  // namespace vkrt
