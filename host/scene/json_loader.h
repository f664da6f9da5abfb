// The course's JSON scene files -> Scene (docs/JSON_FORMAT.md): the G0 xml2json form, the 2019
// transform objects and the current xform arrays, with the XML loader's rules (scene_rules.h) and
// its conventions for errors (a SceneError naming file:line:column, the JSON path and the value)
// and warnings (recovered oddities; errors when strict). Callers use loadScene (scene_loader.h).
#pragma once

#include <string>

#include "diagnostics.h"
#include "scene.h"
#include "scene_loader.h"

namespace vkrt {

// `text` is the file's content (readSourceFile).
Scene loadJsonScene(const std::string& path, const std::string& text, const LoadOptions& options, Diagnostics& diagnostics);

}  // namespace vkrt
