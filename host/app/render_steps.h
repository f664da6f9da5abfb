// The steps of a render that the commands share (a plain render, an MPI rank, watch mode, compare):
// load the scene with its warnings printed, open the device, prepare and render on it.
#pragma once

#include <chrono>
#include <memory>
#include <string>

#include "command_line.h"
#include "diagnostics.h"
#include "gpu_renderer.h"
#include "kernel_error.h"
#include "image.h"
#include "render_options.h"
#include "scene.h"
#include "scene_accel.h"

namespace vkrt {

double secondsSince(std::chrono::steady_clock::time_point start);

// The scene's warnings on stderr, one line per distinct one (Diagnostics::summary); none under -q.
// Errors are never silenced, and under --strict a warning is an error that never reaches here.
void printWarnings(const Diagnostics& diagnostics, bool quiet);

// Loads the scene, prints its warnings, settles which camera renders and applies the command
// line's lens (-d, --aperture) to it.
Scene loadWithWarnings(CommandLine& cl);
// Throws std::runtime_error when `output` is a file the loaded scene reads (its scene file, a
// mesh, a texture, an environment map face: scene_inputs.h), naming which; loadWithWarnings calls it
// for -o and compare's heat map.
void checkNotASceneInput(const std::string& output, const Scene& scene);

GpuRendererOptions gpuOptions(const CommandLine& cl);

// An option only the GPU renderer has (--gpu N, --shader-dir, --general-kernel, --validate): under
// --device auto it asks for Vulkan whatever the devices are (device_choice.h).
bool asksForVulkan(const CommandLine& cl);

struct DeviceRender {
    Image image;
    std::string device;           // the device, and on the GPU the kernel variant that ran
    double prepareSeconds = 0.0;  // the renderer's own tree and tables
    double seconds = 0.0;         // the render itself
    double pipelineSeconds = 0.0; // GPU: creating and first dispatching the kernel variant (the
                                  // driver's compile; 0 when it was made before)
    bool onGpu = false;           // rendered by the GpuRenderer (the summary then names the compile)
};

// Each renderer prepares the scene its own way (its own tree) and renders it; the Prepared forms
// take what an earlier prepare made (watch mode keeps it while only shaders change).
DeviceRender renderOnCpu(const Scene& scene, const RenderOptions& options);
DeviceRender renderOnGpu(GpuRenderer& gpu, const Scene& scene, const RenderOptions& options, const GpuRenderSettings& settings);
DeviceRender renderPreparedOnCpu(const Scene& scene, const SceneAccel& accel, const RenderOptions& options);
DeviceRender renderPreparedOnGpu(GpuRenderer& gpu, const GpuSceneData& data, const RenderOptions& options,
                                 const GpuRenderSettings& settings);
// The kernel the command line asks for (--general-kernel, --gpu-kernel).
GpuRenderSettings gpuSettingsOf(const CommandLine& cl);

// --device auto: the GPU when a usable Vulkan device is a GPU (device_choice.h), else nullptr (the
// CPU reference) with a note, also when no Vulkan device opens; --gpu N: that device, falling back
// likewise; --device cpu: nullptr; --device gpu: a Vulkan device of any type, or the error.
std::unique_ptr<GpuRenderer> openGpu(const CommandLine& cl);

// The float RGB image every renderer returns: a lower bound on what a render needs.
long long imageMiB(int width, int height);

// Refuses, before the scene is loaded, an image whose pixels alone exceed this machine's memory
// (or the process's address-space limit, ulimit -v, when that is lower).
void checkImageFitsInMemory(int width, int height);

// Before the render, so that a long render is not thrown away for a bad -o.
void checkOutputBeforeRendering(const std::string& output, const std::string& scenePath);

// Load, pick the device, render: what one process or one MPI rank does. A GPU kernel that refuses
// the scene falls back to the CPU reference under --device auto.
DeviceRender renderScene(CommandLine& cl);

// A GPU kernel's refusal of a scene (GpuKernelError: it names the pixel and sample) with the scene
// file named: the error that stands under --device gpu (app.cpp, watch mode's log), and under
// --device auto the note that the CPU reference renders it instead.
GpuKernelError kernelErrorIn(const std::string& scenePath, const GpuKernelError& e);
void noteCpuFallback(const std::string& scenePath, const GpuKernelError& e);

}  // namespace vkrt
