// Loads libvkrt_oiio.so (oiio_codec.h) on first use, so that runs which read and write only what
// vkrt writes natively never load OpenImageIO.
#pragma once

#include "oiio_codec.h"

namespace vkrt {

// The module's table. Looked for at $VKRT_OIIO_MODULE when it is set (only there), else beside
// the running executable, then the folders above it (module_loader.h); throws std::runtime_error naming every
// place tried (and dlerror's reason).
const oiio::Codec& oiioCodec();

}  // namespace vkrt
