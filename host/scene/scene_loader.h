// A course scene file, XML (FORMAT.md) or JSON (docs/JSON_FORMAT.md) -> Scene. The format is
// chosen by the file name's extension (.xml, .json, any case) and confirmed by the content (the
// first byte that is not white space: '<' or '{'); a name without either extension goes by the
// content alone. A file whose name and content disagree, or whose format cannot be told, is a
// SceneError naming the file.
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
