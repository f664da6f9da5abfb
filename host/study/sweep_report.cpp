#include "sweep_report.h"

#include <algorithm>
#include <tuple>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace vkrt::study {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string fixed(double v, const char* format) {
    if (!std::isfinite(v)) return "-";
    char buf[48];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

// "| device | sampler | estimator |", the first cells of every table row about one series.
std::string seriesCells(const Series& s) {
    return "| " + deviceName(s.device) + " | " + samplerLabel(s) + " | " + estimatorName(s.estimator) + " |";
}

// The region columns' header cells (" all | edge | ... |") and the separator's cells.
std::string regionHeader() {
    std::string h;
    for (Region region : kRegions) ((h += ' ') += regionName(region)) += " |";  // not " " + ...: GCC 12's false -Wrestrict
    return h;
}
std::string separator(std::size_t columns) {
    std::string s = "|";
    for (std::size_t c = 0; c < columns; ++c) s += "---|";
    return s + "\n";
}

// The (device, sampler, adaptive) groups whose estimators are compared, in order of appearance.
std::vector<std::tuple<Device, SamplerKind, bool>> devicesAndSamplers(const std::vector<SweepPoint>& points) {
    std::vector<std::tuple<Device, SamplerKind, bool>> groups;
    for (const SweepPoint& p : points) {
        const std::tuple group(p.device, p.sampler, p.adaptiveTarget > 0.0);
        if (std::find(groups.begin(), groups.end(), group) == groups.end()) groups.push_back(group);
    }
    return groups;
}

void writeEqualTime(std::ostream& out, const SweepReportInput& in) {
    out << "\n## Estimators at equal time\n\n"
        << "Per device and sampler, each estimator's RMSE at the same render time: the longest time every "
           "estimator's settings reached (so none is extrapolated), interpolated linearly in log time and log "
           "RMSE between the two settings around it (times are means over seeds). `/ best` is the estimator's "
           "RMSE over all pixels divided by the lowest at that time: how much more error it leaves for the "
           "same time (the time to reach equal error differs by about its square for -0.5 slopes).\n\n"
        << "| device | sampler | estimator | time (s) |" << regionHeader() << " / best |\n"
        << separator(5 + kRegionCount);
    const std::vector<Series> series = seriesIn(in.points);
    for (const auto& [device, sampler, adaptive] : devicesAndSamplers(in.points)) {
        const double t = commonTime(in.points, device, sampler, adaptive);
        const auto inGroup = [&](const Series& s) { return s.device == device && s.sampler == sampler && s.adaptive == adaptive; };
        double best = kNaN;
        for (const Series& s : series)
            if (inGroup(s)) best = std::fmin(best, rmseAtTime(in.points, s, Region::All, t));
        for (const Series& s : series) {
            if (!inGroup(s)) continue;
            out << seriesCells(s) << " " << fixed(t, "%.3f") << " |";
            for (Region region : kRegions) out << " " << fixed(rmseAtTime(in.points, s, region, t), "%.2e") << " |";
            out << " " << fixed(rmseAtTime(in.points, s, Region::All, t) / best, "%.2f") << " |\n";
        }
    }
}

}  // namespace

std::vector<ConvergenceSlope> fitSlopes(const std::vector<SweepPoint>& points, const std::array<double, kRegionCount>& referenceMse) {
    std::vector<ConvergenceSlope> slopes;
    for (const Series& series : seriesIn(points))
        for (Region region : kRegions) {
            const int g = static_cast<int>(region);
            std::vector<double> x, y;
            for (const SweepPoint& p : points) {
                if (!(seriesOf(p) == series)) continue;
                const double floor = std::isfinite(referenceMse[g]) ? kReferenceFloorFactor * referenceMse[g] : 0.0;
                if (!(p.rmse[g] * p.rmse[g] > floor)) continue;
                x.push_back(p.rpp);
                y.push_back(p.rmse[g]);
            }
            slopes.push_back({series, region, fitLogLog(x, y)});
        }
    return slopes;
}

double commonTime(const std::vector<SweepPoint>& points, Device device, SamplerKind sampler, bool adaptive) {
    double longest = kNaN, shortest = kNaN;  // the least longest and the greatest shortest time
    for (const Series& s : seriesIn(points)) {
        if (s.device != device || s.sampler != sampler || s.adaptive != adaptive) continue;
        double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
        for (const SweepPoint& p : points)
            if (seriesOf(p) == s) {
                lo = std::min(lo, p.seconds);
                hi = std::max(hi, p.seconds);
            }
        longest = std::fmin(longest, hi);
        shortest = std::fmax(shortest, lo);
    }
    return shortest <= longest ? longest : kNaN;
}

