#include "sweep_csv.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

namespace vkrt::study {

namespace {

std::string number(double v) {
    if (std::isnan(v)) return "nan";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

}  // namespace

void writeSweepCsv(const std::vector<SweepRow>& rows, const std::filesystem::path& path) {
    std::ofstream out(path);
    if (!out) throw std::runtime_error(path.string() + ": cannot write the sweep's CSV");
    out << "device,sampler,estimator,rpp,seed,time_s,rmse,relmse";
    for (Region region : kRegions)
        if (region != Region::All) out << ",rmse_" << regionName(region);
    out << ",adaptive_target\n";  // empty for a uniform render; an adaptive one's rpp is its mean
    for (const SweepRow& r : rows) {
        out << deviceName(r.device) << ',' << samplerName(r.sampler) << ',' << estimatorName(r.estimator) << ',' << r.rpp
            << ',' << r.seed << ',' << number(r.seconds) << ',' << number(r.error.rmse) << ',' << number(r.error.relMse);
        for (Region region : kRegions)
            if (region != Region::All) out << ',' << number(rmseIn(r.error, region));
        out << ',';
        if (r.adaptiveTarget > 0.0) out << number(r.adaptiveTarget);
        out << '\n';
    }
    if (!out) throw std::runtime_error(path.string() + ": write failed");
}

}  // namespace vkrt::study
