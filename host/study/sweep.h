// `vkrt sweep`: the speed/accuracy trade of a scene, measured. Renders a converged reference
// (reference_cache.h), then every (seed, rpp, sampler, estimator, device) setting, and writes under DIR:
//   sweep.csv (one row per render), error_vs_time.png and error_vs_rpp.png (gnuplot),
//   report.md (convergence slopes, the cheapest setting for a target error), plots/ (plot data).
#pragma once

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <vector>

#include "gnuplot_plots.h"
#include "gpu_renderer.h"
#include "reference_cache.h"
#include "render_options.h"
#include "scene.h"
#include "sweep_types.h"
#include "work_sharing.h"

namespace vkrt::study {

struct SweepOptions {
    std::filesystem::path scenePath;
    std::filesystem::path outDir;
    // Size, depth, light/gloss samples, background, camera, threads, quiet. `seed` is the first of
    // the sweep's seeds (seed, seed + 1, ...); samplesPerPixel, sampler and estimator are ignored.
    RenderOptions render;
    std::vector<int> rpps{1, 4, 16, 64, 256};
    int seeds = 3;
    std::vector<SamplerKind> samplers{SamplerKind::Random, SamplerKind::Regular, SamplerKind::Jittered, SamplerKind::Sobol};
    // How Diffuse surfaces find emitters and the environment (render_options.h). By default only the
    // renders' default, so a sweep costs what it did before the axis existed; every estimator has
    // the same expectation, so all are measured against the one reference.
    std::vector<Estimator> estimators{RenderOptions{}.estimator};
    // Adaptive sampling (--targets): per seed, estimator and device, one render per target error
    // (docs/SAMPLING.md §7) with adaptiveSampler, bounded by adaptive's --min-rpp/--max-rpp; a
    // series of its own in the plots and tables. Empty: none.
    std::vector<double> targets;
    SamplerKind adaptiveSampler = SamplerKind::Sobol2;
    adaptive::AdaptiveOptions adaptive;  // its targetError is set per render
    std::vector<Device> devices{Device::Gpu, Device::Cpu};
    int referenceRpp = 4096;
    std::optional<Device> referenceDevice;  // default: the GPU when the sweep uses it, else the CPU
    SamplerKind referenceSampler = SamplerKind::Sobol;
    std::filesystem::path cacheDir;          // empty: defaultCacheDir()
    double targetRmse = 0.01;                // about 2.5 8-bit steps: noise is hard to see below it
    GpuRendererOptions gpu;
};

struct SweepResult {
    std::vector<SweepRow> rows;
    std::vector<SweepPoint> points;
    Reference reference;
    std::vector<Device> devices;   // the devices actually swept
    std::filesystem::path csv, report;
    PlotFiles plots;
    std::string validationMessages;  // Vulkan validation messages (with gpu.validation), empty when none
    bool leader = true;              // false on MPI ranks other than 0, which write nothing
};

// Throws std::invalid_argument for bad options (naming the option and value).
void validateSweepOptions(const SweepOptions& options);

// `scene` was loaded from options.scenePath (its camera settled in options.render.camera).
// Progress goes to `log`. Without a Vulkan device, a sweep that asked for both devices continues
// on the CPU (with a note); one that asked for the GPU only throws VulkanUnavailable.
// Throws std::runtime_error when gnuplot fails (sweep.csv and report.md are written by then).
//
// With `sharing` (an MPI job, work_sharing.h) the renders are spread over the ranks (shared_renders.h)
// and rank 0 writes everything; the other ranks return a result with no rows and leader false. Every
// rank must open the same devices (else std::runtime_error on the rank that differs).
SweepResult runSweep(const SweepOptions& options, const Scene& scene, std::ostream& log, WorkSharing* sharing = nullptr);

}  // namespace vkrt::study
