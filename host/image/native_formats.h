// The 8-bit formats every render can write without OpenImageIO: PNG through libpng's simplified
// API, and binary PPM (P6) by hand (a header line and the bytes). What a small render writes then
// costs no OpenImageIO load (oiio_codec.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vkrt {

// `rgb`: width * height * 3 bytes, row 0 at the top. Throw std::runtime_error with the library's
// reason (the caller names the file).
void writePng8(const std::string& target, int width, int height, const std::vector<std::uint8_t>& rgb);
std::vector<std::uint8_t> encodePng8(int width, int height, const std::vector<std::uint8_t>& rgb);
void writePpm8(const std::string& target, int width, int height, const std::vector<std::uint8_t>& rgb);

}  // namespace vkrt
