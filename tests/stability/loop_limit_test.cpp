// The number of lights at its extreme, against lavapipe's loop limiter (issue 5): Mesa before 25
// ends every loop silently after 65,535 passes, counted per group of 8 lanes over all loops of
// the kernel and charged for the slowest lane. One sample here runs the light loop once per point
// light and a shadow-ray traversal per light, so its passes grow with the light count.
//
// Measured on Mesa 22.3.6 with the 32x32, 1 rpp scene below: up to 1,500 lights the GPU image
// equals the CPU's; at 2,000 and more the limiter cuts loops off. Before every loop checked that
// it finished (shaders/budget.glsl), the 2,000-light image came back silently wrong (6% of pixels
// off by more than 2/255; 72% at 6,000) although no lane reached the per-lane LOOP_BUDGET, because
// the group's counter also pays for other lanes' passes and for every loop's exit pass.
#include <cstdint>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "app.h"
#include "both_paths.h"
#include "device_list.h"
#include "gpu_environment.h"
#include "image.h"
#include "scene_accel.h"
#include "scene_building.h"
#include "test_paths.h"
#include "vulkan_errors.h"

namespace vkrt::stability {
namespace {

// A fixed pseudo-random stream (the scene must be the same on every standard library).
struct Lcg {
    std::uint64_t state;
    float next(float lo, float hi) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return lo + (hi - lo) * static_cast<float>(state >> 40) / static_cast<float>(1u << 24);
    }
};

// `lights` point lights of equal share above a ground box and 40 spheres.
Scene manyLights(int lights) {
    Scene scene;
    scene.path = std::to_string(lights) + " point lights (built in code)";
    scene.cameras.push_back(perspective({0.0f, 3.0f, 8.0f}, {0.0f, 0.0f, 0.0f}));
    Lcg rng{12345};
    for (int i = 0; i < lights; ++i) {
        const glm::vec3 p(rng.next(-10.0f, 10.0f), rng.next(2.0f, 10.0f), rng.next(-10.0f, 10.0f));
        scene.lights.push_back(pointLight(p, glm::vec3(1.0f / static_cast<float>(lights))));
    }
    const int white = add(scene, lambertian(glm::vec3(0.8f)));
    scene.shapes.push_back(box({-10.0f, -1.0f, -10.0f}, {10.0f, 0.0f, 10.0f}, white));
    for (int i = 0; i < 40; ++i) {
        const glm::vec3 c(rng.next(-3.0f, 3.0f), rng.next(0.3f, 2.0f), rng.next(-3.0f, 3.0f));
        scene.shapes.push_back(sphere(c, rng.next(0.1f, 0.5f), white));
    }
    return scene;
}

// The same scene as a scene file, for the command line.
std::string sceneFileOf(const Scene& scene) {
    std::ostringstream x;
    auto v = [](const glm::vec3& p) { return std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z); };
    x << "<scene>\n<camera name=\"main\" type=\"perspective\"><position>0 3 8</position><lookatPoint>0 0 0</lookatPoint>"
         "<focalLength>1.0</focalLength><imagePlaneWidth>0.5</imagePlaneWidth></camera>\n"
         "<shader name=\"white\" type=\"Lambertian\"><diffuse>0.8 0.8 0.8</diffuse></shader>\n";
    for (const Light& light : scene.lights)
        x << "<light type=\"point\"><position>" << v(light.position) << "</position><intensity>" << v(light.intensity)
          << "</intensity></light>\n";
    for (const Shape& shape : scene.shapes) {
        if (shape.type == ShapeType::Box)
            x << "<shape type=\"box\"><shader ref=\"white\"/><minPt>" << v(shape.minPt) << "</minPt><maxPt>" << v(shape.maxPt)
              << "</maxPt></shape>\n";
        else
            x << "<shape type=\"sphere\"><shader ref=\"white\"/><center>" << v(shape.center) << "</center><radius>"
              << std::to_string(shape.radius) << "</radius></shape>\n";
    }
    x << "</scene>\n";
    return x.str();
}

// Whether the device is lavapipe from a Mesa before 25, whose loop limiter test_loop_limiter.cpp
// measures. Elsewhere no limiter is expected and the GPU must simply agree with the CPU.
bool hasMesaLoopLimiter(const std::string& deviceName) {
    for (const DeviceInfo& d : listDevices()) {
        if (d.name != deviceName || deviceName.find("llvmpipe") == std::string::npos) continue;
        const std::size_t at = d.driver.find("Mesa ");
        if (at == std::string::npos) return true;  // llvmpipe without a version: assume the old one
        return std::stoi(d.driver.substr(at + 5)) < 25;
    }
    return false;
}

TEST(LoopLimit, ManyLightsBelowTheLimitAgreeWithTheCpu) {
    // 1,000 lights: ~half the passes at which the limiter fired here, so the cut-off check must not
    // raise a false alarm and the image must be the CPU's (the suite's agreement rule, both_paths.h).
    const BothImages im = renderBoth(manyLights(1000), smallOptions(32, 32, 1));
    const Distance d = distance(im.cpu, im.gpu);
    recordRow("1,000 point lights (below lavapipe's loop limit)", d);
    EXPECT_TRUE(agrees(d)) << d.describe();
}

