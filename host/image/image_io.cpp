#include "image.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include "output_file.h"

namespace vkrt {

namespace {

bool isSupportedOutput(const std::string& ext) {
    return ext == ".exr" || ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".ppm";
}

// Writes the file at `target` (a temporary name) in the format of `path`'s extension.
void writeImageFile(const Image& image, const std::string& path, const std::string& target) {
    const bool isFloat = lowerExtension(path) == ".exr";
    auto out = OIIO::ImageOutput::create(path);  // the format comes from the final name
    if (!out) throw std::runtime_error(path + ": cannot create image writer: " + OIIO::geterror());
    OIIO::ImageSpec spec(image.width, image.height, 3, isFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    if (!out->open(target, spec)) throw std::runtime_error(path + ": cannot open for writing: " + out->geterror());

    bool ok = false;
    if (isFloat) {
        ok = out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
    } else {
        std::vector<std::uint8_t> bytes(image.pixels.size() * 3);
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c) bytes[i * 3 + c] = quantize8(image.pixels[i][c]);
        ok = out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
    }
    if (!ok) throw std::runtime_error(path + ": write failed: " + out->geterror());
    if (!out->close()) throw std::runtime_error(path + ": close failed: " + out->geterror());
}

}  // namespace

void checkImageOutputPath(const std::string& path) {
    if (path.empty()) throw std::runtime_error("the output path is empty (-o FILE.png)");
    const std::string ext = lowerExtension(path);
    if (!isSupportedOutput(ext))
        throw std::runtime_error(path + ": unsupported output format '" + ext + "' (use .png, .exr, .jpg or .ppm)");
    checkOutputFolder(path, "an image file");
}

void writeImage(const Image& image, const std::string& path) {
    checkImageOutputPath(path);
    writeAtomically(path, [&](const std::string& temporary) { writeImageFile(image, path, temporary); });
}

Image readImage(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error(path + ": cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    const int channels = spec.nchannels;
    std::vector<float> data(static_cast<std::size_t>(spec.width) * spec.height * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, data.data()))
        throw std::runtime_error(path + ": read failed: " + in->geterror());
    Image image(spec.width, spec.height);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) image.pixels[i][c] = data[i * channels + std::min(c, channels - 1)];
    return image;
}

std::size_t countNonFinite(const Image& image) {
    std::size_t n = 0;
    for (const glm::vec3& p : image.pixels)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) ++n;
    return n;
}

}  // namespace vkrt
