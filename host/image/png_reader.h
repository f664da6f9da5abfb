// PNG files read natively through libpng, so that textures and environment maps (every image of
// the course is a PNG) never depend on the OpenImageIO module: a bundle without it, or a machine
// where it cannot load, still renders them. Other formats go through OpenImageIO (oiio_codec.h).
#pragma once

#include <cstddef>
#include <string>

#include "oiio_codec.h"

namespace vkrt {

// True when the file starts with PNG's 8-byte signature (whatever its name says).
bool isPngFile(const std::string& path);

// The same bytes OpenImageIO's readBytes gives (tests/image/png_reader_test.cpp compares them on
// every PNG of the course): every channel the file stores (grey, grey+alpha, RGB, RGBA; a palette
// expands to RGB, or RGBA with a tRNS chunk), 16-bit samples rounded to 8 bits (v * 255 / 65535),
// no gamma or colour-space change. The size is checked against maxTexels from the header, before
// anything is allocated.
oiio::ReadResult readPng8(const std::string& path, std::size_t maxTexels, oiio::Pixels& out, std::string& detail);

}  // namespace vkrt
