// --progressive N: a render's passes written as they complete (RenderOptions::checkpoints), each
// atomically over the output, so a long render shows early and a viewer reloading the file sees
// it sharpen, with --exposure applied as to the final image. The last pass is the image the render
// returns, written by the caller.
#pragma once

#include <chrono>
#include <string>

#include "image.h"
#include "render_options.h"

namespace vkrt {

class ProgressiveOutput : public CheckpointSink {
public:
    ProgressiveOutput(std::string path, int samplesPerPixel, float exposure, bool quiet, std::string prefix = "");
    void checkpoint(const Image& soFar, int samplesDone) override;

private:
    std::string path_;
    int samplesPerPixel_;
    float exposure_;
    bool quiet_;
    std::string prefix_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace vkrt
