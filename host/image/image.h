// A linear float RGB image, the common result of both renderers.
#pragma once

#include <cstddef>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace vkrt {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> pixels;  // row-major, row 0 = top

    Image() = default;
    Image(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, glm::vec3(0.0f)) {}
    glm::vec3& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
    const glm::vec3& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

// The course's 8-bit rule: clamp to [0,1] once, then truncate int(c * 255).
inline std::uint8_t quantize8(float c) {
    if (!(c > 0.0f)) return 0;  // also maps NaN to 0
    if (c >= 1.0f) return 255;
    return static_cast<std::uint8_t>(c * 255.0f);
}

// Writes by extension: .png/.jpg/.jpeg/.ppm as 8-bit (quantize8), .exr as linear float.
// The file is written beside its final name and renamed into place, so a reader (or a kill
// during the write) never sees a truncated image. Throws std::runtime_error naming the file.
// `attributes` ("vkrt:..." names) are kept by EXR files only (a --part's rows, for vkrt merge).
using ImageAttributes = std::map<std::string, std::string>;
void writeImage(const Image& image, const std::string& path, const ImageAttributes& attributes = {});

// The image as the bytes of an 8-bit PNG file (quantize8), for the preview page; throws
// std::runtime_error with libpng's reason.
std::vector<std::uint8_t> encodePng(const Image& image);

// Throws std::runtime_error naming the file when writeImage(path) is bound to fail: an unknown
// extension, a folder that does not exist or cannot be written. Called before a render starts,
// so a long render is not thrown away for a typo in -o.
void checkImageOutputPath(const std::string& path);

// Reads any format OpenImageIO knows; 8-bit files come back as value/255. Throws
// std::runtime_error naming the file when it cannot be read or its header claims more than
// `maxPixels` pixels (default: the read-pixels input limit, input_limits.h), checked before any
// pixel is allocated: a 69-byte PNG may claim 40000 x 40000. An OpenEXR header is checked first
// (exr_header_check.h); at most four channels are read.
Image readImage(const std::string& path, ImageAttributes* attributes = nullptr, std::optional<std::size_t> maxPixels = std::nullopt);

// The number of pixels with a NaN or infinite channel.
std::size_t countNonFinite(const Image& image);

}  // namespace vkrt
