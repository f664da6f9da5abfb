// OpenEXR headers checked before OpenImageIO opens the file. OpenEXR 3.1 allocates what a header's
// fields claim before it reads the bytes behind them: an 875-byte file whose string attribute
// claims 1.6 GB made it zero-fill 1.6 GB (found by fuzz_merge_part), and a data window of 2^31
// rows makes it allocate an offset table of 16 GB. Every such claim is bounded by the file's
// size or by the pixel limit here, so a forged header costs nothing.
#pragma once

#include <cstdint>
#include <string>

namespace vkrt {

// True when the file starts with OpenEXR's magic number.
bool isExrFile(const std::string& path);

// For an OpenEXR file: "" when every attribute's size fits in the file, every part's data window
// is non-empty and holds at most maxPixels pixels, and each part's chunk offset table fits in the
// file; else what is wrong (without the path), with `limitHint` after the message about the pixel
// limit. Files of other formats give "".
std::string exrHeaderProblem(const std::string& path, std::uint64_t maxPixels, const std::string& limitHint = "");

}  // namespace vkrt
