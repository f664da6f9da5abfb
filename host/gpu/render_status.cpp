#include "render_status.h"

#include <sstream>
#include <string>

#include "kernel_error.h"

namespace vkrt {

void throwIfKernelFailed(const gpu::RenderStatus& status, std::uint32_t imageWidth, bool loopLimiter) {
    const std::uint32_t flags = gpu::statusFailures(status);
    if (flags == 0) return;
    std::string where = "(the kernel did not record the pixel)";
    if (gpu::statusPixelPlusOne(status) != 0 && imageWidth > 0) {
        const std::uint32_t pixel = gpu::statusPixelPlusOne(status) - 1;  // stored + 1 so that 0 means "none"
        where = "at pixel (" + std::to_string(pixel % imageWidth) + ", " + std::to_string(pixel / imageWidth) + "), sample " +
                std::to_string(gpu::statusSample(status));
    }
    std::string message = "the GPU kernel could not compute the image correctly " + where + ":";
    if (flags & gpu::STATUS_LOOP_BUDGET_EXCEEDED)
        message += " one sample needed more than " + std::to_string(gpu::LOOP_BUDGET) + " loop iterations (" +
                   (loopLimiter ? "the kernel stops there because lavapipe before Mesa 25 silently cuts every invocation "
                                  "off at 65,535"
                                : "the kernel's budget per sample, which turns a runaway loop into this error instead of a hang") +
                   "); reduce --max-depth, --gloss-samples or --light-samples, or the scene's geometry overlap;";
    if (flags & gpu::STATUS_LOOP_CUT_OFF)
        message += loopLimiter
                       ? " a loop of the kernel was cut off before it finished: this driver ends loops silently after "
                         "65,535 passes per group of 8 lanes (lavapipe before Mesa 25), and one sample of this scene needs "
                         "more (many lights, deep reflection, heavy overlap); reduce the number of lights, --light-samples, "
                         "--gloss-samples or --max-depth, or render with --device cpu;"
                       : " a loop of the kernel ended before it finished its work, which this driver is not known to do "
                         "(only lavapipe before Mesa 25 cuts loops off): please report it with the scene; --device cpu "
                         "renders it meanwhile;";
    if (flags & gpu::STATUS_RAY_STACK_OVERFLOW)
        message += " a ray stack overflowed (BVH traversal stack of " + std::to_string(gpu::TRAVERSAL_STACK_SIZE) +
                   " entries, or the pending reflection/refraction rays); reduce --max-depth or --gloss-samples;";
    if (flags & gpu::STATUS_SHADOW_RAYS_MISMATCH)
        message += " the wavefront stages' two shadings of one hit asked for different shadow rays (this driver compiled "
                   "shaders/wavefront_shade_record.comp and wavefront_shade_resolve.comp to different decisions); "
                   "render with --gpu-kernel megakernel and please report it with the scene;";
    const std::uint32_t known = gpu::STATUS_LOOP_BUDGET_EXCEEDED | gpu::STATUS_RAY_STACK_OVERFLOW | gpu::STATUS_LOOP_CUT_OFF |
                                gpu::STATUS_SHADOW_RAYS_MISMATCH;
    if (flags & ~known) {
        std::ostringstream hex;
        hex << std::hex << (flags & ~known);
        message += " unknown status flags 0x" + hex.str() + ";";
    }
    message.pop_back();
    throw GpuKernelError(message);
}

}  // namespace vkrt
