// The kernel's own failure, as a type callers can tell from other errors (`vkrt` falls back to
// the CPU reference on it with --device auto).
#pragma once

#include <stdexcept>

namespace vkrt {

// The kernel reported that it could not compute a sample correctly (RenderStatus flags, or a
// traced ray's failure words): the message names the pixel or ray, and what to reduce.
class GpuKernelError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace vkrt
