// A course scene file, XML (FORMAT.md) or JSON (docs/JSON_FORMAT.md) -> Scene. The format is
// chosen by the file name's extension (.xml, .json, any case) and confirmed by the content (the
// first byte that is not white space: '<' or '{'); a name without either extension goes by the
// content alone. A file whose name and content disagree, or whose format cannot be told, is a
// SceneError naming the file.
#pragma once

#include <string>

#include "diagnostics.h"
#include "environment_loading.h"
#include "scene.h"

namespace vkrt {

struct LoadOptions {
    bool strict = false;  // every warning becomes a SceneError
    // Read world positions in double and store them relative to the default camera's eye
    // (Scene::origin, local_origin.h): what renders use, so that a scene far from the origin keeps
    // its image. Off, the model holds the file's own numbers (vkrt convert, the loader's tests).
    bool localOrigin = false;
    // How an environment map's -Z cube face file is read: by default whichever way joins its
    // neighbours with the smaller seam error (environment_loading.h, docs/RENDERING.md §10.2).
    NegZRule environmentNegZ = NegZRule::Measure;
    // false: an environment map's files are named (Scene::envMapPrefix / envMapVertCross resolved)
    // but not read, and Scene::environment stays empty: what `vkrt convert` and the writers' tests
    // need (they write the names), without decoding six 1024^2 faces per load.
    bool environmentTexels = true;
    // Shapes and still instances whose shader is an `Emitter` become shape emitters
    // (shader_emitters.h): what renders use. Off, the model keeps the file's form (vkrt convert).
    bool shaderEmitters = false;
};

Scene loadScene(const std::string& path, const LoadOptions& options, Diagnostics& diagnostics);

}  // namespace vkrt
