// libFuzzer target: texture images (OpenImageIO behind loadTextureImage, with its size cap).
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_input.h"
#include "texture_loading.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string error;
    (void)vkrt::loadTextureImage(vkrt::fuzz::writeInput(data, size, ".png"), error);  // nullopt + error is an answer
    return 0;
}
