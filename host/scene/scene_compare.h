// Field-by-field equality of two scene models: what `vkrt convert` checks after writing (the
// written file must load back as the model it was written from) and what the round-trip tests
// assert. Floats compare by bit pattern (0 and -0 differ, as they may in a render), file paths by
// the file they name (two spellings of one path are equal), texture and mesh data element by
// element. Source locations and Scene::path are not compared: a written file has other lines.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "scene.h"

namespace vkrt {

struct SceneDifferences {
    std::vector<std::string> first;  // "shaders[2].diffuse: 0.5 0.5 0.5 vs 0.5 0.5 0.25", at most `limit`
    std::size_t count = 0;           // every differing field
    bool equal() const { return count == 0; }
    std::string summary() const;     // the first ones, one per line, and how many more
};

SceneDifferences compareScenes(const Scene& a, const Scene& b, std::size_t limit = 10);

}  // namespace vkrt
