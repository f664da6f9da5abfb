#include "scene_writing.h"

#include <charconv>
#include <cstdio>
#include <set>
#include <system_error>

#include "scene_rules.h"

namespace vkrt::writing {

namespace {
// What the loaders do with a number's text (number_text.cpp, nlohmann): parse as double, then
// narrow to float.
bool readsBackAs(const char* begin, const char* end, float value) {
    double parsed = 0.0;
    const auto [ptr, error] = std::from_chars(begin, end, parsed);
    return error == std::errc() && ptr == end && static_cast<float>(parsed) == value &&
           std::signbit(static_cast<float>(parsed)) == std::signbit(value);
}
}  // namespace

std::string floatText(float value) {
    char buffer[64];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    if (error == std::errc() && readsBackAs(buffer, end, value)) return std::string(buffer, end);
    // The shortest decimal can lie so near the midpoint between two floats that the double it
    // parses to rounds the other way; 9 digits sit well inside the float's interval.
    const int n = std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(value));
    return std::string(buffer, buffer + n);
}

std::string vec3Text(const glm::vec3& v) { return floatText(v.x) + " " + floatText(v.y) + " " + floatText(v.z); }

std::string relativePath(const std::string& path, const std::filesystem::path& outputDirectory) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path target = fs::absolute(path, ec);
    const fs::path base = fs::absolute(outputDirectory.empty() ? fs::path(".") : outputDirectory, ec);
    if (ec) return path;
    // A prefix such as .../textures/reef_ names no file: relate its folder, keep its file name.
    const fs::path relative = target.parent_path().lexically_normal().lexically_relative(base.lexically_normal());
    if (relative.empty()) return target.lexically_normal().string();
    return (relative / target.filename()).lexically_normal().string();
}

std::string shaderTypeName(const Shader& shader) {
    if (shader.diffuseBounce) return "Diffuse";
    if (shader.emission != glm::vec3(0.0f)) return "Emitter";
    switch (shader.type) {
        case ShaderType::Lambertian: return "Lambertian";
        case ShaderType::BlinnPhong: return "BlinnPhong";
        case ShaderType::Mirror: return "Mirror";
        case ShaderType::Glaze: return "Glaze";
        case ShaderType::BlinnPhongMirrored: return "BlinnPhongMirrored";
        case ShaderType::Dielectric: return "Dielectric";
        case ShaderType::CoolToWarm: return "CoolToWarm";
    }
    return "Lambertian";
}

std::vector<std::string_view> writtenParameters(const Shader& shader) {
    std::vector<std::string_view> written;
    for (std::string_view name : rules::shaderParametersUsedBy(*rules::shaderType(shaderTypeName(shader))))
        if (name != "diffusetex") written.push_back(name);
    return written;
}

std::vector<std::string> shaderNames(const Scene& scene) {
    std::set<std::string> taken;
    for (const Shader& shader : scene.shaders) taken.insert(shader.name);
    std::vector<std::string> names;
    int next = 1;
    for (const Shader& shader : scene.shaders) {
        if (!shader.name.empty()) {
            names.push_back(shader.name);
            continue;
        }
        std::string name;
        do name = "unnamed shader " + std::to_string(next++);
        while (taken.count(name));
        taken.insert(name);
        names.push_back(name);
    }
    return names;
}

Scene asWritten(Scene scene) {
    const std::vector<std::string> names = shaderNames(scene);
    for (std::size_t i = 0; i < names.size(); ++i) {
        scene.shaders[i].name = names[i];
        scene.shaders[i].undefined = false;
    }
    return scene;
}

std::string_view shapeTypeName(ShapeType type) {
    switch (type) {
        case ShapeType::Sphere: return "sphere";
        case ShapeType::Box: return "box";
        case ShapeType::Triangle: return "triangle";
        case ShapeType::Mesh: return "mesh";
    }
    return "sphere";
}

std::string_view cameraTypeName(CameraType type) { return type == CameraType::Orthographic ? "orthographic" : "perspective"; }

std::string_view axisName(int axis) { return axis == 0 ? "X" : axis == 1 ? "Y" : "Z"; }

std::vector<bool> namedPrototypes(const Scene& scene) {
    std::vector<bool> named(scene.prototypes.size(), true);
    for (const Instance& instance : scene.instances)
        if (instance.ownPrototype) named.at(static_cast<std::size_t>(instance.prototype)) = false;
    return named;
}

}  // namespace vkrt::writing
