// vkrt convert: a scene file read (XML or JSON) and written in the format the output's extension
// names, then checked: the written file is loaded back and must give the model it was written from
// (scene_compare.h), or nothing is written. docs/SCENE_CONVERSION.md.
#pragma once

#include <atomic>
#include <cstddef>
#include <string>
#include <vector>

#include "diagnostics.h"

namespace vkrt {

struct Conversion {
    std::string format;   // "json" or "xml"
    std::string counts;   // "1 camera, 2 lights, ..." for the summary line
    int renamedShaders = 0;  // nameless shaders written under a generated name
    std::size_t escapedNames = 0;  // names written with \xNN escapes (writing::writableName)
    std::vector<std::string> definedPlaceholders;  // shaders the input names but never defines, written
                                                   // as the grey placeholder they render as
};

// Throws std::runtime_error (or SceneError for a bad input) with a message naming the file. The
// input's warnings go to `diagnostics`; the output path is checked before the input is read.
// `cancel` (Ctrl-C, interrupt.h) is polled between the steps; when set, RenderCancelled is thrown and
// nothing is left behind.
Conversion convertScene(const std::string& input, const std::string& output, Diagnostics& diagnostics,
                        const std::atomic<bool>* cancel = nullptr);

}  // namespace vkrt
