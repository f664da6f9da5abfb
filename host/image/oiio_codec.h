// The OpenImageIO side of vkrt's image I/O, built as a module of its own (libvkrt_oiio.so) and
// loaded only when a run needs it (codec_module.h): linking OpenImageIO pulls ~250 shared libraries
// into the process, whose symbol lookup is most of a small render's process time (docs/STARTUP.md).
// What every render writes (PNG, PPM) is written without it (native_formats.h).
//
// The interface is a table of functions behind one extern "C" entry point; both sides are built
// from this header by the same compiler, so C++ types cross it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace vkrt::oiio {

// Bump when the table changes: the loader refuses a module of another version.
inline constexpr int kCodecVersion = 3;

struct Pixels {
    int width = 0, height = 0, channels = 0;
    std::vector<float> floats;         // readFloats, and write when isFloat
    std::vector<std::uint8_t> bytes;   // readBytes, and write otherwise
    // String metadata named "vkrt:..." (a --part's rows): written into formats that keep it (EXR),
    // and read back from them by readFloats.
    std::vector<std::pair<std::string, std::string>> attributes;
};

enum class ReadResult { Ok, CannotOpen, Empty, TooLarge, CannotDecode };

struct Codec {
    int version;
    // 8-bit values as stored (alpha not premultiplied), every channel; the size is checked against
    // maxTexels from the header, before anything is allocated. `detail`: the library's message.
    ReadResult (*readBytes)(const std::string& path, std::size_t maxTexels, Pixels& out, std::string& detail);
    // Float values, every channel (8-bit files as value / 255); the size checked against maxTexels
    // from the header, as readBytes does.
    ReadResult (*readFloats)(const std::string& path, std::size_t maxTexels, Pixels& out, std::string& detail);
    // Writes RGB `pixels` (floats when isFloat, else bytes) to `target` in the format named by
    // `formatPath`'s extension; false with `detail` on failure.
    bool (*write)(const std::string& formatPath, const std::string& target, const Pixels& pixels, bool isFloat,
                  std::string& detail);
};

}  // namespace vkrt::oiio

extern "C" const vkrt::oiio::Codec* vkrt_oiio_codec();
