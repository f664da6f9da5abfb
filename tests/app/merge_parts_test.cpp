// vkrt merge against forged and broken parts (issue 38, item 2): each is refused with a message
// that names the file and what is wrong, quickly and without allocating what the file claims.
// The honest round trip (parts merge into the whole image's bytes) is tests/app/parts_and_merge.py.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <iterator>

#include <gtest/gtest.h>

#include "image.h"
#include "image_parts.h"

namespace vkrt {
namespace {

std::string scratch(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::current_path() / "test_artifacts" / "merge_parts";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

const std::string kRender = "scene s.xml; 8x6; rpp 1; device cpu";

// An EXR part of an 8x6 render with the attributes given (vkrt --part writes these three).
std::string writePart(const std::string& name, const ImageAttributes& attributes, float value = 0.5f) {
    Image image(8, 6);
    for (glm::vec3& p : image.pixels) p = glm::vec3(value);
    const std::string path = scratch(name);
    writeImage(image, path, attributes);
    return path;
}

std::string mergeError(const std::vector<std::string>& paths) {
    try {
        mergeParts(paths);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

TEST(MergeRefuses, APartClaimingMorePartsThanRowsAtOnce) {
    const std::string forged = writePart("forged.exr", {{"vkrt:part", "1/2000000000"}, {"vkrt:rows", "0 0"}, {"vkrt:render", kRender}});
    const auto start = std::chrono::steady_clock::now();
    const std::string error = mergeError({forged});
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
    EXPECT_NE(error.find("1/2000000000 of a 6-row image"), std::string::npos) << error;
}

TEST(MergeRefuses, AShortListOfMissingParts) {
    const std::string first = writePart("first.exr", {{"vkrt:part", "1/6"}, {"vkrt:rows", "0 1"}, {"vkrt:render", kRender}});
    const std::string error = mergeError({first});
    EXPECT_NE(error.find("part(s) 2, 3, 4, 5, 6 of 6 missing"), std::string::npos) << error;
    // 30 parts of a 30-row image, one given: the first 20 missing are named, the rest counted.
    Image tall(2, 30);
    const std::string one = scratch("one_of_30.exr");
    writeImage(tall, one, {{"vkrt:part", "1/30"}, {"vkrt:rows", "0 1"}, {"vkrt:render", kRender}});
    const std::string cut = mergeError({one});
    EXPECT_NE(cut.find("part(s) 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21 and 9 more of 30 missing"),
              std::string::npos) << cut;
}

TEST(MergeRefuses, APartWithoutItsRenderAttributeNamingIt) {
    const std::string part = writePart("no_render.exr", {{"vkrt:part", "1/1"}, {"vkrt:rows", "0 6"}});
    const std::string error = mergeError({part});
    EXPECT_NE(error.find("no_render.exr: not a part of a render (no vkrt:render"), std::string::npos) << error;
    EXPECT_EQ(error.find("map::at"), std::string::npos) << error;
}

TEST(MergeRefuses, NanPixels) {
    const std::string part = writePart("nan.exr", {{"vkrt:part", "1/1"}, {"vkrt:rows", "0 6"}, {"vkrt:render", kRender}}, NAN);
    const std::string error = mergeError({part});
    EXPECT_NE(error.find("nan.exr: 48 pixel(s) are NaN or Inf"), std::string::npos) << error;
    const std::string fine = writePart("fine.exr", {{"vkrt:part", "1/1"}, {"vkrt:rows", "0 6"}, {"vkrt:render", kRender}});
    EXPECT_EQ(mergeParts({fine}).at(3, 2), glm::vec3(0.5f));  // the same file, finite: merged
}

TEST(MergeRefuses, FilesThatAreNotExrBeforeDecodingThem) {
    // A PNG header claiming 40000 x 40000 pixels (IHDR patched; the file is 69 bytes long).
    const std::string small = scratch("tiny.png");
    writeImage(Image(1, 1), small);
    std::string bytes;
    {
        std::ifstream in(small, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    ASSERT_GT(bytes.size(), 24u);
    const unsigned char claim[8] = {0, 0, 0x9c, 0x40, 0, 0, 0x9c, 0x40};  // 40000, 40000 big-endian at offset 16
    for (int i = 0; i < 8; ++i) bytes[16 + i] = static_cast<char>(claim[i]);
    const std::string bomb = scratch("bomb.png");
    std::ofstream(bomb, std::ios::binary) << bytes;
    EXPECT_NE(mergeError({bomb}).find("bomb.png: not an OpenEXR file"), std::string::npos) << mergeError({bomb});
    // A device that never ends, and a folder: refused before anything is read.
    EXPECT_NE(mergeError({"/dev/zero"}).find("/dev/zero: not a regular file"), std::string::npos) << mergeError({"/dev/zero"});
    EXPECT_NE(mergeError({scratch("")}).find("not a regular file"), std::string::npos);
}

// The same header check guards every image read: a file that claims more pixels than
// the limit given is refused from its header, naming its size.
TEST(ReadImage, RefusesAClaimedSizeBeyondTheCapBeforeAllocating) {
    const std::string path = writePart("capped.exr", {});
    try {
        readImage(path, nullptr, 47);  // 8 x 6 = 48 pixels
        FAIL() << "read past the cap";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("claims 8x6 pixels, more than the 47"), std::string::npos) << e.what();
    }
    EXPECT_EQ(readImage(path, nullptr, 48).width, 8);
}

// The bytes of a file, with `patch` written over them right after the first `after`.
std::string patched(const std::string& source, const std::string& name, const std::string& after, const std::string& patch) {
    std::ifstream in(source, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t at = bytes.find(after);
    EXPECT_NE(at, std::string::npos) << after;
    bytes.replace(at + after.size(), patch.size(), patch);
    const std::string path = scratch(name);
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

std::string le32(std::uint32_t v) { return {char(v), char(v >> 8), char(v >> 16), char(v >> 24)}; }

std::string readError(const std::string& path) {
    const auto start = std::chrono::steady_clock::now();
    std::string error;
    try {
        readImage(path);
    } catch (const std::runtime_error& e) {
        error = e.what();
    }
    // OpenEXR would zero-fill what the header claims (1.6 GB: 6-15 s) before failing.
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0) << path;
    return error;
}

// A PNG is bounded by its file's size too: deflate expands at most 1032 times, so a 69-byte
// file claiming 16000 x 16000 (within the pixel limit: 3 GiB of floats) is a forged header.
TEST(ReadImage, APngClaimingFarMorePixelsThanItsBytesCanHoldIsRefused) {
    const std::string path = scratch("flat.png");
    Image flat(250, 250);
    for (glm::vec3& p : flat.pixels) p = glm::vec3(0.5f);
    writeImage(flat, path);  // a flat image: the most compressible case, which must still be read
    EXPECT_EQ(readImage(path).width, 250);
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const unsigned char claim[8] = {0, 0, 0x3e, 0x80, 0, 0, 0x3e, 0x80};  // 16000, 16000 big-endian at offset 16
    for (int i = 0; i < 8; ++i) bytes[16 + i] = static_cast<char>(claim[i]);
    // The IHDR chunk's CRC (over its type and 13 data bytes, offsets 12-28) made right again, so
    // that the decoder reads the forged size instead of refusing a damaged chunk.
    std::uint32_t crc = 0xffffffffu;
    for (int i = 12; i < 29; ++i) {
        crc ^= static_cast<unsigned char>(bytes[i]);
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    crc ^= 0xffffffffu;
    for (int i = 0; i < 4; ++i) bytes[29 + i] = static_cast<char>(crc >> (24 - 8 * i));
    const std::string bomb = scratch("bomb16k.png");
    std::ofstream(bomb, std::ios::binary) << bytes;
    const std::string error = readError(bomb);
    EXPECT_NE(error.find("claims 16000x16000 pixels in a " + std::to_string(bytes.size()) + "-byte file: more than 2048 a byte"),
              std::string::npos)
        << error;
}

// OpenEXR allocates what a header claims before reading it (fuzz_merge_part found an 875-byte
// part whose string attribute claimed 1.6 GB: 15 s of zero-filling under the sanitizers). Each
// claim is bounded by the file's size before OpenImageIO opens it (exr_header_check.h).
TEST(ReadImage, AnEXRHeaderClaimingMoreThanTheFileHoldsIsRefusedFromItsHeader) {
    const std::string honest = writePart("honest.exr", {{"vkrt:part", "1/1"}, {"vkrt:rows", "0 6"}, {"vkrt:render", kRender}});
    EXPECT_EQ(readImage(honest).width, 8);
    const std::string attribute = patched(honest, "attribute.exr", std::string("vkrt:render\0string\0", 19), le32(0x63610000));
    EXPECT_NE(readError(attribute).find("attribute.exr: attribute 'vkrt:render' claims 1667301376 bytes, more than the"),
              std::string::npos)
        << readError(attribute);
    EXPECT_NE(mergeError({attribute}).find("claims 1667301376 bytes"), std::string::npos) << mergeError({attribute});
    // 100000 x 100000 pixels: past the read-pixels limit, with the flag that raises it named.
    const std::string window = std::string("dataWindow\0box2i\0", 17) + le32(16);
    const std::string wide = patched(honest, "wide.exr", window, le32(0) + le32(0) + le32(99999) + le32(99999));
    EXPECT_NE(readError(wide).find("claims 100000x100000 pixels, more than the 268435456 vkrt reads (--input-limit read-pixels=N"),
              std::string::npos)
        << readError(wide);
    // One column of 2^27 rows is within the pixel limit, but its chunks' offset table (8 bytes a
    // chunk) cannot fit in a file of a few hundred bytes: OpenEXR would allocate it first.
    const std::string tall = patched(honest, "tall.exr", window, le32(0) + le32(0) + le32(0) + le32((1u << 27) - 1));
    EXPECT_NE(readError(tall).find("chunks need an offset table larger than the"), std::string::npos) << readError(tall);
    // A 6-row part 2,752,518 pixels wide: within the pixel limit, but OpenImageIO reads 64 rows of the
    // full width at a time (8.4 GB; found by fuzz_merge_part).
    const std::string wideRows = patched(honest, "wide_rows.exr", window, le32(0) + le32(0) + le32(2752517) + le32(5));
    EXPECT_NE(readError(wideRows).find("rows of 2752518 pixels x 3 channels: more than the 262144 values a row"), std::string::npos)
        << readError(wideRows);
    // 24070 x 48 float pixels (14 MB) in a file of a few hundred bytes: within every limit above,
    // but more than ZIP can expand to (fuzz_merge_part's 861-byte 24070 x 769 part took 1.3 s and
    // 346 MB before it was refused).
    const std::string dense = patched(honest, "dense.exr", window, le32(0) + le32(0) + le32(24069) + le32(47));
    EXPECT_NE(readError(dense).find("the image claims 24070x48 pixels of 12 bytes in a"), std::string::npos) << readError(dense);
    EXPECT_NE(readError(dense).find("more than its compression (3) can expand to"), std::string::npos) << readError(dense);
    // A negative-size and an empty window.
    const std::string empty = patched(honest, "empty.exr", window, le32(5) + le32(0) + le32(4) + le32(5));
    EXPECT_NE(readError(empty).find("the data window 5,0 .. 4,5 is empty"), std::string::npos) << readError(empty);
}

}  // namespace
}  // namespace vkrt
