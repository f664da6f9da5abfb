#include "gnuplot_plots.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <map>
#include <spawn.h>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>

extern char** environ;

namespace vkrt::study {

namespace {

// One colour per sampler, the same in every plot; devices differ by dash and by filled (GPU) or
// open (CPU) points.
std::string colour(SamplerKind s) {
    switch (s) {
    case SamplerKind::Random: return "#d62728";
    case SamplerKind::Regular: return "#7f7f7f";
    case SamplerKind::Jittered: return "#1f77b4";
    case SamplerKind::Sobol: return "#2ca02c";
    case SamplerKind::Sobol2: return "#8c564b";
    }
    return "#000000";
}

// Adaptive sampling's series (--targets), whatever its sampler.
const char* const kAdaptiveColour = "#e377c2";

// A sweep of several estimators compares them, so they get the colours (colour is what the eye
// follows from panel to panel) and the samplers the point shapes; with one estimator the plots are
// those of a sampler sweep.
std::string colour(Estimator e) {
    switch (e) {
    case Estimator::Bounce: return "#d62728";
    case Estimator::Nee: return "#ff7f0e";
    case Estimator::MisBalance: return "#9467bd";
    case Estimator::MisPower: return "#2ca02c";
    }
    return "#000000";
}

// gnuplot point types: circle, square, triangle, diamond, triangle down, each filled (GPU) or open (CPU).
int pointType(SamplerKind s, bool gpu) {
    int filled = 7;
    switch (s) {
    case SamplerKind::Random: filled = 7; break;
    case SamplerKind::Regular: filled = 5; break;
    case SamplerKind::Jittered: filled = 9; break;
    case SamplerKind::Sobol: filled = 13; break;
    case SamplerKind::Sobol2: filled = 11; break;  // triangle pointing down
    }
    return gpu ? filled : filled - 1;
}

// A gnuplot single-quoted string: a quote inside is written twice.
std::string quoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

std::string number(double v) {
    if (!(v > 0.0) || !std::isfinite(v)) return "NaN";  // gnuplot skips NaN (log scale needs > 0)
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

struct PlotSeries {
    Series series;
    std::filesystem::path data;
};

// Runs `gnuplot script`, stderr into logPath; throws with the log on failure.
void runGnuplot(const std::filesystem::path& script, const std::filesystem::path& logPath) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 2, logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    std::string program = "gnuplot", scriptArg = script.string();
    char* argv[] = {program.data(), scriptArg.data(), nullptr};
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0)
        throw std::runtime_error("cannot run gnuplot (" + std::string(std::strerror(spawned)) +
                                 "): install gnuplot-nox (setup.sh does) to get the sweep's plots");
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::ifstream log(logPath);
        std::stringstream text;
        text << log.rdbuf();
        throw std::runtime_error("gnuplot failed on " + script.string() + ":\n" + text.str());
    }
}

}  // namespace

PlotFiles plotSweep(const std::vector<SweepPoint>& points, const std::array<double, kRegionCount>& referenceRmse,
                    const std::array<std::size_t, kRegionCount>& regionPixels, const std::string& title,
                    const std::filesystem::path& outDir) {
    const std::filesystem::path dir = outDir / "plots";
    std::filesystem::create_directories(dir);

    std::vector<PlotSeries> series;
    std::map<std::string, std::ofstream> files;
    bool severalEstimators = false;
    for (const SweepPoint& p : points) severalEstimators = severalEstimators || p.estimator != points.front().estimator;
    for (const SweepPoint& p : points) {
        const std::string name = deviceName(p.device) + "_" + samplerName(p.sampler) + (p.adaptiveTarget > 0.0 ? "_adaptive_" : "_") +
                                 estimatorName(p.estimator);
        auto [it, added] = files.try_emplace(name);
        if (added) {
            series.push_back({seriesOf(p), dir / (name + ".dat")});
            it->second.open(series.back().data);
            it->second << "# rpp seconds";
            for (Region region : kRegions) it->second << " rmse_" << regionName(region);
            it->second << " (RMSE over seeds)\n";
        }
        it->second << p.rpp << ' ' << number(p.seconds);
        for (double e : p.rmse) it->second << ' ' << number(e);
        it->second << '\n';
    }
    for (auto& [name, f] : files) f.close();

    PlotFiles out{outDir / "error_vs_time.png", outDir / "error_vs_rpp.png"};
    std::ostringstream gp;
    gp << "set terminal pngcairo size 2000,900 noenhanced font 'sans,10'\n"
       << "set logscale xy\nset grid\nset key bottom left box opaque\nset ylabel 'RMSE (linear radiance)'\n";
    auto figure = [&](const std::filesystem::path& png, bool byTime) {
        gp << "set output " << quoted(png.string()) << "\n"
           << "set xlabel " << quoted(byTime ? "render time (s)" : "rays per pixel") << "\n"
           << "set multiplot layout 2,4 title " << quoted(title + (byTime ? ": error vs time" : ": error vs rpp")) << "\n";
        for (Region region : kRegions) {
            const int g = static_cast<int>(region);
            gp << "set title " << quoted(regionName(region) + " pixels (" + std::to_string(regionPixels[g]) + ")") << "\n";
            bool anyData = false;
            for (const SweepPoint& p : points) anyData = anyData || (p.rmse[g] > 0.0 && std::isfinite(p.rmse[g]));
            if (!anyData) {
                // An empty region still gets its panel, so the layout does not shift.
                gp << "unset key\nset label 1 'no pixels in this region' at graph 0.5,0.5 center\n"
                   << "plot [1:10] [1:10] NaN notitle\nunset label 1\n";
                continue;
            }
            // One legend, in the first panel: the colours and dashes mean the same in every panel.
            gp << (region == Region::All ? "set key bottom left box opaque\n" : "unset key\n") << "plot ";
            for (std::size_t k = 0; k < series.size(); ++k) {
                const Series& s = series[k].series;
                const bool gpu = s.device == Device::Gpu;
                std::string title = deviceName(s.device);
                title += ' ';  // appended separately: GCC 12 warns falsely (-Wrestrict) on " " + string
                title += samplerLabel(s);
                if (severalEstimators) (title += ' ') += estimatorName(s.estimator);
                gp << (k ? ", \\\n     " : "") << quoted(series[k].data.string()) << " using " << (byTime ? 2 : 1) << ':'
                   << (3 + g) << " with linespoints lw 2 lc rgb "
                   << quoted(severalEstimators ? colour(s.estimator) : s.adaptive ? kAdaptiveColour : colour(s.sampler))
                   << " dt " << (gpu ? 1 : 2)
                   << " pt " << (severalEstimators ? pointType(s.sampler, gpu) : (gpu ? 7 : 6)) << " title " << quoted(title);
            }
            if (referenceRmse[g] > 0.0 && std::isfinite(referenceRmse[g]))
                gp << ", \\\n     " << number(referenceRmse[g]) << " with lines dt 3 lw 2 lc rgb '#000000' title 'reference noise'";
            gp << "\n";
        }
        gp << "unset multiplot\n";
    };
    figure(out.errorVsTime, true);
    figure(out.errorVsRpp, false);

    const std::filesystem::path script = dir / "sweep.gp";
    std::ofstream(script) << gp.str();
    runGnuplot(script, dir / "gnuplot.log");
    return out;
}

}  // namespace vkrt::study
