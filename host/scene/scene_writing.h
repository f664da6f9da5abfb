// What the two scene writers (json_writer.h, xml_writer.h) share: numbers that load back as the
// same float, paths relative to the written file, the type and shader names the loaders read
// back as the same model. docs/SCENE_CONVERSION.md states the rules and the one field a write changes.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "scene.h"

namespace vkrt::writing {

// The shortest decimal that both loaders (decimal -> double -> float) read back as `value`, bit
// for bit; 9 significant digits when the shortest one would not survive the double step.
std::string floatText(float value);
std::string vec3Text(const glm::vec3& v);  // "x y z", the form every course file uses

// `path` (as the model stores it, resolved) relative to the folder the scene is written to, so the
// written file finds the same meshes, textures and environment maps; absolute when no relative
// path exists (another drive or root) or when the output folder's path runs through a symbolic
// link (where `..` would not lead back). An environment-map prefix keeps its partial file name.
std::string relativePath(const std::string& path, const std::filesystem::path& outputDirectory);

// The type name a loader reads back as this shader: Diffuse (diffuseBounce), Emitter (emission),
// else the type's own name.
std::string shaderTypeName(const Shader& shader);
// The parameters that type reads, in the order they are written (never the 2012 diffusetex).
std::vector<std::string_view> writtenParameters(const Shader& shader);

// The name each shader is written with: its own, or for a nameless one (XML's inline shaders, a
// JSON "_name": "") "unnamed shader N", N the first number no other shader's name uses.
std::vector<std::string> shaderNames(const Scene& scene);

// A writer writes the file's own coordinates: a scene loaded with LoadOptions::localOrigin holds
// positions relative to its camera and is refused (std::logic_error: the caller loaded it wrong).
void requireFileCoordinates(const Scene& scene);

// The model a written file loads back as: `scene` with the names shaderNames gives and every
// undefined shader's placeholder written as a definition (undefined = false). These are the only
// fields a write changes (docs/SCENE_CONVERSION.md).
Scene asWritten(Scene scene);

// Names a format cannot hold as they are: JSON holds only UTF-8, so there a byte that is not part
// of a valid UTF-8 sequence is written as the four characters \xNN (hex); XML 1.0 holds no control
// character but TAB, LF and CR, so there those are written the same way. Every other name is kept.
enum class NameFormat { Json, Xml };
std::string writableName(const std::string& name, NameFormat format);
bool isValidUtf8(const std::string& text);

// `scene` with every name (cameras, shaders, textures, shapes, prototypes, instances, shape
// lights) made writable; `changed` counts the names that changed. Throws std::runtime_error naming
// both when a changed name becomes another name of its kind (a file would then refer to the wrong one).
Scene withWritableNames(Scene scene, NameFormat format, std::size_t* changed);

std::string_view shapeTypeName(ShapeType type);
std::string_view cameraTypeName(CameraType type);
std::string_view axisName(int axis);  // X, Y, Z

// Scene::prototypes placed through instance ids (written as the format's prototypes), as opposed
// to those that are a transformed plain shape's own (Instance::ownPrototype).
std::vector<bool> namedPrototypes(const Scene& scene);

// The one shape list both formats write, from Scene::shapes (plain) and Scene::instances: each keeps
// its order, and they are interleaved so that meshes come up in Scene::meshes' order, which the
// loaders number by first use (named prototypes first, then shape lights, then the shape list).
struct ShapeSlot {
    bool instance = false;  // Scene::instances[index], else Scene::shapes[index]
    std::size_t index = 0;
};
std::vector<ShapeSlot> shapeOrder(const Scene& scene);

// Scene::lights and the shape lights (Scene::emitters) in the order the file listed them
// (Emitter::lightsBefore), so a written scene loads back with the same indices.
void forEachLightInFileOrder(const Scene& scene, const std::function<void(const Light&)>& light,
                             const std::function<void(const Emitter&)>& emitter);

}  // namespace vkrt::writing
