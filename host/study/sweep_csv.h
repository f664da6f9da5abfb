// DIR/sweep.csv: one row per render of a sweep.
#pragma once

#include <filesystem>
#include <vector>

#include "sweep_types.h"

namespace vkrt::study {

// The header: device,sampler,rpp,seed,time_s,rmse,relmse,rmse_edge,rmse_penumbra,rmse_gloss.
// An empty region's RMSE is written as "nan". Throws std::runtime_error naming the file.
void writeSweepCsv(const std::vector<SweepRow>& rows, const std::filesystem::path& path);

}  // namespace vkrt::study
