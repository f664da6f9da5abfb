// The sweep's plots, drawn by gnuplot (Debian gnuplot-nox): log-log RMSE against time and against
// rays per pixel, one panel per region, one line per device, sampler and estimator.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "sweep_types.h"

namespace vkrt::study {

struct PlotFiles {
    std::filesystem::path errorVsTime;  // DIR/error_vs_time.png
    std::filesystem::path errorVsRpp;   // DIR/error_vs_rpp.png
};

// Writes DIR/plots/<device>_<sampler>_<estimator>.dat and DIR/plots/sweep.gp and runs gnuplot on it.
// Colour = sampler, or with several estimators colour = estimator and point shape = sampler;
// solid lines and filled points = GPU, dashed and open = CPU.
// referenceRmse (per Region; NaN = none) is drawn as a dotted "reference noise" line: errors near
// it are the reference's own noise, not the render's. regionPixels labels the panels.
// Throws std::runtime_error when gnuplot is missing or fails (with its message).
PlotFiles plotSweep(const std::vector<SweepPoint>& points, const std::array<double, kRegionCount>& referenceRmse,
                    const std::array<std::size_t, kRegionCount>& regionPixels, const std::string& title,
                    const std::filesystem::path& outDir);

}  // namespace vkrt::study
