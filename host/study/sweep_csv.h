// DIR/sweep.csv: one row per render of a sweep.
#pragma once

#include <filesystem>
#include <vector>

#include "sweep_types.h"

namespace vkrt::study {

// The header: device,sampler,estimator,rpp,seed,time_s,rmse,relmse, then rmse_<region> for every
// region but all (edge, penumbra, gloss, defocus, motion, indirect, emitter). An empty region's
// RMSE is written as "nan". Throws std::runtime_error naming the file.
void writeSweepCsv(const std::vector<SweepRow>& rows, const std::filesystem::path& path);

}  // namespace vkrt::study
