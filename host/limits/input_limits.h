// What vkrt reads at most from a file it is handed: one policy for every reader (scene files, OBJ
// meshes, textures, environment maps, images read whole by merge, check and sweep). Each limit is
// checked from a file's size or header before anything is allocated, so a small forged file cannot
// make vkrt allocate gigabytes; host/scene/README.md gives each value's reason. The limits are
// process-wide: `--input-limit NAME=VALUE` sets them once, before any file is read.
#pragma once

#include <cstdint>
#include <string>

namespace vkrt {

struct InputLimits {
    std::uint64_t sceneFileBytes = std::uint64_t(64) << 20;  // one XML/JSON scene file
    std::uint64_t meshFileBytes = std::uint64_t(1) << 30;    // one OBJ file
    std::uint64_t imageTexels = std::uint64_t(1) << 25;      // one texture, or an environment map's six faces together
    std::uint64_t sceneTexels = std::uint64_t(1) << 26;      // all of a scene's textures together
    std::uint64_t readPixels = std::uint64_t(1) << 28;       // one image read whole (merge's parts, check's image)
};

// The limits in force (the defaults above until setInputLimit changes one).
const InputLimits& inputLimits();

// "NAME=VALUE" with NAME one of scene-bytes, mesh-bytes, image-texels, scene-texels, read-pixels
// and VALUE a positive whole number, optionally with a K, M or G suffix (powers of 1024).
// Throws std::invalid_argument naming what is wrong and the names there are.
void setInputLimit(const std::string& assignment);

// Puts every limit back to its default (tests).
void resetInputLimits();

// " (--input-limit NAME=N raises it)": the end of every message that reports a limit.
std::string inputLimitHint(const char* name);

}  // namespace vkrt
