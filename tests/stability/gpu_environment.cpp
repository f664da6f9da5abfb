#include "gpu_environment.h"

#include <cstdlib>
#include <memory>

#include <gtest/gtest.h>

namespace vkrt::stability {

namespace {

class GpuEnvironment : public ::testing::Environment {
public:
    static GpuEnvironment* instance;

    GpuRenderer& renderer() {
        // Created on first use, so a filtered run without GPU tests never opens the device.
        if (!renderer_) {
            GpuRendererOptions options{.validation = true};
            // To check a GLSL edit against this suite without rebuilding (the --shader-dir of the CLI).
            if (const char* dir = std::getenv("VKRT_STABILITY_SHADER_DIR"); dir && *dir) options.shaderDir = dir;
            renderer_ = std::make_unique<GpuRenderer>(options);
            log_ = renderer_->validationLog();
        }
        return *renderer_;
    }

    void TearDown() override {
        renderer_.reset();  // messages sent while destroying count too
        if (log_) {
            EXPECT_EQ(log_->count(), 0u) << "validation messages:\n" << log_->joined();
        }
    }

private:
    std::unique_ptr<GpuRenderer> renderer_;
    std::shared_ptr<const ValidationLog> log_;
};

GpuEnvironment* GpuEnvironment::instance = nullptr;

// Registered before main() runs the tests; gtest owns and deletes the environment.
const bool registered = [] {
    GpuEnvironment::instance = new GpuEnvironment;
    ::testing::AddGlobalTestEnvironment(GpuEnvironment::instance);
    return true;
}();

}  // namespace

GpuRenderer& sharedGpu() { return GpuEnvironment::instance->renderer(); }

}  // namespace vkrt::stability
