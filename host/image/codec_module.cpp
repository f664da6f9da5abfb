#include "codec_module.h"

#include <dlfcn.h>

#include "module_loader.h"

namespace vkrt {

const oiio::Codec& oiioCodec() {
    return moduleTable<oiio::Codec>({"libvkrt_oiio.so", "VKRT_OIIO_MODULE", "vkrt_oiio_codec", RTLD_LOCAL},
                                    oiio::kCodecVersion, "OpenImageIO image I/O: reading images, writing .exr and .jpg");
}

}  // namespace vkrt
