// Course XML scene file -> Scene (docs/XML_FORMAT.md). Accepts every variant the real files use; malformed
// input is a SceneError naming file:line, the element and the value; recoverable oddities are
// warnings in Diagnostics (errors when strict). Callers use loadScene (scene_loader.h).
#pragma once

#include <string>

#include "diagnostics.h"
#include "scene.h"
#include "scene_loader.h"

namespace vkrt {

// `text` is the file's content (readSourceFile).
Scene loadXmlScene(const std::string& path, const std::string& text, const LoadOptions& options, Diagnostics& diagnostics);

}  // namespace vkrt
