#include "codec_module.h"

#include <mutex>
#include <stdexcept>
#include <string>

#include <dlfcn.h>

#include "module_loader.h"

namespace vkrt {

const oiio::Codec& oiioCodec() {
    static std::once_flag once;
    static const oiio::Codec* codec = nullptr;
    static std::string failure;
    std::call_once(once, [] {
        try {
            ModuleSearch search{"libvkrt_oiio.so", "VKRT_OIIO_MODULE", VKRT_OIIO_MODULE_PATH, "vkrt_oiio_codec", RTLD_LOCAL};
            codec = static_cast<const oiio::Codec*>(loadModule(
                search,
                [](void* entry, const void*& table) {
                    const oiio::Codec* found = reinterpret_cast<decltype(&vkrt_oiio_codec)>(entry)();
                    if (!found) return std::string("no codec table");
                    if (found->version != oiio::kCodecVersion)
                        return "codec version " + std::to_string(found->version) + ", expected " + std::to_string(oiio::kCodecVersion);
                    table = found;
                    return std::string();
                },
                "OpenImageIO image I/O: reading images, writing .exr and .jpg"));
        } catch (const std::exception& e) {
            failure = e.what();
        }
    });
    if (!codec) throw std::runtime_error(failure);
    return *codec;
}

}  // namespace vkrt
