#include "codec_module.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include <dlfcn.h>

namespace vkrt {

namespace {

const oiio::Codec* load() {
    std::vector<std::string> candidates;
    std::error_code ec;
    if (const char* env = std::getenv("VKRT_OIIO_MODULE"); env && *env) {
        candidates.push_back(env);  // the user's choice, and only it
    } else {
        const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
        if (!ec) candidates.push_back((exe.parent_path() / "libvkrt_oiio.so").string());
#ifdef VKRT_OIIO_MODULE_PATH
        candidates.push_back(VKRT_OIIO_MODULE_PATH);  // the build tree's (tests run from their own folders)
#endif
    }
    std::string tried;
    for (std::size_t k = 0; k < candidates.size(); ++k) {
        const std::string& path = candidates[k];
        if (std::find(candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(k), path) != candidates.begin() + static_cast<std::ptrdiff_t>(k))
            continue;  // the build tree is also the executable's folder
        if (!std::filesystem::exists(path, ec)) {
            tried += "\n  " + path + ": no such file";
            continue;
        }
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            tried += "\n  " + path + ": " + dlerror();
            continue;
        }
        using Entry = const oiio::Codec* (*)();
        const auto entry = reinterpret_cast<Entry>(dlsym(handle, "vkrt_oiio_codec"));
        const oiio::Codec* codec = entry ? entry() : nullptr;
        if (codec && codec->version == oiio::kCodecVersion) return codec;  // kept loaded for the process
        tried += "\n  " + path + (codec ? ": codec version " + std::to_string(codec->version) + ", expected " +
                                              std::to_string(oiio::kCodecVersion)
                                        : ": no vkrt_oiio_codec entry point");
        dlclose(handle);
    }
    throw std::runtime_error("cannot load libvkrt_oiio.so (OpenImageIO image I/O: reading images, writing .exr and .jpg); "
                             "tried:" + tried);
}

}  // namespace

const oiio::Codec& oiioCodec() {
    static std::once_flag once;
    static const oiio::Codec* codec = nullptr;
    static std::string failure;
    std::call_once(once, [] {
        try {
            codec = load();
        } catch (const std::exception& e) {
            failure = e.what();
        }
    });
    if (!codec) throw std::runtime_error(failure);
    return *codec;
}

}  // namespace vkrt
