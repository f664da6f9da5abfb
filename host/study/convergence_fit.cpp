#include "convergence_fit.h"

#include <cmath>
#include <stdexcept>

namespace vkrt::study {

LogLogFit fitLogLog(const std::vector<double>& x, const std::vector<double>& y) {
    if (x.size() != y.size()) throw std::invalid_argument("fitLogLog: x and y differ in length");
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (!(x[i] > 0.0 && y[i] > 0.0 && std::isfinite(x[i]) && std::isfinite(y[i]))) continue;
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
        ++n;
    }
    LogLogFit fit;
    fit.points = n;
    const double denominator = n * sxx - sx * sx;
    // Fewer than two distinct x values leave the slope undefined.
    if (n < 2 || !(std::abs(denominator) > 1e-12 * std::max(1.0, n * sxx))) return fit;
    fit.slope = (n * sxy - sx * sy) / denominator;
    fit.intercept = (sy - fit.slope * sx) / n;
    fit.valid = true;
    return fit;
}

}  // namespace vkrt::study
