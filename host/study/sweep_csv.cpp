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
    out << "device,sampler,rpp,seed,time_s,rmse,relmse,rmse_edge,rmse_penumbra,rmse_gloss,rmse_defocus,rmse_motion\n";
    for (const SweepRow& r : rows)
        out << deviceName(r.device) << ',' << samplerName(r.sampler) << ',' << r.rpp << ',' << r.seed << ','
            << number(r.seconds) << ',' << number(r.error.rmse) << ',' << number(r.error.relMse) << ','
            << number(r.error.rmseEdge) << ',' << number(r.error.rmsePenumbra) << ',' << number(r.error.rmseGloss)
            << ',' << number(r.error.rmseDefocus) << ',' << number(r.error.rmseMotion) << '\n';
    if (!out) throw std::runtime_error(path.string() + ": write failed");
}

}  // namespace vkrt::study
