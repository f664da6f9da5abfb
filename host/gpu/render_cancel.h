// The GPU renderer's answer to RenderOptions::cancel (Ctrl-C), checked before each submission of
// every render loop (megakernel passes, adaptive passes, wavefront waves).
#pragma once

#include "context.h"
#include "render_options.h"

namespace vkrt {

// Throws RenderCancelled when options.cancel is set, after the device has finished what it was
// given: the caller's buffers are freed while the exception unwinds, and no submission may still
// be writing them.
void throwIfCancelled(const Context& context, const RenderOptions& options);

}  // namespace vkrt
