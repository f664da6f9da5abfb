// Course XML scene file -> Scene (docs/XML_FORMAT.md). Accepts every variant the real files use; malformed
// input is a SceneError naming file:line, the element and the value; recoverable oddities are
// warnings in Diagnostics (errors when strict).
#pragma once

#include <string>

#include "diagnostics.h"
#include "scene.h"

namespace vkrt {

struct LoadOptions {
    bool strict = false;  // every warning becomes a SceneError
};

Scene loadScene(const std::string& path, const LoadOptions& options, Diagnostics& diagnostics);

}  // namespace vkrt
