// Image files -> Texture::rgba8: PNG through libpng (png_reader.h), any other format through
// OpenImageIO (the module host/image/oiio_codec.h loads).
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>

#include "scene.h"

namespace vkrt {

// Reads a PNG natively, any other image OpenImageIO can read (JPEG, EXR, ...) through its module: 1 channel is grey, 2 grey+alpha,
// 3 RGB, 4+ RGBA (extra channels dropped); alpha defaults to opaque. Values are converted to 8
// bits by OpenImageIO (no colour-space change: textures are used linearly, as the course did).
// Returns nullopt and sets `error` when the file is missing, unreadable, empty or claims more
// than the image-texels input limit (input_limits.h; checked from the header, before any texel is
// allocated). A scene's textures together hold at most the scene-texels limit: many images each
// under the per-image limit would otherwise add up without bound (eight took 1.25 GB); the texture
// past the total is left out with a warning, as a missing one is.
std::optional<Texture> loadTextureImage(const std::string& path, std::string& error);

// Texture name -> index into Scene::textures, or kNoTexture for a texture that was defined but
// could not be loaded (the shader then uses its tint colour alone).
using TextureTable = std::map<std::string, int>;

// A texture definition, as both formats read it: the first definition of a name is kept, a file an
// earlier name loaded is shared (same canonical path), and a file that cannot be loaded leaves the
// name defined as kNoTexture. The loader warns with
// `problem`: at the definition for a Duplicate (value: the name), at the file name for a
// Missing one (value: the resolved path).
struct TextureDefinition {
    enum Outcome { Added, Duplicate, Missing } outcome = Added;
    std::string problem;
};
TextureDefinition defineTexture(Scene& scene, TextureTable& textures, const std::string& name, const std::string& path,
                                const SourceLocation& where);

}  // namespace vkrt