TEST(LoopLimit, ALoopCutOffIsAnErrorNeverAWrongImage) {
    const Scene scene = manyLights(3000);
    const RenderOptions options = smallOptions(32, 32, 1);
    GpuRenderer& gpu = sharedGpu();
    const bool limiter = hasMesaLoopLimiter(gpu.deviceName());
    std::printf("device '%s': Mesa loop limiter %s\n", gpu.deviceName().c_str(), limiter ? "expected" : "not expected");
    try {
        const Image image = gpu.render(GpuRenderer::prepare(scene), options);
        EXPECT_FALSE(limiter) << "lavapipe's limiter cuts this scene's loops off, yet the kernel reported nothing";
        const Distance d = distance(renderCpu(scene, prepareCpuScene(scene), options), image);
        EXPECT_TRUE(agrees(d)) << "the GPU image is wrong without an error: " << d.describe();
    } catch (const GpuKernelError& e) {
        const std::string message = e.what();
        EXPECT_TRUE(limiter) << "a loop was reported cut off on a device without Mesa's limiter: " << message;
        // The per-lane budget is not what caught it: the cut-off check is (see the header comment).
        EXPECT_NE(message.find("cut off"), std::string::npos) << message;
        EXPECT_EQ(message.find(std::to_string(gpu::LOOP_BUDGET)), std::string::npos) << message;
        EXPECT_NE(message.find("at pixel ("), std::string::npos) << message;
    }
}

// `vkrt scene.xml` with --device auto (the default): a kernel error makes it render on the CPU
// reference, whose traversal needs the BVH's CPU copy that a GPU render skips building; the note
// saying so, and under --device gpu (or in `vkrt compare`) the error, name the scene file before
// the pixel. --gpu N
// (the device auto would pick among Vulkan's) keeps auto on Vulkan where lavapipe is the only
// device: without it auto renders on the CPU reference from the start (device_choice.h).
TEST(LoopLimit, TheCommandLineFallsBackToTheCpuOnALoopCutOff) {
    const std::string dir = test::artifactDir();
    const std::string scenePath = dir + "/loop_limit_3000_lights.xml";
    std::ofstream(scenePath) << sceneFileOf(manyLights(3000));
    const std::string gpu = std::to_string(chooseDevice(listDevices(), -1));
    auto run = [&](const std::string& out, const char* device) {
        const char* argv[] = {"vkrt", scenePath.c_str(), "-w", "32", "-h", "32", "-r", "1", "--device", device,
                              "--gpu", gpu.c_str(), "--validate", "-o", out.c_str()};
        return runVkrt(static_cast<int>(std::size(argv)), argv);
    };
    // What the command prints on stderr, with its exit code.
    auto runCapturing = [&](const std::string& out, const char* device, std::string& printed) {
        std::ostringstream err;
        std::streambuf* saved = std::cerr.rdbuf(err.rdbuf());
        const int code = run(out, device);
        std::cerr.rdbuf(saved);
        printed = err.str();
        return code;
    };
    std::string autoPrinted, gpuPrinted;
    ASSERT_EQ(run(dir + "/loop_limit_cpu.exr", "cpu"), 0);
    ASSERT_EQ(runCapturing(dir + "/loop_limit_auto.exr", "auto", autoPrinted), 0);
    const int gpuCode = runCapturing(dir + "/loop_limit_gpu.exr", "gpu", gpuPrinted);
    const Image cpu = readImage(dir + "/loop_limit_cpu.exr");
    const Image automatic = readImage(dir + "/loop_limit_auto.exr");
    if (hasMesaLoopLimiter(sharedGpu().deviceName())) {
        // The fallback ran the CPU reference itself: the same image to the bit.
        EXPECT_EQ(cpu.pixels, automatic.pixels);
        // Both the note and, under --device gpu, the error name the scene file, then the pixel.
        EXPECT_NE(autoPrinted.find("note: " + scenePath + ": the GPU kernel could not compute the image correctly at pixel ("),
                  std::string::npos)
            << autoPrinted;
        EXPECT_NE(autoPrinted.find("rendering on the CPU reference instead"), std::string::npos) << autoPrinted;
        EXPECT_EQ(gpuCode, 1);
        EXPECT_NE(gpuPrinted.find("vkrt: error: " + scenePath + ": the GPU kernel could not compute the image correctly at pixel ("),
                  std::string::npos)
            << gpuPrinted;
        // `vkrt compare` renders on the GPU too, outside the render command's path: app.cpp names the file.
        std::string comparePrinted;
        {
            std::ostringstream err;
            std::streambuf* saved = std::cerr.rdbuf(err.rdbuf());
            const char* argv[] = {"vkrt", "compare", scenePath.c_str(), "-w", "32", "-h", "32", "-r", "1", "--gpu", gpu.c_str()};
            EXPECT_EQ(runVkrt(static_cast<int>(std::size(argv)), argv), 1);
            std::cerr.rdbuf(saved);
            comparePrinted = err.str();
        }
        EXPECT_NE(comparePrinted.find("vkrt: error: " + scenePath + ": the GPU kernel could not compute the image correctly"),
                  std::string::npos)
            << comparePrinted;
    } else {
        EXPECT_EQ(gpuCode, 0) << gpuPrinted;
        const Distance d = distance(cpu, automatic);
        EXPECT_TRUE(agrees(d)) << d.describe();
    }
}

}  // namespace
}  // namespace vkrt::stability
