#include "command_line.h"

#include <cfloat>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include <CLI/CLI.hpp>

#include "exposure.h"
#include "image_check.h"
#include "input_limits.h"
#include "version.h"

namespace vkrt {

namespace {

std::string number(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

// "r,g,b" or "r g b" -> a colour; throws CLI::ValidationError.
glm::vec3 parseColour(const std::string& text) {
    std::string s = text;
    for (char& c : s)
        if (c == ',') c = ' ';
    std::istringstream in(s);
    glm::vec3 c;
    std::string extra;
    if (!(in >> c.r >> c.g >> c.b) || (in >> extra))
        throw CLI::ValidationError("--bg", "expected three numbers r,g,b, got '" + text + "'");
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(c[i])) throw CLI::ValidationError("--bg", "not a finite colour: '" + text + "'");
    return c;
}

// "x,y,z" or "x y z" -> the --up vector: three numbers a float holds, not all zero (whether it is
// parallel to the gaze is checked once the scene's camera is known, render_steps.cpp).
glm::vec3 parseUp(const std::string& text) {
    std::string s = text;
    for (char& c : s)
        if (c == ',') c = ' ';
    std::istringstream in(s);
    glm::dvec3 up;
    std::string extra;
    if (!(in >> up.x >> up.y >> up.z) || (in >> extra))
        throw CLI::ValidationError("--up", "expected three numbers x,y,z, got '" + text + "'");
    for (int i = 0; i < 3; ++i)
        if (!(std::fabs(up[i]) <= FLT_MAX)) throw CLI::ValidationError("--up", "'" + text + "': each number must be finite and within float");
    if (up == glm::dvec3(0.0)) throw CLI::ValidationError("--up", "'" + text + "': the up vector has zero length");
    return glm::vec3(up);
}

// --exposure EV: a finite number of stops within kMaxExposureStops (exposure.h).
float parseExposure(const std::string& text) {
    std::size_t used = 0;
    double ev = 0.0;
    try {
        ev = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != text.size())
        throw CLI::ValidationError("--exposure", "'" + text + "': expected a number of stops (1 doubles the image, -1 halves it)");
    if (!(std::fabs(ev) <= kMaxExposureStops))
        throw CLI::ValidationError("--exposure", "'" + text + "': must be finite and within -" + number(kMaxExposureStops) +
                                                     ".." + number(kMaxExposureStops) + " stops");
    return static_cast<float>(ev);
}

// --exposure EV, with what it means for the command at hand.
void addExposureOption(CLI::App& app, CommandLine& cl, const std::string& help) {
    app.add_option_function<std::string>("--exposure", [&cl](const std::string& text) { cl.exposure = parseExposure(text); }, help)
        ->type_name("EV")
        ->default_str("0");
}

// --input-limit NAME=VALUE (repeatable): raises or lowers one of the limits every reader keeps
// (input_limits.h), for every command that reads files.
void addInputLimitOption(CLI::App& app) {
    app.add_option_function<std::vector<std::string>>(
           "--input-limit",
           [](const std::vector<std::string>& assignments) {
               for (const std::string& a : assignments) {
                   try {
                       setInputLimit(a);
                   } catch (const std::invalid_argument& e) {
                       throw CLI::ValidationError("--input-limit", e.what());
                   }
               }
           },
           "Raise (or lower) what vkrt reads from one file: NAME=VALUE with K, M or G for powers of 1024; names "
           "scene-bytes (64M), mesh-bytes (1G), image-texels (32M: one texture, or an environment map's six faces), "
           "scene-texels (64M: all of a scene's textures), read-pixels (256M: an image read whole). Repeatable")
        ->type_name("NAME=VALUE");
}

// The options every command shares (what the image is, which GPU, how to run).
// A number a float holds: a scene file refuses 1e39 for a lens, so the command line does too
// (CLI11 would read it as inf).
const CLI::Validator kFiniteFloat(
    [](std::string& text) -> std::string {
        try {
            const double v = std::stod(text);
            if (std::isfinite(v) && std::fabs(v) <= FLT_MAX) return "";
        } catch (const std::exception&) {
            return "";  // not a number: the option's own conversion says so
        }
        return "'" + text + "' is beyond what a float holds (3.4e38)";
    },
    "FINITE");

void addImageOptions(CLI::App& app, CommandLine& cl, std::string& bg) {
    addInputLimitOption(app);
    app.add_option("scene", cl.scenePath, "Scene file: .xml or .json (the UMD course's formats)");
    app.add_option("-i,--input,--inputfile", cl.scenePath, "Scene file (the course's spelling)");
    app.add_option("-w,--width", cl.render.width, "Image width in pixels")->check(CLI::Range(1, 1 << 16));
    app.add_option("-h,--height", cl.render.height, "Image height in pixels")->check(CLI::Range(1, 1 << 16));
    app.add_option("-k,--max-depth,--recursionDepth", cl.render.maxDepth, "Reflection/refraction recursion depth")
        ->check(CLI::Range(0, 64));
    app.add_option("--light-samples", cl.render.lightSamples,
                   "Light samples per pixel sample: per area light, and for all shape emitters together (each "
                   "goes to one, chosen by power)")
        ->check(CLI::Range(1, 4096));
    app.add_option("--gloss-samples", cl.render.glossSamples,
                   "Glossy reflection directions per pixel sample (at primary hits)")
        ->check(CLI::Range(1, 4096));
    app.add_option("--seed", cl.render.seed, "Random seed: the same seed and options give the same image");
    app.add_option("--bg", bg, "Background colour r,g,b (overrides the scene's bgColor)");
    app.add_option_function<std::string>(
           "--look", [&cl](const std::string& name) { cl.referenceLook = name == "reference"; },
           "reference: the instructor's reference renders' look (50/255 grey background, no environment "
           "map; --bg still overrides the colour); scene: the scene's own background and environment")
        ->check(CLI::IsMember({"scene", "reference"}))
        ->default_str("scene");
    app.add_flag("--no-environment{false}", cl.render.environment,
                 "Rays that leave the scene see the background colour even when the scene names an environment map "
                 "(as in the course's own ray tracers and its reference renders)");
    app.add_option_function<std::vector<float>>(
           "--shutter",
           [&cl](const std::vector<float>& v) {
               const std::string text = number(v[0]) + "," + number(v[1]);
               if (!std::isfinite(v[0]) || !std::isfinite(v[1])) throw CLI::ValidationError("--shutter", text + ": open and close must be finite");
               if (v[1] < v[0]) throw CLI::ValidationError("--shutter", text + ": the shutter closes (" + number(v[1]) + ") before it opens (" + number(v[0]) + ")");
               cl.render.shutter = glm::vec2(v[0], v[1]);
           },
           "Motion blur: the shutter's OPEN,CLOSE in the motion's time (0 = the instances' <transform>, 1 = "
           "their <transformEnd>; default 0,1, the whole motion; 0,0 renders the start pose sharp). A scene "
           "without moving instances renders the same image with any shutter")
        ->delimiter(',')
        ->expected(2);
    app.add_option("--camera", cl.camera, "Which camera of the scene (index; default: the one <sceneParameters> names, else the first)")
        ->check(CLI::NonNegativeNumber);
    app.add_option_function<std::string>(
        "--up", [&cl](const std::string& text) { cl.up = parseUp(text); },
        "The camera's up vector x,y,z (overrides the scene's; default: 0,1,0, or 1,0,0 for a camera looking straight "
        "up or down: docs/RENDERING.md §1). Must not be parallel to the view direction");
    app.add_option("-n,--numcpus,--threads", cl.render.threads,
                   "CPU threads of the CPU reference and of host-side work, the course's -n (default 0: all cores); "
                   "a GPU render runs on the Vulkan device")
        ->check(CLI::Range(0, 1024));
    app.add_option("--gpu", cl.gpuIndex, "Vulkan device index (see --list-devices); asks for Vulkan under --device auto")
        ->check(CLI::NonNegativeNumber);
    app.add_flag("--validate", cl.validate, "Enable the Vulkan validation layers");
    app.add_option("--shader-dir", cl.shaderDir,
                   "Compile the GLSL kernels from this directory at run time (edit and re-run, no rebuild)")
        ->check(CLI::ExistingDirectory);
    app.add_flag("--strict", cl.strict, "Treat scene warnings as errors");
    app.add_flag("-q,--quiet", cl.render.quiet, "No progress bar, summary or warnings (errors are always printed)");
}

void addRenderOptions(CLI::App& app, CommandLine& cl, std::string& bg, std::string& sampler, std::string& device) {
    addImageOptions(app, cl, bg);
    app.add_option("-r,--rpp", cl.render.samplesPerPixel,
                   "Samples per pixel; n*n jittered sub-pixel samples when it is a square")
        ->check(CLI::Range(1, 1 << 20));
    app.add_option("--sampler", sampler,
                   "Sample pattern: jittered (Cook 1984), regular, random, sobol (Owen-scrambled, Burley 2020) or sobol2 (two independent Sobol sequences interleaved; the default of --target-error and --time)")
        ->check(CLI::IsMember({"jittered", "regular", "random", "sobol", "sobol2"}));
    app.add_option_function<std::string>(
           "--estimator",
           [&cl](const std::string& name) {
               try {
                   cl.render.estimator = parseEstimator(name);
               } catch (const std::invalid_argument& e) {
                   throw CLI::ValidationError("--estimator", e.what());
               }
           },
           "Diffuse surfaces (path tracing): how light from shape emitters and the environment map is found: "
           "bounce (only by the cosine-weighted bounce ray, the course's shader), nee (only by light samples), "
           "mis-balance or mis (both, weighted by the balance or the power heuristic). Same image in "
           "expectation; default mis")
        ->default_str("mis");
    app.add_option("--device", device,
                   "Renderer: gpu (Vulkan, any device, lavapipe included; an error when none opens), cpu (the "
                   "reference) or auto (a GPU when Vulkan has one, else the CPU reference with a note: it is faster "
                   "than a Vulkan driver that runs on the CPU; --gpu, --shader-dir, --general-kernel and --validate "
                   "ask for Vulkan)")
        ->check(CLI::IsMember({"auto", "cpu", "gpu"}));
    app.add_flag("--general-kernel", cl.general, "GPU: use the kernel with every feature (no specialisation)");
    app.add_option("--gpu-kernel", cl.gpuKernel,
                   "GPU: megakernel (one invocation computes a sample's whole path), wavefront (waves of paths "
                   "through one kernel per stage: camera rays, closest hits, shading, shadow rays, accumulation; "
                   "the same image, far fewer registers per kernel on a GPU compiler) or auto (the megakernel on "
                   "lavapipe, where it is faster, the wavefront stages on other devices)")
        ->check(CLI::IsMember({"auto", "megakernel", "wavefront"}))
        ->default_str("auto");
}

// vkrt sweep: lists instead of single values, and where the results and the reference cache go.
struct SweepText {
    std::string out, cache, device = "both", referenceDevice;
    std::vector<std::string> samplers{"random", "regular", "jittered", "sobol"};
    std::vector<std::string> estimators{estimatorName(RenderOptions{}.estimator)};
};

void addSweepOptions(CLI::App& app, CommandLine& cl, std::string& bg, SweepText& text) {
    addImageOptions(app, cl, bg);
    study::SweepOptions& sw = cl.sweep;
    app.add_option("--out", text.out, "Directory for sweep.csv, the plots and report.md")->required();
    app.add_option("--rpp", sw.rpps, "Rays per pixel to sweep, comma-separated")->delimiter(',')->check(CLI::Range(1, 1 << 20));
    app.add_option("--seeds", sw.seeds, "Seeds per setting (--seed, --seed + 1, ...)")->check(CLI::Range(1, 1000));
    app.add_option("--samplers", text.samplers, "Samplers to sweep, comma-separated")
        ->delimiter(',')
        ->check(CLI::IsMember({"jittered", "regular", "random", "sobol", "sobol2"}));
    app.add_option("--estimators,--estimator", text.estimators,
                   "Diffuse surfaces' estimators to sweep, comma-separated: bounce, nee, mis-balance, mis (vkrt --estimator; "
                   "all have the same expectation, so they share the reference). Default: the renders' default only")
        ->delimiter(',')
        ->check(CLI::IsMember({"bounce", "nee", "mis-balance", "mis"}));
    app.add_option("--targets", sw.targets,
                   "Also adaptive renders (vkrt --target-error, sobol2) at these target errors, comma-separated: a "
                   "series of their own, each point at its mean rpp")
        ->delimiter(',');
    app.add_option("--min-rpp", sw.adaptive.minRpp, "With --targets: every pixel's first round (even)")
        ->default_val(sw.adaptive.minRpp);
    app.add_option("--max-rpp", sw.adaptive.maxRpp, "With --targets: no pixel gets more samples (even)")
        ->default_val(sw.adaptive.maxRpp);
    app.add_option("--device", text.device, "Devices to sweep: gpu, cpu or both")->check(CLI::IsMember({"gpu", "cpu", "both"}));
    app.add_option("--reference-rpp", sw.referenceRpp, "Rays per pixel of the converged reference (sobol; even: two halves estimate its noise)")
        ->check(CLI::Range(2, 1 << 24));
    app.add_option("--reference-device", text.referenceDevice,
                   "Device for the reference (default: gpu when sweeping the gpu, else cpu)")
        ->check(CLI::IsMember({"gpu", "cpu"}));
    app.add_option("--cache", text.cache, "Reference cache directory (default: $XDG_CACHE_HOME/vkrt or ~/.cache/vkrt)");
    app.add_option("--target-rmse", sw.targetRmse, "Target RMSE for the report's cheapest setting")
        ->check(CLI::PositiveNumber);
}

// The flags of the course's handleGraphicsArgs (umdcs4212/starterCode src/handleGraphicsArgs.cpp)
// that have no vkrt spelling of their own; -i -o -w -h -n -r -k are aliases of vkrt's options.
struct CourseText {
    std::optional<double> aspect;
    std::string split;
    std::optional<int> windowWidth, windowHeight;
};

void addCourseOptions(CLI::App& app, CommandLine& cl, CourseText& course) {
    app.add_option("-a,--aspect", course.aspect,
                   "Aspect ratio width/height, the course's -a: sets the side not given, height = round(width / R) "
                   "(width: -w or 250), or width = round(height * R) when only -h is given; with both -w and -h it "
                   "must match them")
        ->check(CLI::Range(1.0 / (1 << 16), double(1 << 16)));
    app.add_flag("-v,--verbose", cl.verbose, "Print the settings before running (the course's verbose output)")
        ->excludes("--quiet");
    app.add_option("-d,--depth,--focus-distance", cl.focusDistance,
                   "Depth of field: the distance along the view direction that is in focus (the course's -d; 0 = "
                   "pinhole). Overrides the camera's focusDistance; needs an aperture (--aperture or the scene's)")
        ->check(CLI::NonNegativeNumber)
        ->check(kFiniteFloat);
    app.add_option("--aperture", cl.aperture,
                   "Depth of field: the lens diameter in scene units (0 = pinhole). Overrides the camera's aperture")
        ->check(CLI::NonNegativeNumber)
        ->check(kFiniteFloat);
    app.add_option("-s,--split", course.split,
                   "The course's BVH split method: accepted and ignored, vkrt always builds binned-SAH BVHs (docs/BVH.md)");
    app.add_option("-x,--winwidth", course.windowWidth,
                   "The course's preview window width: accepted and ignored, vkrt has no preview window")
        ->check(CLI::PositiveNumber);
    app.add_option("-y,--winheight", course.windowHeight,
                   "The course's preview window height: accepted and ignored, vkrt has no preview window")
        ->check(CLI::PositiveNumber);
}

// -a R fixes the side the command line leaves open, so the image is R times as wide as it is high
// (the camera's image plane follows the pixel grid, docs/XML_FORMAT.md §3.3). Both sides given: R must
// agree with them up to the rounding of one side, otherwise the command line contradicts itself.
void applyAspect(RenderOptions& render, double aspect, bool widthGiven, bool heightGiven) {
    const std::string flag = "-a " + number(aspect);
    const auto side = [&](double exact, const char* name) {
        const long rounded = std::lround(exact);
        if (rounded < 1 || rounded > (1 << 16))
            throw CLI::ValidationError(flag, std::string("gives an image ") + name + " of " + number(exact) +
                                                 " pixels, outside 1..65536");
        return static_cast<int>(rounded);
    };
    const int w = render.width, h = render.height;
    if (widthGiven && heightGiven) {
        if (h != std::lround(w / aspect) && w != std::lround(h * aspect))
            throw CLI::ValidationError(flag, "contradicts -w " + std::to_string(w) + " -h " + std::to_string(h) +
                                                 " (aspect " + number(double(w) / h) +
                                                 "); give -a with only one of -w and -h, or leave -a out");
    } else if (heightGiven) {
        render.width = side(h * aspect, "width");
    } else {
        render.height = side(w / aspect, "height");
    }
}

// After parsing: resolve -a, and say which course flags vkrt cannot honour.
void applyCourseOptions(const CLI::App& app, CommandLine& cl, const CourseText& course) {
    // -i and the positional scene fill one field: a second scene would be dropped without a word.
    const std::size_t scenes = app.count("-i") + app.count("scene");
    if (scenes > 1) {
        std::string names;
        for (const char* name : {"-i", "scene"})
            for (const std::string& s : app.get_option(name)->as<std::vector<std::string>>())
                names += (names.empty() ? "'" : ", '") + s + "'";
        throw CLI::ValidationError("scene", std::to_string(scenes) + " scene files given (" + names +
                                                "); vkrt renders one scene per run");
    }
    if (course.aspect) applyAspect(cl.render, *course.aspect, app.count("-w") > 0, app.count("-h") > 0);
    if (app.count("-s") > 0)
        cl.notices.push_back("-s " + course.split + " ignored: vkrt always builds binned-SAH BVHs (docs/BVH.md), "
                             "the split method is not selectable");
    if (course.windowWidth)
        cl.notices.push_back("-x " + std::to_string(*course.windowWidth) +
                             " ignored: it sizes the course's preview window, and vkrt has none (it writes the image only)");
    if (course.windowHeight)
        cl.notices.push_back("-y " + std::to_string(*course.windowHeight) +
                             " ignored: it sizes the course's preview window, and vkrt has none (it writes the image only)");
}

// --target-error / --time: adaptive sampling, and the options it cannot go with.
void applyAdaptiveOptions(const CLI::App& app, CommandLine& cl, std::optional<double> targetError, std::optional<double> seconds) {
    cl.adaptiveSampling = targetError || seconds;
    const char* adaptiveOnly[] = {"--min-rpp", "--max-rpp", "--error-map", "--sample-map"};
    if (!cl.adaptiveSampling) {
        for (const char* name : adaptiveOnly)
            if (app.count(name) > 0)
                throw CLI::ValidationError(name, "belongs to adaptive sampling: add --target-error E or --time SECONDS");
        return;
    }
    const char* flag = targetError ? "--target-error" : "--time";
    cl.adaptive.targetError = targetError;
    cl.adaptive.seconds = seconds;
    try {
        adaptive::checkAdaptiveOptions(cl.adaptive);
    } catch (const std::invalid_argument& e) {
        throw CLI::ValidationError(e.what());  // the message names the option and its value
    }
    if (app.count("--rpp") > 0)
        throw CLI::ValidationError("--rpp", std::string("sets one count for every pixel; ") + flag +
                                                " chooses each pixel's: bound it with --min-rpp and --max-rpp");
    // The first N samples of a pixel must be those of an N-rpp render, and its two halves
    // independent: jittered and regular strata depend on the rpp, plain sobol's halves are one net.
    if (app.count("--sampler") == 0) cl.render.sampler = SamplerKind::Sobol2;
    if (cl.render.sampler != SamplerKind::Sobol2 && cl.render.sampler != SamplerKind::Random)
        throw CLI::ValidationError("--sampler", samplerName(cl.render.sampler) + " with " + flag +
                                                    ": adaptive sampling needs sobol2 (its default) or random, whose first N "
                                                    "samples of a pixel are an N-rpp render's and whose even and odd samples "
                                                    "are independent (docs/SAMPLING.md §7)");
    if (cl.watch)
        for (const char* map : {"--error-map", "--sample-map"})
            if (app.count(map) > 0)
                throw CLI::ValidationError(map, "--watch writes the image only; write the maps with a render without --watch");
    if (cl.parts > 0)
        throw CLI::ValidationError("--part", std::string("adaptive sampling (") + flag +
                                                 ") decides each pixel's samples from the whole image; render it in one process");
    cl.render.samplesPerPixel = static_cast<int>(cl.adaptive.maxRpp);
}

}  // namespace

std::string describeSettings(const CommandLine& cl) {
    const RenderOptions& r = cl.render;
    std::ostringstream out;
    out << "scene: " << cl.scenePath << "\n";
    if (cl.command == Command::Render) out << "output: " << cl.outputPath << "\n";
    if (cl.command == Command::Compare) out << "heat map: " << (cl.heatMapPath.empty() ? "none" : cl.heatMapPath) << "\n";
    if (cl.command == Command::Sweep) out << "sweep out: " << cl.sweep.outDir << "\n";
    out << "image: " << r.width << "x" << r.height << " (aspect " << number(double(r.width) / r.height) << ")\n";
    if (cl.adaptiveSampling) {
        out << "adaptive sampling: " << samplerName(r.sampler) << ", " << cl.adaptive.minRpp << "-" << cl.adaptive.maxRpp << " rpp";
        if (cl.adaptive.targetError) out << ", target error " << *cl.adaptive.targetError;
        if (cl.adaptive.seconds) out << ", time " << *cl.adaptive.seconds << " s";
        out << "\n";
    } else if (cl.command != Command::Sweep) {
        out << "rays per pixel: " << r.samplesPerPixel << " (" << samplerName(r.sampler) << ")\n";
    }
    if (cl.command != Command::Sweep) out << "estimator: " << estimatorName(r.estimator) << "\n";
    if (cl.command == Command::Sweep) {
        out << "estimators:";
        for (Estimator e : cl.sweep.estimators) out << " " << estimatorName(e);
        out << "\n";
    }
    out << "recursion depth: " << r.maxDepth << "\n";
    if (cl.focusDistance) out << "focus distance: " << *cl.focusDistance << "\n";
    if (cl.aperture) out << "aperture: " << *cl.aperture << "\n";
    if (cl.up) out << "up: " << cl.up->x << "," << cl.up->y << "," << cl.up->z << "\n";
    if (cl.exposure != 0.0f) out << "exposure: " << number(cl.exposure) << " stops (x" << number(std::exp2(cl.exposure)) << ")\n";
    if (r.shutter) out << "shutter: " << r.shutter->x << "," << r.shutter->y << "\n";
    out << "CPU threads: " << (r.threads == 0 ? std::string("all cores") : std::to_string(r.threads)) << "\n";
    out << "seed: " << r.seed << "\n";
    if (cl.command != Command::Sweep)
        out << "device: " << (cl.device == DeviceChoice::Cpu ? "cpu" : cl.device == DeviceChoice::Gpu ? "gpu" : "auto") << "\n";
    return out.str();
}

namespace {

// vkrt convert IN -o OUT: the scene read in one format and written in the other (or the same).
ParseResult parseConvert(std::vector<std::string> args) {
    CommandLine cl;
    cl.command = Command::Convert;
    CLI::App app{"vkrt convert: read a course scene (XML or JSON) and write it in the format -o's extension names "
                 "(.json: the course's current JSON form; .xml: the course's XML form). The written file is loaded "
                 "back and must give the same scene model, or nothing is written (docs/SCENE_CONVERSION.md).",
                 "vkrt convert"};
    app.set_help_flag("-?,--help", "Print this help and exit");
    app.add_option("scene", cl.scenePath, "Scene file to read: .xml or .json");
    app.add_option("-i,--input,--inputfile", cl.scenePath, "Scene file to read (the course's spelling)");
    app.add_option("-o,--output,--outputfile", cl.outputPath, "Scene file to write: .json or .xml")->required();
    app.add_flag("--strict", cl.strict, "Treat the input's warnings as errors");
    app.add_flag("-q,--quiet", cl.render.quiet, "No summary line or warnings (errors are always printed)");
    addInputLimitOption(app);
    try {
        std::vector<std::string> reversed(args.rbegin(), args.rend());
        app.parse(reversed);
        if (app.count("-i") + app.count("scene") > 1)
            throw CLI::ValidationError("scene", "two scene files given; vkrt convert reads one (-o names the output)");
        if (cl.scenePath.empty()) throw CLI::RequiredError("a scene file to read (vkrt convert in.xml -o out.json)");
        if (cl.outputPath.empty()) throw CLI::ValidationError("-o", "the output path is empty (give out.json or out.xml)");
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return {std::nullopt, code == 0 ? 0 : 2};
    }
    return {cl, 0};
}

// vkrt merge PART.exr... -o OUT: the parts of one render (--part I/N), put together.
ParseResult parseMerge(std::vector<std::string> args) {
    CommandLine cl;
    cl.command = Command::Merge;
    CLI::App app{"vkrt merge: put the parts of one render (vkrt scene --part I/N -o part_I.exr, one process per part) "
                 "together into the image a single process would have written, byte for byte",
                 "vkrt merge"};
    app.set_help_flag("-?,--help", "Print this help and exit");
    app.add_option("parts", cl.mergeInputs, "The parts' EXR files, in any order (every part exactly once)")->required();
    app.add_option("-o,--output", cl.outputPath, "Image to write: .png, .exr, .jpg or .ppm")->required();
    app.add_flag("-q,--quiet", cl.render.quiet, "No summary line");
    addInputLimitOption(app);
    try {
        std::vector<std::string> reversed(args.rbegin(), args.rend());
        app.parse(reversed);
        if (cl.outputPath.empty()) throw CLI::ValidationError("-o", "the output path is empty (give out.png)");
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return {std::nullopt, code == 0 ? 0 : 2};
    }
    return {cl, 0};
}

}  // namespace

ParseResult parseCommandLine(int argc, const char* const* argv) {
    resetInputLimits();  // each command line starts from the defaults (several are parsed in one test process)
    CommandLine cl;
    std::vector<std::string> args(argv + 1, argv + argc);
    if (!args.empty() && args[0] == "convert") return parseConvert({args.begin() + 1, args.end()});
    if (!args.empty() && args[0] == "merge") return parseMerge({args.begin() + 1, args.end()});
    if (!args.empty() && (args[0] == "compare" || args[0] == "sweep" || args[0] == "check")) {
        cl.command = args[0] == "compare" ? Command::Compare : args[0] == "check" ? Command::Check : Command::Sweep;
        args.erase(args.begin());
    }
    const bool compare = cl.command == Command::Compare;
    const bool sweep = cl.command == Command::Sweep;
    const bool check = cl.command == Command::Check;

    CLI::App app{check ? "vkrt check: is your image the same picture as vkrt's render of the scene? Renders the scene "
                         "on the CPU reference at your image's size and tests every pixel against the render's own "
                         "noise; names the common mistake (flipped, gamma, background, a light missing...) that "
                         "explains a difference. Writes IMAGE_vkrt_reference.png and IMAGE_vkrt_diff.png beside your "
                         "image. Exit code 0: same picture, 3: different.\nUsage: vkrt check scene.xml yours.png [options]"
                 : compare ? "vkrt compare: render a scene on the GPU and on the CPU reference with the same seed and "
                           "report how far apart the images are (--stat: different seeds and a z-test)"
                 : sweep ? "vkrt sweep: measure error against a converged reference and render time over samplers, rays "
                           "per pixel, seeds and devices; writes DIR/sweep.csv, DIR/error_vs_*.png and DIR/report.md"
                         : "vkrt: a Vulkan compute-shader ray tracer for the UMD course scene format.\n"
                           "Usage: vkrt scene.xml [options]  |  vkrt compare scene.xml [options]  |  "
                           "vkrt check scene.xml yours.png  |  vkrt sweep scene.xml --out DIR [options]  |  vkrt convert in.xml -o out.json  |  vkrt --list-devices",
                 check ? "vkrt check" : compare ? "vkrt compare" : sweep ? "vkrt sweep" : "vkrt"};
    app.set_help_flag("-?,--help", "Print this help and exit (-h is the height, as in the course)");
    app.set_version_flag("--version", versionLine(), "Print vkrt's version (and the git commit it was built from) and exit");
    app.option_defaults()->always_capture_default();
    std::string bg, sampler = "jittered", device = "auto";
    std::optional<double> targetError, timeBudget;  // --target-error, --time
    SweepText sweepText;
    if (sweep) {
        addSweepOptions(app, cl, bg, sweepText);
    } else {
        addRenderOptions(app, cl, bg, sampler, device);
    }
    CourseText course;
    addCourseOptions(app, cl, course);
    bool listDevices = false;
    if (check) {
        app.add_option("image", cl.imagePath, "Your image of the scene (.png, .jpg, .ppm or .exr)")->required();
        addExposureOption(app, cl, "Your image was made at this exposure: vkrt's render is scaled by 2^EV before the test");
    } else if (compare) {
        app.add_option("-o,--output", cl.heatMapPath,
                       "Difference heat map image with its legend in /255 (with --stat the z map); none is written "
                       "without -o. Exit code 3 when the images fail the agreement rule (or --stat's z-test)");
        app.add_flag("--stat", cl.statistical,
                     "Statistical comparison: GPU (seed + 1, -r rpp) vs a CPU reference (seed, 16x the rpp, at least "
                     "256) by a per-pixel z-test against the CPU's sample variance (alpha 0.01, Sidak; pass when "
                     ">= 99.75% of values pass; exit code 3 on failure)");
        app.add_flag("--keep", cl.keepRenders,
                     "Also write both renders, SCENE_gpu.png and SCENE_cpu.png, beside the heat map (or in the "
                     "working folder)")
            ->excludes("--stat");
    } else if (!sweep) {
        app.add_option("-o,--output,--outputfile", cl.outputPath, "Output image: .png, .exr (linear float), .jpg or .ppm");
        app.add_option_function<std::string>(
            "--part",
            [&cl](const std::string& text) {
                int part = 0, parts = 0;
                char extra = 0;
                if (std::sscanf(text.c_str(), "%d/%d%c", &part, &parts, &extra) != 2 || parts < 1 || part < 1 || part > parts)
                    throw CLI::ValidationError("--part", "'" + text + "': expected I/N with 1 <= I <= N (e.g. 2/4)");
                cl.part = part;
                cl.parts = parts;
            },
            "Render part I of N (I/N, 1-based) of the image's rows into an EXR (-o part_I.exr); `vkrt merge` "
            "puts the N parts together into the image one process would have written, byte for byte");
        app.add_flag("--list-devices", listDevices, "List the Vulkan devices and exit");
        app.add_flag("--watch", cl.watch,
                     "Keep running: render again whenever the scene, a mesh or texture it reads, or (with --shader-dir, "
                     "on the GPU) a GLSL file changes; print each render's times or error; Ctrl-C stops");
        app.add_option("--preview", cl.previewPort,
                       "With --watch: serve a page on http://127.0.0.1:PORT/ showing the latest image and the last "
                       "error, refreshed as renders finish (0: any free port, printed)")
            ->check(CLI::Range(0, 65535))
            ->default_str("none");
        app.add_option("--target-error", targetError,
                       "Adaptive sampling: render in rounds until the image's estimated relative RMSE (RMSE over pixels "
                       "and channels / mean luminance, docs/SAMPLING.md §7) is at most E (>= 1e-4), samples going where "
                       "the noise is; deterministic. Uses --sampler sobol2 unless random is given");
        app.add_option("--time", timeBudget,
                       "Adaptive sampling: render in rounds for about SECONDS of render time (with --target-error: "
                       "whichever comes first); the only input that makes an image differ between runs");
        app.add_option("--min-rpp", cl.adaptive.minRpp, "Adaptive sampling: every pixel's first round (even)")
            ->default_val(cl.adaptive.minRpp);
        app.add_option("--max-rpp", cl.adaptive.maxRpp, "Adaptive sampling: no pixel gets more samples (even)")
            ->default_val(cl.adaptive.maxRpp);
        app.add_option("--error-map", cl.errorMapPath,
                       "Adaptive sampling: write each pixel's estimated standard error (per channel, linear) to this "
                       "image (.exr keeps the floats)");
        app.add_option("--sample-map", cl.sampleMapPath,
                       "Adaptive sampling: write each pixel's sample count to this image: .exr the counts as floats, "
                       ".png/.jpg/.ppm a heat map with its legend");
        addExposureOption(app, cl,
                          "Scale the image by 2^EV before it is written (EV in stops: 1 doubles it, -1 halves it), in "
                          "every format: PNG/JPEG/PPM then clamp to [0,1] and truncate to 8 bits (no gamma), EXR stays "
                          "linear floats. Applies to each --progressive pass, --watch output and --part (merge copies it)");
        app.add_option("--progressive", cl.render.checkpoints,
                       "Write the image N times as the samples come in (after 1/N, 2/N, ... of the rpp), so a long "
                       "render shows early; the last is the same image as without it")
            ->check(CLI::Range(1, 1 << 16));
    }

    try {
        std::vector<std::string> reversed(args.rbegin(), args.rend());
        app.parse(reversed);
        if (listDevices) {
            cl.command = Command::ListDevices;
            return {cl, 0};
        }
        applyCourseOptions(app, cl, course);
        if (cl.parts > 0) {
            if (cl.parts > cl.render.height)
                throw CLI::ValidationError("--part", std::to_string(cl.parts) + " parts of a " + std::to_string(cl.render.height) +
                                                         "-row image would leave some parts without a row");
            std::string ext = std::filesystem::path(cl.outputPath).extension().string();
            for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            if (ext != ".exr")
                throw CLI::ValidationError("--part", "a part is written as EXR (linear float, with its rows), not '" +
                                                         (cl.outputPath.empty() ? std::string("the default .png") : cl.outputPath) +
                                                         "': give -o part_" + std::to_string(cl.part) + ".exr");
            cl.render.rows = partRows(cl.render.height, cl.part, cl.parts);
        }
        if (cl.previewPort >= 0 && !cl.watch)
            throw CLI::ValidationError("--preview", "shows the renders of --watch: add --watch (vkrt --watch scene.xml --preview 8080)");
        if (cl.parts > 0 && (cl.watch || cl.render.checkpoints > 1))
            throw CLI::ValidationError(cl.watch ? "--watch" : "--progressive",
                                       "writes the whole image from one process; a --part is one process's share of it");
        if (check) {
            for (const char* size : {"--width", "--height", "--aspect"})
                if (app.count(size) > 0)
                    throw CLI::ValidationError(size, "check renders at your image's size: leave -w, -h and -a out");
            for (const char* gpu : {"--device", "--gpu", "--general-kernel", "--gpu-kernel", "--shader-dir"})
                if (app.count(gpu) > 0)
                    throw CLI::ValidationError(gpu, "check renders its reference on the CPU (it needs each pixel's "
                                                    "sample variance): leave it out");
            if (app.count("--rpp") == 0) cl.render.samplesPerPixel = kCheckReferenceRpp;
        }
        if (!compare && !sweep && !check && app.count("--output") > 0 && cl.outputPath.empty())
            throw CLI::ValidationError("-o", "the output path is empty (give a file name such as out.png, or leave -o out)");
        if (cl.scenePath.empty()) throw CLI::RequiredError("a scene file (vkrt scene.xml)");
        if (cl.referenceLook) applyReferenceLook(cl.render);  // before --bg, which overrides its colour
        if (!bg.empty()) cl.render.background = parseColour(bg);
        cl.render.sampler = parseSampler(sampler);  // CLI11 checked the name
        if (!compare && !sweep && !check) applyAdaptiveOptions(app, cl, targetError, timeBudget);
        cl.device = device == "cpu" ? DeviceChoice::Cpu : device == "gpu" ? DeviceChoice::Gpu : DeviceChoice::Auto;
        if (sweep) {
            study::SweepOptions& sw = cl.sweep;
            sw.scenePath = cl.scenePath;
            sw.outDir = sweepText.out;
            sw.cacheDir = sweepText.cache;
            sw.samplers.clear();
            for (const std::string& name : sweepText.samplers) sw.samplers.push_back(parseSampler(name));
            sw.estimators.clear();
            for (const std::string& name : sweepText.estimators) sw.estimators.push_back(parseEstimator(name));
            sw.devices.clear();
            if (sweepText.device != "cpu") sw.devices.push_back(study::Device::Gpu);
            if (sweepText.device != "gpu") sw.devices.push_back(study::Device::Cpu);
            if (!sweepText.referenceDevice.empty())
                sw.referenceDevice = sweepText.referenceDevice == "gpu" ? study::Device::Gpu : study::Device::Cpu;
        }
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return {std::nullopt, code == 0 ? 0 : 2};
    }

    const std::string stem = std::filesystem::path(cl.scenePath).stem().string();
    if (cl.outputPath.empty()) cl.outputPath = stem + ".png";
    return {cl, 0};
}

}  // namespace vkrt
