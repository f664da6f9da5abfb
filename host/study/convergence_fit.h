// Convergence rates: a least-squares line through (log x, log y), whose slope is the exponent of
// error ~ x^slope (-0.5 for independent random samples, down to -0.75 and below for stratified
// samples on edges and -1 on smooth integrands; Mitchell 1996, Owen 1997).
#pragma once

#include <vector>

namespace vkrt::study {

struct LogLogFit {
    double slope = 0.0;
    double intercept = 0.0;   // log(y) at x = 1
    int points = 0;
    bool valid = false;       // at least two points with distinct positive x and positive y
};

// Points with x <= 0, y <= 0 or a non-finite value are skipped.
LogLogFit fitLogLog(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace vkrt::study
