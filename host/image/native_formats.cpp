#include "native_formats.h"

#include <cstdio>
#include <memory>
#include <stdexcept>

#include <png.h>

namespace vkrt {

void writePng8(const std::string& target, int width, int height, const std::vector<std::uint8_t>& rgb) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(width);
    image.height = static_cast<png_uint_32>(height);
    image.format = PNG_FORMAT_RGB;
    if (!png_image_write_to_file(&image, target.c_str(), 0, rgb.data(), 0, nullptr)) {
        const std::string reason = image.message;
        png_image_free(&image);
        throw std::runtime_error("write failed: " + reason);
    }
}

std::vector<std::uint8_t> encodePng8(int width, int height, const std::vector<std::uint8_t>& rgb) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(width);
    image.height = static_cast<png_uint_32>(height);
    image.format = PNG_FORMAT_RGB;
    png_alloc_size_t size = 0;  // first the size, then the bytes
    if (png_image_write_to_memory(&image, nullptr, &size, 0, rgb.data(), 0, nullptr)) {
        std::vector<std::uint8_t> bytes(size);
        if (png_image_write_to_memory(&image, bytes.data(), &size, 0, rgb.data(), 0, nullptr)) {
            bytes.resize(size);
            return bytes;
        }
    }
    const std::string reason = image.message;
    png_image_free(&image);
    throw std::runtime_error("PNG encoding failed: " + reason);
}

void writePpm8(const std::string& target, int width, int height, const std::vector<std::uint8_t>& rgb) {
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(target.c_str(), "wb"), std::fclose);
    if (!file) throw std::runtime_error("cannot open for writing");
    const bool ok = std::fprintf(file.get(), "P6\n%d %d\n255\n", width, height) > 0 &&
                    std::fwrite(rgb.data(), 1, rgb.size(), file.get()) == rgb.size() && std::fflush(file.get()) == 0;
    if (!ok) throw std::runtime_error("write failed");
}

}  // namespace vkrt
