#include "exr_header_check.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <vector>

namespace vkrt {

namespace {

constexpr unsigned char kMagic[4] = {0x76, 0x2f, 0x31, 0x01};
// Version field flags (OpenEXR's file layout): single-part tiled, long names, multi-part.
constexpr std::uint32_t kTiled = 0x200, kLongNames = 0x400, kMultiPart = 0x1000;

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

std::uint32_t le32(const unsigned char* b) {
    return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
}

// The most a compression can expand its chunks, rounded up: deflate's limit is 1032 (ZIP, ZIPS,
// PXR24's 24-bit floats 4/3 of that), RLE's 64, B44's fixed 32/14 and B44A's flat blocks 32/3.
// PIZ's Huffman run codes and DWA's flat blocks have no such bound: 0, unchecked.
std::uint64_t maxExpansion(int compression) {
    switch (compression) {
        case 0: return 1;                 // none
        case 1: return 64;                // RLE
        case 2: case 3: return 1100;      // ZIPS, ZIP
        case 5: return 1400;              // PXR24
        case 6: case 7: return 11;        // B44, B44A
        default: return 0;                // PIZ, DWAA, DWAB, newer
    }
}

// Scan lines per chunk of each compression (OpenEXR's file layout); an unknown one counts as the
// largest, so the offset-table bound stays a lower bound.
std::uint64_t linesPerChunk(int compression) {
    switch (compression) {
        case 0: case 1: case 2: return 1;     // none, RLE, ZIPS
        case 3: case 5: return 16;            // ZIP, PXR24
        case 4: case 6: case 7: case 8: return 32;  // PIZ, B44, B44A, DWAA
        default: return 256;                  // DWAB and anything newer
    }
}

// OpenImageIO reads an OpenEXR file in blocks of 64 scan lines of the full width, whatever the
// image's height (a 4-row part claiming 2,752,518 columns made it allocate 8.4 GB: found by
// fuzz_merge_part). Width x channels is bounded so that such a block stays within 256 MiB: 2^18
// values a row, a 65536-wide RGBA image (vkrt renders at most 65536 wide).
constexpr std::uint64_t kMaxRowValues = std::uint64_t(1) << 18;

struct Part {
    bool hasWindow = false, hasTiles = false, hasChunkCount = false;
    std::uint64_t channels = 0;
    std::uint64_t pixelBytes = 0;  // the channels' stored sizes: 2 for half, 4 for float and uint
    std::int64_t x0 = 0, y0 = 0, x1 = -1, y1 = -1;
    std::uint32_t tileX = 0, tileY = 0;
    int compression = 0;
    std::uint64_t chunkCount = 0;
};

class Reader {
public:
    Reader(std::FILE* f, std::uint64_t size) : file_(f), size_(size) {}
    std::uint64_t offset() const { return offset_; }
    std::uint64_t left() const { return size_ - offset_; }
    bool byte(unsigned char& c) {
        const int got = std::fgetc(file_);
        if (got == EOF) return false;
        c = static_cast<unsigned char>(got);
        ++offset_;
        return true;
    }
    bool bytes(unsigned char* out, std::size_t n) {
        if (std::fread(out, 1, n, file_) != n) return false;
        offset_ += n;
        return true;
    }
    bool skip(std::uint64_t n) {
        if (n > left() || std::fseek(file_, static_cast<long>(offset_ + n), SEEK_SET) != 0) return false;
        offset_ += n;
        return true;
    }
    // A NUL-terminated name of at most maxLength characters; "" at the NUL that ends a header.
    bool name(std::string& out, std::size_t maxLength) {
        out.clear();
        for (unsigned char c = 0;;) {
            if (!byte(c)) return false;
            if (c == 0) return true;
            if (out.size() == maxLength) return false;
            out.push_back(static_cast<char>(c));
        }
    }

private:
    std::FILE* file_;
    std::uint64_t size_, offset_ = 0;
};

}  // namespace

bool isExrFile(const std::string& path) {
    File file(std::fopen(path.c_str(), "rb"), std::fclose);
    unsigned char magic[4] = {0, 0, 0, 0};
    return file && std::fread(magic, 1, 4, file.get()) == 4 && std::memcmp(magic, kMagic, 4) == 0;
}

std::string exrHeaderProblem(const std::string& path, std::uint64_t maxPixels, const std::string& limitHint) {
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) return "";  // the reader that follows says why it cannot read it
    File file(std::fopen(path.c_str(), "rb"), std::fclose);
    if (!file) return "";
    Reader in(file.get(), size);
    unsigned char head[8];
    if (!in.bytes(head, 8) || std::memcmp(head, kMagic, 4) != 0) return "";
    const std::uint32_t flags = le32(head + 4);
    const std::size_t maxName = (flags & kLongNames) ? 255 : 31;
    const bool multiPart = (flags & kMultiPart) != 0;

