// libFuzzer target: vkrt merge's part reader (host/image/part_merge.h), the one reader that takes
// attributes from the file it reads (issue 38: a part claiming 1 of 2,000,000,000 once built a
// 2 GB list of missing parts). It must merge or throw std::runtime_error naming the file.
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "fuzz_input.h"
#include "part_merge.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        (void)vkrt::mergeParts({vkrt::fuzz::writeInput(data, size, ".exr")});
    } catch (const std::runtime_error&) {
        // the documented answer to a file that is not a complete set of parts
    }
    return 0;
}
