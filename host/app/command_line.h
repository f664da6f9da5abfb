// The vkrt command line: `vkrt scene.xml [options]`, `vkrt compare scene.xml [options]`,
// `vkrt check scene.xml image.png`, `vkrt convert in.xml -o out.json`, `vkrt --list-devices`, `vkrt --version`, plus every flag of the course's handleGraphicsArgs (-i -o -w -h -a -n -r -k
// -v -s -x -y -?; -d is refused until depth of field exists).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "adaptive_render.h"
#include "render_options.h"
#include "sweep.h"

namespace vkrt {

enum class Command { Render, Compare, Check, Sweep, Convert, Merge, ListDevices };
enum class DeviceChoice { Auto, Cpu, Gpu };

struct CommandLine {
    Command command = Command::Render;
    std::string scenePath;
    std::string outputPath;       // default: <scene name>.png in the current directory; convert: required
    RenderOptions render;
    bool strict = false;
    DeviceChoice device = DeviceChoice::Auto;
    int gpuIndex = -1;            // -1: best device
    bool validate = false;        // Vulkan validation layers
    std::string shaderDir;        // compile kernels from this GLSL tree at run time
    bool general = false;         // GPU: run the general kernel instead of the scene-specialised one
    std::string gpuKernel = "auto";  // GPU: --gpu-kernel auto, megakernel or wavefront (GpuKernel)
    std::string heatMapPath;      // compare -o: difference heat map; empty: none written
    std::optional<int> camera;    // --camera; default: the scene's <sceneParameters><camera>, else the first
    bool statistical = false;     // compare --stat: z-test of GPU and CPU renders with different seeds
    bool keepRenders = false;     // compare --keep: write both renders beside the heat map
    std::string imagePath;        // check: the image to judge against vkrt's render of the scene
    bool referenceLook = false;   // --look reference: applyReferenceLook (render_options.h)
    study::SweepOptions sweep;    // sweep: everything but the render options above (copied in by the parser)
    bool verbose = false;         // -v: print the settings before running (the course's verbose output)
    // Depth of field (-d/--focus-distance, --aperture): override the rendered camera's values.
    std::optional<float> focusDistance, aperture;
    std::optional<glm::vec3> up;  // --up x,y,z: the rendered camera's up vector (docs/RENDERING.md §1)
    std::vector<std::string> notices;  // one line per course flag accepted but ignored, and why
    // --part I/N (1-based): this process renders the rows of part I of N into an EXR that
    // `vkrt merge` combines (image_parts.h); 0/0 when the whole image is rendered.
    int part = 0, parts = 0;
    std::vector<std::string> mergeInputs;  // vkrt merge: the parts' files
    bool watch = false;           // --watch: render again whenever an input changes (watch_mode.h)
    int previewPort = -1;         // --preview PORT (with --watch): the page on 127.0.0.1; -1: none, 0: any port
    float exposure = 0.0f;        // --exposure EV: the written image is scaled by 2^EV (exposure.h)
    // --target-error / --time: adaptive sampling (adaptive_render.h) instead of a uniform --rpp.
    bool adaptiveSampling = false;
    adaptive::AdaptiveOptions adaptive;
    std::string errorMapPath;     // --error-map: each pixel's estimated standard error (adaptive)
    std::string sampleMapPath;    // --sample-map: each pixel's sample count (adaptive)
};

// The settings a run will use, one per line (what -v prints).
std::string describeSettings(const CommandLine& cl);

// Parses argv. Returns the command line, or the exit code to stop with (0 after --help,
// 2 after a usage error; the message has been printed).
struct ParseResult {
    std::optional<CommandLine> commandLine;
    int exitCode = 0;
};
ParseResult parseCommandLine(int argc, const char* const* argv);

}  // namespace vkrt