    std::vector<Part> parts;
    for (;;) {  // one header per part; a multi-part file ends its list with an empty header
        Part part;
        std::string name, type;
        int attributes = 0;
        for (;;) {
            if (!in.name(name, maxName)) return "a header attribute's name is unterminated or longer than " + std::to_string(maxName) + " characters";
            if (name.empty()) break;
            if (!in.name(type, maxName)) return "attribute '" + name + "' has an unterminated or overlong type name";
            unsigned char sizeBytes[4];
            if (!in.bytes(sizeBytes, 4)) return "attribute '" + name + "' is cut short";
            const std::int32_t claimed = static_cast<std::int32_t>(le32(sizeBytes));
            if (claimed < 0 || static_cast<std::uint64_t>(claimed) > in.left())
                return "attribute '" + name + "' claims " + std::to_string(claimed) + " bytes, more than the " +
                       std::to_string(in.left()) + " left in the " + std::to_string(size) + "-byte file";
            const std::uint64_t valueEnd = in.offset() + static_cast<std::uint64_t>(claimed);
            unsigned char v[16];
            if (name == "dataWindow" && type == "box2i" && claimed == 16 && in.bytes(v, 16)) {
                part.hasWindow = true;
                part.x0 = static_cast<std::int32_t>(le32(v));
                part.y0 = static_cast<std::int32_t>(le32(v + 4));
                part.x1 = static_cast<std::int32_t>(le32(v + 8));
                part.y1 = static_cast<std::int32_t>(le32(v + 12));
            } else if (name == "tiles" && type == "tiledesc" && claimed == 9 && in.bytes(v, 9)) {
                part.hasTiles = true;
                part.tileX = le32(v);
                part.tileY = le32(v + 4);
            } else if (name == "channels" && type == "chlist") {
                // Each channel: its name, then 16 bytes (type, pLinear, reserved, x and y sampling);
                // a NUL ends the list. Counted within the attribute's own bytes.
                std::string channel;
                for (std::uint64_t at = in.offset(); at < valueEnd; at = in.offset()) {
                    if (!in.name(channel, 255) || channel.empty()) break;
                    ++part.channels;
                    unsigned char rest[16];
                    if (in.offset() + 16 > valueEnd || !in.bytes(rest, 16)) break;
                    part.pixelBytes += le32(rest) == 1 ? 2 : 4;
                }
            } else if (name == "compression" && type == "compression" && claimed == 1 && in.bytes(v, 1)) {
                part.compression = v[0];
            } else if (name == "chunkCount" && type == "int" && claimed == 4 && in.bytes(v, 4)) {
                part.hasChunkCount = true;
                part.chunkCount = static_cast<std::int32_t>(le32(v)) < 0 ? UINT64_MAX : le32(v);
            }
            if (!in.skip(valueEnd - in.offset())) return "attribute '" + name + "' is cut short";
            ++attributes;
        }
        if (attributes == 0) {
            if (multiPart && !parts.empty()) break;
            return "an empty header";
        }
        parts.push_back(part);
        if (!multiPart) break;
    }

    std::uint64_t tableBytes = 0;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const Part& p = parts[i];
        const std::string which = parts.size() > 1 ? "part " + std::to_string(i) + ": " : "";
        if (!p.hasWindow) return which + "no dataWindow";
        if (p.x1 < p.x0 || p.y1 < p.y0)
            return which + "the data window " + std::to_string(p.x0) + "," + std::to_string(p.y0) + " .. " + std::to_string(p.x1) +
                   "," + std::to_string(p.y1) + " is empty";
        const std::uint64_t w = static_cast<std::uint64_t>(p.x1 - p.x0 + 1), h = static_cast<std::uint64_t>(p.y1 - p.y0 + 1);
        if (w * h > maxPixels)
            return which + "the image claims " + std::to_string(w) + "x" + std::to_string(h) + " pixels, more than the " +
                   std::to_string(maxPixels) + " vkrt reads" + limitHint;
        if (w * std::max<std::uint64_t>(p.channels, 1) > kMaxRowValues)
            return which + "rows of " + std::to_string(w) + " pixels x " + std::to_string(p.channels) + " channels: more than the " +
                   std::to_string(kMaxRowValues) + " values a row vkrt reads";
        // Each chunk has an 8-byte entry in the offset table that follows the headers: its least
        // possible number of chunks bounds what the table may hold.
        std::uint64_t chunks = 0;
        if (p.hasChunkCount) {
            chunks = p.chunkCount;
        } else if (p.hasTiles || (!multiPart && (flags & kTiled))) {
            if (p.tileX == 0 || p.tileY == 0) return which + "tiles of zero size";
            chunks = ((w + p.tileX - 1) / p.tileX) * ((h + p.tileY - 1) / p.tileY);
        } else {
            chunks = (h + linesPerChunk(p.compression) - 1) / linesPerChunk(p.compression);
        }
        if (chunks > in.left() / 8 || tableBytes + chunks * 8 > in.left())
            return which + "its " + std::to_string(chunks) + " chunks need an offset table larger than the " +
                   std::to_string(in.left()) + " bytes left in the " + std::to_string(size) + "-byte file";
        tableBytes += chunks * 8;
        // What the pixels take decoded cannot exceed what the compression can make of the file:
        // an 861-byte part claiming 24070 x 769 float pixels (222 MB) is forged.
        if (const std::uint64_t expansion = maxExpansion(p.compression);
            expansion > 0 && w * h * p.pixelBytes > expansion * static_cast<std::uint64_t>(size))
            return which + "the image claims " + std::to_string(w) + "x" + std::to_string(h) + " pixels of " +
                   std::to_string(p.pixelBytes) + " bytes in a " + std::to_string(size) + "-byte file: more than its compression (" +
                   std::to_string(p.compression) + ") can expand to";
    }
    return "";
}

}  // namespace vkrt
