#include "progressive_output.h"

#include <cstdio>

#include "exposure.h"

namespace vkrt {

ProgressiveOutput::ProgressiveOutput(std::string path, int samplesPerPixel, float exposure, bool quiet, std::string prefix)
    : path_(std::move(path)), samplesPerPixel_(samplesPerPixel), exposure_(exposure), quiet_(quiet), prefix_(std::move(prefix)),
      start_(std::chrono::steady_clock::now()) {}

void ProgressiveOutput::checkpoint(const Image& soFar, int samplesDone) {
    writeImage(withExposure(soFar, exposure_), path_);
    if (!quiet_)
        std::fprintf(stderr, "%s%d/%d rpp at %.3fs -> %s\n", prefix_.c_str(), samplesDone, samplesPerPixel_,
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(), path_.c_str());
}

}  // namespace vkrt
