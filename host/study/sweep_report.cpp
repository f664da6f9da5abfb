#include "sweep_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace vkrt::study {

namespace {

std::string fixed(double v, const char* format) {
    if (!std::isfinite(v)) return "-";
    char buf[48];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

std::vector<std::pair<Device, SamplerKind>> seriesOf(const std::vector<SweepPoint>& points) {
    std::vector<std::pair<Device, SamplerKind>> series;
    for (const SweepPoint& p : points)
        if (std::find(series.begin(), series.end(), std::pair(p.device, p.sampler)) == series.end())
            series.emplace_back(p.device, p.sampler);
    return series;
}

}  // namespace

std::vector<ConvergenceSlope> fitSlopes(const std::vector<SweepPoint>& points, const std::array<double, kRegionCount>& referenceMse) {
    std::vector<ConvergenceSlope> slopes;
    for (const auto& [device, sampler] : seriesOf(points))
        for (Region region : kRegions) {
            const int g = static_cast<int>(region);
            std::vector<double> x, y;
            for (const SweepPoint& p : points) {
                if (p.device != device || p.sampler != sampler) continue;
                const double floor = std::isfinite(referenceMse[g]) ? kReferenceFloorFactor * referenceMse[g] : 0.0;
                if (!(p.rmse[g] * p.rmse[g] > floor)) continue;
                x.push_back(p.rpp);
                y.push_back(p.rmse[g]);
            }
            slopes.push_back({device, sampler, region, fitLogLog(x, y)});
        }
    return slopes;
}

std::optional<SweepPoint> cheapestReaching(const std::vector<SweepPoint>& points, Region region, double target) {
    std::optional<SweepPoint> best;
    for (const SweepPoint& p : points) {
        const double e = p.rmse[static_cast<int>(region)];
        if (!(e <= target)) continue;
        if (!best || p.seconds < best->seconds) best = p;
    }
    return best;
}

void writeSweepReport(const SweepReportInput& in, const std::filesystem::path& path) {
    std::ofstream out(path);
    if (!out) throw std::runtime_error(path.string() + ": cannot write the sweep report");

    out << "# Sweep: " << in.scenePath << "\n\n"
        << in.settings << "\n\n"
        << "Reference: " << in.referenceLine << "\n\n"
        << "Region pixels (docs/SAMPLING.md §3): all " << in.regionPixels[0] << ", edge " << in.regionPixels[1]
        << ", penumbra " << in.regionPixels[2] << ", gloss " << in.regionPixels[3] << ", defocus " << in.regionPixels[4]
        << ", motion " << in.regionPixels[5] << ". "
        << "The reference's own estimated RMSE: all " << fixed(std::sqrt(in.referenceMse[0]), "%.2e") << ", edge "
        << fixed(std::sqrt(in.referenceMse[1]), "%.2e") << ", penumbra " << fixed(std::sqrt(in.referenceMse[2]), "%.2e")
        << ", gloss " << fixed(std::sqrt(in.referenceMse[3]), "%.2e") << ", defocus "
        << fixed(std::sqrt(in.referenceMse[4]), "%.2e") << ", motion " << fixed(std::sqrt(in.referenceMse[5]), "%.2e") << ".\n\n";

    out << "## Convergence slopes\n\n"
        << "RMSE ~ rpp^slope: least squares in log-log over the rpp values of a device and sampler (RMSE pooled "
           "over seeds), leaving out settings whose MSE is below "
        << kReferenceFloorFactor << "x the reference's own (they would measure the reference). "
        << "(n) = points used. -0.5 is plain Monte Carlo; stratification does better on edges (about -0.75) "
           "and smooth regions.\n\n"
        << "| device | sampler | all | edge | penumbra | gloss | defocus | motion |\n|---|---|---|---|---|---|---|---|\n";
    const std::vector<ConvergenceSlope> slopes = fitSlopes(in.points, in.referenceMse);
    for (const auto& [device, sampler] : seriesOf(in.points)) {
        out << "| " << deviceName(device) << " | " << samplerName(sampler) << " |";
        for (const ConvergenceSlope& s : slopes) {
            if (s.device != device || s.sampler != sampler) continue;
            out << ' ' << (s.fit.valid ? fixed(s.fit.slope, "%+.2f") + " (" + std::to_string(s.fit.points) + ")" : "-")
                << " |";
        }
        out << "\n";
    }

    out << "\n## Cheapest setting reaching RMSE <= " << in.targetRmse << "\n\n"
        << "Over the swept settings (mean time over seeds; the machine's speed drifts, so treat times as "
           "indicative).\n\n"
        << "| region | device | sampler | rpp | time (s) | RMSE |\n|---|---|---|---|---|---|\n";
    for (Region region : kRegions) {
        const std::optional<SweepPoint> best = cheapestReaching(in.points, region, in.targetRmse);
        out << "| " << regionName(region) << " | ";
        if (!best) {
            out << (in.regionPixels[static_cast<int>(region)] == 0 ? "no pixels" : "not reached") << " | | | | |\n";
            continue;
        }
        out << deviceName(best->device) << " | " << samplerName(best->sampler) << " | " << best->rpp << " | "
            << fixed(best->seconds, "%.3f") << " | " << fixed(best->rmse[static_cast<int>(region)], "%.2e") << " |\n";
    }

    out << "\n## Per setting\n\n| device | sampler | rpp | seeds | time (s) | RMSE | relMSE | edge | penumbra | gloss | defocus | motion |\n"
        << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const SweepPoint& p : in.points)
        out << "| " << deviceName(p.device) << " | " << samplerName(p.sampler) << " | " << p.rpp << " | " << p.seeds
            << " | " << fixed(p.seconds, "%.3f") << " | " << fixed(p.rmse[0], "%.2e") << " | " << fixed(p.relMse, "%.2e")
            << " | " << fixed(p.rmse[1], "%.2e") << " | " << fixed(p.rmse[2], "%.2e") << " | " << fixed(p.rmse[3], "%.2e")
            << " | " << fixed(p.rmse[4], "%.2e") << " | " << fixed(p.rmse[5], "%.2e") << " |\n";

    out << "\n## Files\n\n";
    for (const std::string& f : in.files) out << "- `" << f << "`\n";
    if (!out) throw std::runtime_error(path.string() + ": write failed");
}

}  // namespace vkrt::study
