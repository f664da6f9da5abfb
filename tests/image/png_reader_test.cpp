// The native PNG reader (host/image/png_reader.h) must give the bytes OpenImageIO gives, since a
// texture or environment map renders from them and a bundle without the OpenImageIO module must
// render the build's image: every PNG of the course's two corpora, and small files in the layouts
// the corpora do not use (grey, grey+alpha, palette with transparency, 16-bit, interlaced).
#include <png.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "codec_module.h"
#include "png_reader.h"
#include "test_paths.h"

namespace vkrt {
namespace {

constexpr std::size_t kNoLimit = std::size_t(1) << 30;

oiio::Pixels readWithOiio(const std::string& path) {
    oiio::Pixels pixels;
    std::string detail;
    EXPECT_EQ(oiioCodec().readBytes(path, kNoLimit, pixels, detail), oiio::ReadResult::Ok) << path << ": " << detail;
    return pixels;
}

oiio::Pixels readNatively(const std::string& path) {
    oiio::Pixels pixels;
    std::string detail;
    EXPECT_TRUE(isPngFile(path)) << path;
    EXPECT_EQ(readPng8(path, kNoLimit, pixels, detail), oiio::ReadResult::Ok) << path << ": " << detail;
    return pixels;
}

void expectSameBytes(const std::string& path) {
    const oiio::Pixels a = readNatively(path), b = readWithOiio(path);
    EXPECT_EQ(a.width, b.width) << path;
    EXPECT_EQ(a.height, b.height) << path;
    EXPECT_EQ(a.channels, b.channels) << path;
    ASSERT_EQ(a.bytes.size(), b.bytes.size()) << path;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.bytes.size(); ++i) differing += a.bytes[i] != b.bytes[i];
    EXPECT_EQ(differing, 0u) << path;
}

TEST(PngReader, GivesOpenImageIosBytesForEveryCoursePng) {
    VKRT_SKIP_WITHOUT(test::upstreamDir());
    VKRT_SKIP_WITHOUT(test::jsonSceneDir());
    int files = 0;
    for (const std::string& root : {test::upstreamDir(), test::jsonSceneDir()})
        for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
            if (entry.path().extension() != ".png") continue;
            expectSameBytes(entry.path().string());
            ++files;
        }
    EXPECT_GE(files, 50);  // 52 PNGs when this was written: textures, env-map faces, reference renders
}

// A PNG of `colour` type and `depth` bits, written with libpng's full API (the simplified writer
// cannot make palettes with tRNS or 16-bit files without a gamma chunk).
std::string writeTestPng(const std::string& name, int colour, int depth, bool interlaced) {
    const std::string path = test::artifactDir() + "/png_reader_" + name + ".png";
    constexpr int width = 7, height = 5;
    FILE* file = std::fopen(path.c_str(), "wb");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, file);
    png_set_IHDR(png, info, width, height, depth, colour, interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    int samples = 1;
    if (colour == PNG_COLOR_TYPE_PALETTE) {
        png_color palette[4] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {10, 20, 30}};
        png_set_PLTE(png, info, palette, 4);
        png_byte alpha[3] = {0, 128, 255};
        png_set_tRNS(png, info, alpha, 3, nullptr);
    } else {
        samples = colour == PNG_COLOR_TYPE_GRAY ? 1 : colour == PNG_COLOR_TYPE_GRAY_ALPHA ? 2 : colour == PNG_COLOR_TYPE_RGB ? 3 : 4;
    }
    png_write_info(png, info);
    const int bytesPerSample = depth == 16 ? 2 : 1;
    std::vector<std::vector<png_byte>> rows(height, std::vector<png_byte>(width * samples * bytesPerSample));
    std::uint32_t state = 12345u;
    for (auto& row : rows)
        for (png_byte& b : row) {
            state = state * 1664525u + 1013904223u;
            b = static_cast<png_byte>(state >> 24);
            if (colour == PNG_COLOR_TYPE_PALETTE) b &= 3;
        }
    std::vector<png_bytep> pointers;
    for (auto& row : rows) pointers.push_back(row.data());
    png_write_image(png, pointers.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
    return path;
}

TEST(PngReader, GivesOpenImageIosBytesForLayoutsTheCourseDoesNotUse) {
    expectSameBytes(writeTestPng("grey8", PNG_COLOR_TYPE_GRAY, 8, false));
    expectSameBytes(writeTestPng("grey_alpha8", PNG_COLOR_TYPE_GRAY_ALPHA, 8, false));
    expectSameBytes(writeTestPng("palette_trns", PNG_COLOR_TYPE_PALETTE, 8, false));
    expectSameBytes(writeTestPng("rgb16", PNG_COLOR_TYPE_RGB, 16, false));
    expectSameBytes(writeTestPng("rgba16_interlaced", PNG_COLOR_TYPE_RGBA, 16, true));
    expectSameBytes(writeTestPng("rgb8_interlaced", PNG_COLOR_TYPE_RGB, 8, true));
}

TEST(PngReader, RefusesAClaimedSizeBeforeAllocatingAndNamesBrokenFiles) {
    const std::string path = writeTestPng("size_check", PNG_COLOR_TYPE_RGB, 8, false);  // 7 x 5
    oiio::Pixels pixels;
    std::string detail;
    EXPECT_EQ(readPng8(path, 34, pixels, detail), oiio::ReadResult::TooLarge);
    EXPECT_EQ(pixels.width, 7);
    EXPECT_TRUE(pixels.bytes.empty());

    // Cut after the header: the reader says why instead of returning garbage.
    const std::string cut = test::artifactDir() + "/png_reader_cut.png";
    std::filesystem::copy_file(path, cut, std::filesystem::copy_options::overwrite_existing);
    std::filesystem::resize_file(cut, 40);
    EXPECT_TRUE(isPngFile(cut));
    EXPECT_NE(readPng8(cut, kNoLimit, pixels, detail), oiio::ReadResult::Ok);
    EXPECT_FALSE(detail.empty());

    EXPECT_EQ(readPng8(test::artifactDir() + "/no_such.png", kNoLimit, pixels, detail), oiio::ReadResult::CannotOpen);
    EXPECT_FALSE(isPngFile(test::sourceDir() + "/README.md"));
}

}  // namespace
}  // namespace vkrt