double rmseAtTime(const std::vector<SweepPoint>& points, const Series& series, Region region, double seconds) {
    std::vector<std::pair<double, double>> curve;  // (time, RMSE), ordered by time
    for (const SweepPoint& p : points)
        if (seriesOf(p) == series) curve.emplace_back(p.seconds, p.rmse[static_cast<int>(region)]);
    std::sort(curve.begin(), curve.end());
    if (curve.empty() || !(seconds >= curve.front().first && seconds <= curve.back().first)) return kNaN;
    for (std::size_t k = 0; k < curve.size(); ++k) {
        const auto [t1, e1] = curve[k];
        if (seconds > t1) continue;
        if (seconds == t1 || k == 0) return e1;
        const auto [t0, e0] = curve[k - 1];
        if (!(t0 > 0.0 && e0 > 0.0 && e1 > 0.0)) return kNaN;
        const double a = std::log(seconds / t0) / std::log(t1 / t0);
        return std::exp((1.0 - a) * std::log(e0) + a * std::log(e1));
    }
    return kNaN;
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
        << "Region pixels (docs/SAMPLING.md §3):";
    for (Region region : kRegions)
        out << (region == Region::All ? " " : ", ") << regionName(region) << " " << in.regionPixels[static_cast<int>(region)];
    out << ". The reference's own estimated RMSE:";
    for (Region region : kRegions)
        out << (region == Region::All ? " " : ", ") << regionName(region) << " "
            << fixed(std::sqrt(in.referenceMse[static_cast<int>(region)]), "%.2e");
    out << ".\n\n";

    out << "## Convergence slopes\n\n"
        << "RMSE ~ rpp^slope: least squares in log-log over the rpp values of a device, sampler and estimator "
           "(RMSE pooled over seeds), leaving out settings whose MSE is below "
        << kReferenceFloorFactor << "x the reference's own (they would measure the reference). "
        << "(n) = points used. -0.5 is plain Monte Carlo; stratification does better on edges (about -0.75) "
           "and smooth regions.\n\n"
        << "| device | sampler | estimator |" << regionHeader() << "\n"
        << separator(3 + kRegionCount);
    const std::vector<ConvergenceSlope> slopes = fitSlopes(in.points, in.referenceMse);
    for (const Series& series : seriesIn(in.points)) {
        out << seriesCells(series);
        for (const ConvergenceSlope& s : slopes) {
            if (!(s.series == series)) continue;
            out << ' ' << (s.fit.valid ? fixed(s.fit.slope, "%+.2f") + " (" + std::to_string(s.fit.points) + ")" : "-")
                << " |";
        }
        out << "\n";
    }

    bool severalEstimators = false;
    for (const SweepPoint& p : in.points) severalEstimators = severalEstimators || p.estimator != in.points.front().estimator;
    if (severalEstimators) writeEqualTime(out, in);

    out << "\n## Cheapest setting reaching RMSE <= " << in.targetRmse << "\n\n"
        << "Over the swept settings (mean time over seeds; the machine's speed drifts, so treat times as "
           "indicative).\n\n"
        << "| region | device | sampler | estimator | rpp | time (s) | RMSE |\n"
        << separator(7);
    for (Region region : kRegions) {
        const std::optional<SweepPoint> best = cheapestReaching(in.points, region, in.targetRmse);
        out << "| " << regionName(region) << " | ";
        if (!best) {
            out << (in.regionPixels[static_cast<int>(region)] == 0 ? "no pixels" : "not reached") << " | | | | | |\n";
            continue;
        }
        out << deviceName(best->device) << " | " << samplerLabel(seriesOf(*best)) << " | " << estimatorName(best->estimator)
            << " | " << best->rpp << " | " << fixed(best->seconds, "%.3f") << " | "
            << fixed(best->rmse[static_cast<int>(region)], "%.2e") << " |\n";
    }

    out << "\n## Per setting\n\n| device | sampler | estimator | rpp | seeds | time (s) | relMSE |" << regionHeader() << "\n"
        << separator(7 + kRegionCount);
    for (const SweepPoint& p : in.points) {
        out << seriesCells(seriesOf(p)) << " " << p.rpp << " | " << p.seeds << " | " << fixed(p.seconds, "%.3f") << " | "
            << fixed(p.relMse, "%.2e") << " |";
        for (double e : p.rmse) out << " " << fixed(e, "%.2e") << " |";
        out << "\n";
    }

    out << "\n## Files\n\n";
    for (const std::string& f : in.files) out << "- `" << f << "`\n";
    if (!out) throw std::runtime_error(path.string() + ": write failed");
}

}  // namespace vkrt::study
