// Image files -> Texture::rgba8 through OpenImageIO.
#pragma once

#include <optional>
#include <string>

#include "scene.h"

namespace vkrt {

// Reads any image OpenImageIO can read (PNG, JPEG, EXR, ...): 1 channel is grey, 2 grey+alpha,
// 3 RGB, 4+ RGBA (extra channels dropped); alpha defaults to opaque. Values are converted to 8
// bits by OpenImageIO (no colour-space change: textures are used linearly, as the course did).
// Returns nullopt and sets `error` when the file is missing, unreadable or empty.
std::optional<Texture> loadTextureImage(const std::string& path, std::string& error);

}  // namespace vkrt
