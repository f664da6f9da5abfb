#include "render_cancel.h"

namespace vkrt {

void throwIfCancelled(const Context& context, const RenderOptions& options) {
    if (!options.cancel || !options.cancel->load()) return;
    context.device().waitIdle();
    throw RenderCancelled{};
}

}  // namespace vkrt
