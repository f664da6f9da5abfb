#include "image.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include <unistd.h>

#include "codec_module.h"
#include "exr_header_check.h"
#include "input_limits.h"
#include "native_formats.h"
#include "output_file.h"

namespace vkrt {

namespace {

bool isSupportedOutput(const std::string& ext) {
    return ext == ".exr" || ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".ppm";
}

// Writes the file at `target` (a temporary name) in the format of `path`'s extension: PNG and PPM
// natively, EXR and JPEG through the OpenImageIO module.
void writeImageFile(const Image& image, const std::string& path, const std::string& target, const ImageAttributes& attributes) {
    const std::string ext = lowerExtension(path);
    const bool isFloat = ext == ".exr";
    oiio::Pixels pixels;
    pixels.width = image.width;
    pixels.height = image.height;
    pixels.channels = 3;
    pixels.attributes.assign(attributes.begin(), attributes.end());
    if (isFloat) {
        pixels.floats.resize(image.pixels.size() * 3);
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c) pixels.floats[i * 3 + c] = image.pixels[i][c];
    } else {
        pixels.bytes.resize(image.pixels.size() * 3);
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c) pixels.bytes[i * 3 + c] = quantize8(image.pixels[i][c]);
    }
    try {
        if (ext == ".png") return writePng8(target, image.width, image.height, pixels.bytes);
        if (ext == ".ppm") return writePpm8(target, image.width, image.height, pixels.bytes);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
    std::string detail;
    if (!oiioCodec().write(path, target, pixels, isFloat, detail)) throw std::runtime_error(path + ": " + detail);
}

}  // namespace

std::vector<std::uint8_t> encodePng(const Image& image) {
    std::vector<std::uint8_t> rgb(image.pixels.size() * 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = quantize8(image.pixels[i][c]);
    return encodePng8(image.width, image.height, rgb);
}

void checkImageOutputPath(const std::string& path) {
    if (path.empty()) throw std::runtime_error("the output path is empty (-o FILE.png)");
    const std::string ext = lowerExtension(path);
    if (!isSupportedOutput(ext))
        throw std::runtime_error(path + ": unsupported output format '" + ext + "' (use .png, .exr, .jpg or .ppm)");
    checkOutputFolder(path, "an image file");
    // .exr and .jpg are written by the OpenImageIO module: a render must not end in "cannot load".
    if (ext != ".png" && ext != ".ppm") {
        try {
            oiioCodec();
        } catch (const std::runtime_error& e) {
            throw std::runtime_error(path + ": " + e.what());
        }
    }
}

void writeImage(const Image& image, const std::string& path, const ImageAttributes& attributes) {
    checkImageOutputPath(path);
    writeAtomically(path, [&](const std::string& temporary) { writeImageFile(image, path, temporary, attributes); });
}

namespace {

constexpr std::uintmax_t kMaxPixelsPerByte = 2048;

}  // namespace

Image readImage(const std::string& path, ImageAttributes* attributes, std::optional<std::size_t> limit) {
    const std::size_t maxPixels = limit ? *limit : static_cast<std::size_t>(inputLimits().readPixels);
    const std::string hint = limit ? "" : inputLimitHint("read-pixels");
    if (const std::string problem = exrHeaderProblem(path, maxPixels, hint); !problem.empty())
        throw std::runtime_error(path + ": " + problem);
    // Any other format is bounded by its file's size too: PNG's deflate expands at most 1032 times
    // and JPEG's flattest blocks about 700 times, so more than kMaxPixelsPerByte pixels a byte is a
    // forged header (a 69-byte PNG may claim 16000 x 16000: 3 GiB of floats).
    std::size_t cap = maxPixels;
    std::error_code ec;
    const std::uintmax_t fileBytes = std::filesystem::file_size(path, ec);
    if (!ec && !isExrFile(path)) cap = std::min<std::uintmax_t>(cap, fileBytes * kMaxPixelsPerByte);
    oiio::Pixels data;
    std::string detail;
    switch (oiioCodec().readFloats(path, cap, data, detail)) {
        case oiio::ReadResult::Ok: break;
        case oiio::ReadResult::Empty: throw std::runtime_error(path + ": the image has no pixels");
        case oiio::ReadResult::TooLarge:
            if (static_cast<std::size_t>(data.width) * static_cast<std::size_t>(data.height) <= maxPixels)
                throw std::runtime_error(path + ": the image claims " + std::to_string(data.width) + "x" + std::to_string(data.height) +
                                         " pixels in a " + std::to_string(fileBytes) + "-byte file: more than " +
                                         std::to_string(kMaxPixelsPerByte) + " a byte, which no PNG or JPEG compresses to");
            throw std::runtime_error(path + ": the image claims " + std::to_string(data.width) + "x" + std::to_string(data.height) +
                                     " pixels, more than the " + std::to_string(maxPixels) + " vkrt reads" + hint);
        case oiio::ReadResult::CannotDecode: throw std::runtime_error(path + ": read failed: " + detail);
        default: throw std::runtime_error(path + ": cannot read image: " + detail);
    }
    if (attributes) attributes->insert(data.attributes.begin(), data.attributes.end());
    const int channels = data.channels;
    Image image(data.width, data.height);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) image.pixels[i][c] = data.floats[i * channels + std::min(c, channels - 1)];
    return image;
}

std::size_t countNonFinite(const Image& image) {
    std::size_t n = 0;
    for (const glm::vec3& p : image.pixels)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) ++n;
    return n;
}

}  // namespace vkrt
