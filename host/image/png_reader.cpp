#include "png_reader.h"

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include <png.h>

namespace vkrt {

namespace {

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

// libpng reports errors by longjmp to the setjmp in decode(); the message is kept here first.
void onError(png_structp png, png_const_charp message) {
    auto* detail = static_cast<std::string*>(png_get_error_ptr(png));
    *detail = message ? message : "libpng error";
    png_longjmp(png, 1);
}
void onWarning(png_structp, png_const_charp) {}  // e.g. a bad CRC in an ancillary chunk: read on, as OIIO does

// Everything that lives across the setjmp is owned by the caller (`out`, `rows`), so a longjmp
// out of libpng leaves no object of this frame half-built.
oiio::ReadResult decode(png_structp png, png_infop info, std::size_t maxTexels, oiio::Pixels& out,
                        std::vector<png_bytep>& rows, std::string& detail) {
    if (setjmp(png_jmpbuf(png))) return out.width > 0 && out.height > 0 ? oiio::ReadResult::CannotDecode : oiio::ReadResult::CannotOpen;
    png_read_info(png, info);
    const png_uint_32 width = png_get_image_width(png, info), height = png_get_image_height(png, info);
    const int colour = png_get_color_type(png, info);
    const int depth = png_get_bit_depth(png, info);
    out.width = static_cast<int>(width);
    out.height = static_cast<int>(height);
    if (width == 0 || height == 0) return oiio::ReadResult::Empty;
    // Allocated only after this check: a 69-byte file may claim 40000 x 40000.
    if (static_cast<std::size_t>(width) * height > maxTexels) return oiio::ReadResult::TooLarge;

    if (colour == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (colour == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
    if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
    if (depth == 16) png_set_scale_16(png);  // rounds, as OpenImageIO's conversion does
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    out.channels = png_get_channels(png, info);

    const std::size_t stride = static_cast<std::size_t>(width) * static_cast<std::size_t>(out.channels);
    out.bytes.resize(stride * height);
    rows.resize(height);
    for (png_uint_32 y = 0; y < height; ++y) rows[y] = out.bytes.data() + y * stride;
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);
    return oiio::ReadResult::Ok;
}

}  // namespace

bool isPngFile(const std::string& path) {
    const File file(std::fopen(path.c_str(), "rb"), std::fclose);
    png_byte signature[8];
    return file && std::fread(signature, 1, sizeof signature, file.get()) == sizeof signature &&
           png_sig_cmp(signature, 0, sizeof signature) == 0;
}

oiio::ReadResult readPng8(const std::string& path, std::size_t maxTexels, oiio::Pixels& out, std::string& detail) {
    out = {};
    const File file(std::fopen(path.c_str(), "rb"), std::fclose);
    if (!file) {
        detail = std::string("cannot open: ") + std::strerror(errno);
        return oiio::ReadResult::CannotOpen;
    }
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &detail, onError, onWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info) {
        png_destroy_read_struct(png ? &png : nullptr, nullptr, nullptr);
        detail = "libpng cannot allocate its reader";
        return oiio::ReadResult::CannotOpen;
    }
    png_init_io(png, file.get());
    std::vector<png_bytep> rows;
    const oiio::ReadResult result = decode(png, info, maxTexels, out, rows, detail);
    png_destroy_read_struct(&png, &info, nullptr);
    if (result != oiio::ReadResult::Ok && result != oiio::ReadResult::TooLarge) out.bytes.clear();
    return result;
}

}  // namespace vkrt
