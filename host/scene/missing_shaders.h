// Shaders a scene file names but never defines. sd20190404_oneOBJ_Al.json names `whiteMat`,
// sd20200409_mirroredScene.json misspells `_name` so its `green1` is never defined, and many
// prototypes name shaders no file has: each missing name gets one grey Lambertian (the loader
// warns at every reference), so the scene stays whole and the image shows what was missing instead
// of the load failing on a file the course's own parser renders.
#pragma once

#include <map>
#include <string>

#include "scene.h"

namespace vkrt {

class MissingShaders {
public:
    // The placeholder's index in scene.shaders, added at its first reference.
    int placeholderFor(Scene& scene, const std::string& name, const SourceLocation& where);
    bool isPlaceholder(int shader) const;

private:
    std::map<std::string, int> indexByName_;
};

}  // namespace vkrt
