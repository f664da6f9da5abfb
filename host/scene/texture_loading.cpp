#include "texture_loading.h"

#include <cstdint>
#include <filesystem>
#include <vector>

#include "codec_module.h"
#include "exr_header_check.h"
#include "input_limits.h"
#include "png_reader.h"
#include "scene_rules.h"

namespace vkrt {

std::optional<Texture> loadTextureImage(const std::string& path, std::string& error) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        error = "texture file not found";
        return std::nullopt;
    }
    const std::size_t maxTexels = static_cast<std::size_t>(inputLimits().imageTexels);
    if (const std::string problem = exrHeaderProblem(path, maxTexels, inputLimitHint("image-texels")); !problem.empty()) {
        error = "cannot read texture image (" + problem + ")";
        return std::nullopt;
    }
    oiio::Pixels image;
    std::string detail;
    oiio::ReadResult result = oiio::ReadResult::CannotOpen;
    if (isPngFile(path)) {
        result = readPng8(path, maxTexels, image, detail);  // no module needed (png_reader.h)
    } else {
        try {
            result = oiioCodec().readBytes(path, maxTexels, image, detail);
        } catch (const std::runtime_error& e) {  // the module itself is missing
            detail = e.what();
        }
    }
    switch (result) {
        case oiio::ReadResult::Ok: break;
        case oiio::ReadResult::CannotOpen: error = "cannot read texture image (" + detail + ")"; return std::nullopt;
        case oiio::ReadResult::Empty: error = "texture image is empty"; return std::nullopt;
        // Checked before anything is allocated: a 69-byte PNG may claim 40000 x 40000, which would
        // zero-fill gigabytes before the decoder finds no data.
        case oiio::ReadResult::TooLarge:
            error = "texture image claims " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                    " texels, more than the " + std::to_string(maxTexels) + " vkrt loads" + inputLimitHint("image-texels");
            return std::nullopt;
        case oiio::ReadResult::CannotDecode: error = "cannot decode texture image (" + detail + ")"; return std::nullopt;
    }
    const int channels = image.channels;
    const std::size_t texels = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
    const std::vector<std::uint8_t>& pixels = image.bytes;

    Texture texture;
    texture.path = path;
    texture.width = image.width;
    texture.height = image.height;
    texture.rgba8.resize(texels);
    for (std::size_t i = 0; i < texels; ++i) {
        const std::uint8_t* p = &pixels[i * static_cast<std::size_t>(channels)];
        const bool grey = channels < 3;
        const std::uint32_t r = p[0];
        const std::uint32_t g = grey ? p[0] : p[1];
        const std::uint32_t b = grey ? p[0] : p[2];
        const std::uint32_t a = channels == 2 ? p[1] : channels >= 4 ? p[3] : 255u;
        texture.rgba8[i] = r | (g << 8) | (b << 16) | (a << 24);
    }
    return texture;
}

TextureDefinition defineTexture(Scene& scene, TextureTable& textures, const std::string& name, const std::string& path,
                                const SourceLocation& where) {
    if (textures.count(name)) return {TextureDefinition::Duplicate, "duplicate texture name, the first definition is kept"};
    // One decode per file: the texture a file gave an earlier name is shared (100 names of one
    // 2K image would otherwise decode it 100 times and hold 100 copies).
    std::error_code ec;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
    for (std::size_t i = 0; i < scene.textures.size() && !ec; ++i) {
        std::error_code other;
        if (std::filesystem::weakly_canonical(scene.textures[i].path, other) == canonical && !other) {
            textures[name] = static_cast<int>(i);
            return {};
        }
    }
    std::string error;
    std::optional<Texture> texture = loadTextureImage(path, error);
    if (!texture) {
        textures[name] = kNoTexture;
        return {TextureDefinition::Missing, rules::missingTextureProblem(error, name)};
    }
    std::size_t total = static_cast<std::size_t>(texture->width) * static_cast<std::size_t>(texture->height);
    for (const Texture& loaded : scene.textures) total += static_cast<std::size_t>(loaded.width) * static_cast<std::size_t>(loaded.height);
    if (total > inputLimits().sceneTexels) {
        textures[name] = kNoTexture;
        return {TextureDefinition::Missing,
                rules::missingTextureProblem("with it the scene's textures would hold " + std::to_string(total) +
                                                 " texels, more than the " + std::to_string(inputLimits().sceneTexels) +
                                                 " vkrt loads for one scene" + inputLimitHint("scene-texels"),
                                             name)};
    }
    texture->name = name;
    texture->where = where;
    textures[name] = static_cast<int>(scene.textures.size());
    scene.textures.push_back(std::move(*texture));
    return {};
}

}  // namespace vkrt
