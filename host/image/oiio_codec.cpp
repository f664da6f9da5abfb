// libvkrt_oiio.so: oiio_codec.h's table, implemented with OpenImageIO.
#include "oiio_codec.h"

#include <OpenImageIO/imageio.h>

namespace vkrt::oiio {
namespace {

ReadResult open(const std::string& path, bool unassociatedAlpha, std::unique_ptr<OIIO::ImageInput>& input, std::string& detail) {
    OIIO::ImageSpec config;
    // Texels as stored: OpenImageIO would otherwise premultiply colour by alpha on reading.
    if (unassociatedAlpha) config.attribute("oiio:UnassociatedAlpha", 1);
    input = OIIO::ImageInput::open(path, &config);
    if (!input) {
        detail = OIIO::geterror();
        return ReadResult::CannotOpen;
    }
    const OIIO::ImageSpec& spec = input->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) return ReadResult::Empty;
    return ReadResult::Ok;
}

// The channels read: the first four (RGBA, in OpenImageIO's order) at most, so that a header that
// claims a thousand channels costs no more than a four-channel image of its size.
int kept(const OIIO::ImageSpec& spec) { return spec.nchannels < 4 ? spec.nchannels : 4; }

ReadResult readBytes(const std::string& path, std::size_t maxTexels, Pixels& out, std::string& detail) {
    std::unique_ptr<OIIO::ImageInput> input;
    if (const ReadResult r = open(path, true, input, detail); r != ReadResult::Ok) return r;
    const OIIO::ImageSpec& spec = input->spec();
    out.width = spec.width;
    out.height = spec.height;
    out.channels = kept(spec);
    const std::size_t texels = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height);
    if (texels > maxTexels) return ReadResult::TooLarge;
    out.bytes.resize(texels * static_cast<std::size_t>(out.channels));
    if (!input->read_image(0, 0, 0, out.channels, OIIO::TypeDesc::UINT8, out.bytes.data())) {
        detail = input->geterror();
        return ReadResult::CannotDecode;
    }
    return ReadResult::Ok;
}

ReadResult readFloats(const std::string& path, std::size_t maxTexels, Pixels& out, std::string& detail) {
    std::unique_ptr<OIIO::ImageInput> input;
    if (const ReadResult r = open(path, false, input, detail); r != ReadResult::Ok) return r;
    const OIIO::ImageSpec& spec = input->spec();
    out.width = spec.width;
    out.height = spec.height;
    out.channels = kept(spec);
    if (static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height) > maxTexels) return ReadResult::TooLarge;
    for (const OIIO::ParamValue& p : spec.extra_attribs)
        if (p.name().string().rfind("vkrt:", 0) == 0 && p.type() == OIIO::TypeDesc::STRING)
            out.attributes.emplace_back(p.name().string(), p.get_string());
    out.floats.resize(static_cast<std::size_t>(spec.width) * spec.height * out.channels);
    if (!input->read_image(0, 0, 0, out.channels, OIIO::TypeDesc::FLOAT, out.floats.data())) {
        detail = input->geterror();
        return ReadResult::CannotDecode;
    }
    return ReadResult::Ok;
}

bool write(const std::string& formatPath, const std::string& target, const Pixels& pixels, bool isFloat, std::string& detail) {
    auto out = OIIO::ImageOutput::create(formatPath);  // the format comes from the final name
    if (!out) {
        detail = "cannot create image writer: " + OIIO::geterror();
        return false;
    }
    OIIO::ImageSpec spec(pixels.width, pixels.height, 3, isFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    // The same image gives the same bytes: OpenEXR's writer would stamp the current time (capDate).
    spec.attribute("DateTime", "");
    for (const auto& [name, value] : pixels.attributes) spec.attribute(name, value);
    if (!out->open(target, spec)) {
        detail = "cannot open for writing: " + out->geterror();
        return false;
    }
    const bool ok = isFloat ? out->write_image(OIIO::TypeDesc::FLOAT, pixels.floats.data())
                            : out->write_image(OIIO::TypeDesc::UINT8, pixels.bytes.data());
    if (!ok) {
        detail = "write failed: " + out->geterror();
        return false;
    }
    if (!out->close()) {
        detail = "close failed: " + out->geterror();
        return false;
    }
    return true;
}

constexpr Codec kCodec{kCodecVersion, readBytes, readFloats, write};

}  // namespace
}  // namespace vkrt::oiio

extern "C" const vkrt::oiio::Codec* vkrt_oiio_codec() { return &vkrt::oiio::kCodec; }
