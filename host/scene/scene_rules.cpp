#include "scene_rules.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>

namespace vkrt::rules {

namespace {
// A type name as files spell it and what it reads as: one table per kind gives both the parser and
// the names a typo is compared with (name_suggestion.h).
template <typename T>
using NameTable = std::vector<std::pair<std::string_view, T>>;

template <typename T>
std::optional<T> lookUp(const NameTable<T>& table, std::string_view name) {
    for (const auto& [spelling, value] : table)
        if (spelling == name) return value;
    return std::nullopt;
}

template <typename T>
std::vector<std::string_view> namesOf(const NameTable<T>& table) {
    std::vector<std::string_view> names;
    for (const auto& entry : table) names.push_back(entry.first);
    return names;
}

const NameTable<CameraType> kCameraTypes = {{"perspective", CameraType::Perspective},
                                            {"orthographic", CameraType::Orthographic}};
const NameTable<LightType> kLightTypes = {{"point", LightType::Point}, {"area", LightType::Area}};
const NameTable<ShaderTypeName> kShaderTypes = {
    {"Lambertian", {ShaderType::Lambertian, "Lambertian"}},
    {"Diffuse", {ShaderType::Lambertian, "Diffuse", /*diffuseBounce=*/true}},
    {"BlinnPhong", {ShaderType::BlinnPhong, "BlinnPhong"}},
    {"Phong", {ShaderType::BlinnPhong, "BlinnPhong"}},
    {"Mirror", {ShaderType::Mirror, "Mirror"}},
    {"Glaze", {ShaderType::Glaze, "Glaze"}},
    {"BlinnPhongMirrored", {ShaderType::BlinnPhongMirrored, "BlinnPhongMirrored"}},
    {"Dielectric", {ShaderType::Dielectric, "Dielectric"}},
    {"CoolToWarm", {ShaderType::CoolToWarm, "CoolToWarm"}},
    {"Emitter", {ShaderType::Lambertian, "Emitter", false, /*emitter=*/true}}};
const NameTable<ShapeType> kShapeTypes = {
    {"sphere", ShapeType::Sphere}, {"box", ShapeType::Box}, {"triangle", ShapeType::Triangle}, {"mesh", ShapeType::Mesh}};
}  // namespace

std::optional<CameraType> cameraType(std::string_view name) { return lookUp(kCameraTypes, name); }
std::vector<std::string_view> cameraTypeNames() { return namesOf(kCameraTypes); }

std::string viewDirProblem(const glm::vec3& viewDir) {
    return viewDir == glm::vec3(0.0f) ? "view direction has zero length" : "";
}

std::string lookatProblem(const glm::vec3& gaze) {
    const bool finite = std::isfinite(gaze.x) && std::isfinite(gaze.y) && std::isfinite(gaze.z);
    return gaze == glm::vec3(0.0f) || !finite ? "lookatPoint must differ from the camera position" : "";
}

std::string focalLengthProblem(CameraType type, float focalLength) {
    return type == CameraType::Perspective && !(focalLength > 0.0f) ? "focal length must be positive" : "";
}

std::string imagePlaneWidthProblem(float width) { return !(width > 0.0f) ? "image plane width must be positive" : ""; }
std::string focusDistanceProblem(float distance) {
    return !(distance >= 0.0f) ? "focus distance must not be negative (0 is the pinhole)" : "";
}
std::string apertureProblem(float aperture) {
    return !(aperture >= 0.0f) ? "aperture (the lens diameter) must not be negative (0 is the pinhole)" : "";
}

namespace {
// The power of two that brings `largest` (> 0, finite) into [1, 2); 1 inside [2^-16, 2^16]. In
// double: a subnormal float's scale (up to 2^149) does not fit a float.
double conditioningScale(float largest) {
    if (largest >= 0x1p-16f && largest <= 0x1p16f) return 1.0;
    int exponent = 0;
    std::frexp(largest, &exponent);  // largest = m * 2^exponent, m in [0.5, 1)
    return std::ldexp(1.0, 1 - exponent);
}
}  // namespace

// Products by a power of two are exact in double, and so is the conversion back (the result is
// a normal float in [1, 2) or below it by the components' ratios).
void conditionCamera(Camera& camera) {
    const glm::vec3 g = glm::abs(camera.gaze);
    camera.gaze = glm::vec3(glm::dvec3(camera.gaze) * conditioningScale(std::max(g.x, std::max(g.y, g.z))));
    if (camera.type != CameraType::Perspective) return;
    const double scale = conditioningScale(std::max(camera.focalLength, camera.imagePlaneWidth));
    camera.focalLength = static_cast<float>(camera.focalLength * scale);
    camera.imagePlaneWidth = static_cast<float>(camera.imagePlaneWidth * scale);
}

std::string narrowFieldProblem(const Camera& camera) {
    return camera.type == CameraType::Perspective && camera.focalLength / camera.imagePlaneWidth > 0x1p22f
               ? "the field of view is narrower than float directions resolve (focalLength / imagePlaneWidth above 2^22): every pixel shows the same colour"
               : "";
}

std::optional<int> cameraByName(const Scene& scene, const std::string& name) {
    for (std::size_t i = 0; i < scene.cameras.size(); ++i)
        if (scene.cameras[i].name == name) return static_cast<int>(i);
    return std::nullopt;
}

std::optional<LightType> lightType(std::string_view name) { return lookUp(kLightTypes, name); }
std::vector<std::string_view> lightTypeNames() {
    std::vector<std::string_view> names = namesOf(kLightTypes);
    names.push_back("shape");
    return names;
}

std::optional<glm::vec3> unitNormal(const glm::vec3& normal) {
    const float length = glm::length(normal);
    if (!(length > 0.0f) || !std::isfinite(length)) return std::nullopt;
    // A normal already unit to float precision is kept as it is: dividing it by its rounded length
    // can move a last bit, so a written scene (vkrt convert) would not load back the same. The float
    // quotient below has |n|^2 within about 7 * 2^-24 of 1 (the length's and the division's
    // roundings), inside this bound of 16 * 2^-24, so the rule is idempotent.
    const double lengthSquared = glm::dot(glm::dvec3(normal), glm::dvec3(normal));
    if (std::abs(lengthSquared - 1.0) < 0x1p-20) return normal;
    return normal / length;
}

std::string lightSizeProblem(float size) { return !(size >= 0.0f) ? "must not be negative" : ""; }

std::optional<ShaderTypeName> shaderType(std::string_view name) { return lookUp(kShaderTypes, name); }
std::vector<std::string_view> shaderTypeNames() { return namesOf(kShaderTypes); }

const std::vector<std::string_view>& shaderParameters() {
    static const std::vector<std::string_view> all = {"diffuse",   "diffusetex",      "specular",        "phongExp",
                                                      "mirrorCoef", "roughness",      "refractiveIndex", "attenuationCoef",
                                                      "emission"};
    return all;
}

std::vector<std::string_view> shaderParametersUsedBy(const ShaderTypeName& type) {
    if (type.emitter) return {"emission"};
    switch (type.type) {
        case ShaderType::Lambertian:
        case ShaderType::CoolToWarm: return {"diffuse", "diffusetex"};
        // BlinnPhong keeps mirrorCoef/roughness: mirrorCoef > 0 makes it BlinnPhongMirrored.
        case ShaderType::BlinnPhong:
        case ShaderType::BlinnPhongMirrored:
            return {"diffuse", "diffusetex", "specular", "phongExp", "mirrorCoef", "roughness"};
        case ShaderType::Mirror: return {"roughness"};
        case ShaderType::Glaze: return {"diffuse", "diffusetex", "mirrorCoef", "roughness"};
        // roughness: glossy translucency, the refracted direction perturbed as gloss perturbs the
        // reflected one (vkrt's addition, issue 21).
        case ShaderType::Dielectric: return {"refractiveIndex", "attenuationCoef", "roughness"};
    }
    return {};
}

std::string unusedParameterProblem(const ShaderTypeName& type) {
    return std::string("not used by a ") + type.display + " shader, ignored";
}

std::string negativeColourProblem(const glm::vec3& colour) {
    return colour.x < 0.0f || colour.y < 0.0f || colour.z < 0.0f
               ? "a negative colour component, kept as given (it subtracts light, as in the course's renderers)"
               : "";
}

std::string mirrorCoefProblem(float value) {
    return value < 0.0f || value > 1.0f ? "mirrorCoef outside 0..1, kept as given (the reflection blend extrapolates)" : "";
}

std::string nonNegativeProblem(float value) { return value < 0.0f ? "must not be negative" : ""; }

std::string refractiveIndexProblem(float value) { return !(value > 0.0f) ? "must be positive" : ""; }

std::string attenuationProblem(const glm::vec3& value) {
    return value.x < 0.0f || value.y < 0.0f || value.z < 0.0f
               ? "must not be negative (a transmittance per unit distance, from 0 = opaque to 1 = clear)"
               : "";
}

void resolveLegacyShaderType(Shader& shader) {
    if (shader.type == ShaderType::BlinnPhong && shader.mirrorCoef > 0.0f) shader.type = ShaderType::BlinnPhongMirrored;
}

std::optional<ShapeType> shapeType(std::string_view name) { return lookUp(kShapeTypes, name); }
std::vector<std::string_view> shapeTypeNames(bool instance) {
    std::vector<std::string_view> names = namesOf(kShapeTypes);
    if (instance) names.push_back("instance");
    return names;
}

std::vector<std::string_view> geometryKeys(ShapeType type) {
    switch (type) {
        case ShapeType::Sphere: return {"center", "radius"};
        case ShapeType::Box: return {"minPt", "maxPt"};
        case ShapeType::Triangle: return {"v0", "v1", "v2"};
        case ShapeType::Mesh: return {"file"};
    }
    return {};
}

std::string radiusProblem(float radius) { return !(radius > 0.0f) ? "radius must be positive" : ""; }

std::string orderBoxCorners(glm::vec3& minPt, glm::vec3& maxPt) {
    std::string axes;
    for (int axis = 0; axis < 3; ++axis) {
        if (!(minPt[axis] > maxPt[axis])) continue;
        std::swap(minPt[axis], maxPt[axis]);
        axes += std::string(axes.empty() ? "" : " and ") + "xyz"[axis];
    }
    if (axes.empty()) return "";
    return "greater than maxPt on the " + axes + " axis, read with the corners swapped there";
}

PrototypeDefinition definePrototypeName(std::map<std::string, int>& indexByName, const std::string& name,
                                        std::optional<ShapeType> type, int nextIndex) {
    if (indexByName.count(name)) return PrototypeDefinition::Duplicate;
    indexByName[name] = type ? nextIndex : -1;
    return type ? PrototypeDefinition::Added : PrototypeDefinition::UnknownType;
}

bool isDegenerateTriangle(const glm::vec3& v0, const glm::vec3& v1, const glm::vec3& v2) {
    return glm::length(glm::cross(v1 - v0, v2 - v0)) == 0.0f;
}

std::optional<int> rotationAxis(std::string_view axis) {
    if (axis.empty()) return std::nullopt;
    switch (std::toupper(static_cast<unsigned char>(axis[0]))) {
        case 'X': return 0;
        case 'Y': return 1;
        case 'Z': return 2;
        default: return std::nullopt;
    }
}

// Right-handed rotation about a coordinate axis (as glm::rotate). Sine and cosine are taken in
// double from the angle reduced modulo 360, so 90 degrees gives a cosine of ~1e-17 rather than
// float's -4e-8, and angles like 4500 (pt_test.xml) lose no precision.
glm::mat4 axisRotation(int axis, double degrees) {
    const double radians = std::fmod(degrees, 360.0) * (3.14159265358979323846 / 180.0);
    const float c = static_cast<float>(std::cos(radians));
    const float s = static_cast<float>(std::sin(radians));
    const int a = (axis + 1) % 3;  // the rotation maps axis a towards axis b
    const int b = (axis + 2) % 3;
    glm::mat4 r(1.0f);
    r[a][a] = c;   // glm is column-major: r[column][row]
    r[a][b] = s;
    r[b][a] = -s;
    r[b][b] = c;
    return r;
}

glm::mat4 translation(const glm::vec3& t) { return glm::translate(glm::mat4(1.0f), t); }

glm::mat4 scaling(const glm::vec3& s) { return glm::scale(glm::mat4(1.0f), s); }

std::string scaleProblem(const glm::vec3& s) {
    return s.x == 0.0f || s.y == 0.0f || s.z == 0.0f ? "a zero scale factor makes the transform singular" : "";
}

glm::mat4 stepMatrix(const TransformStep& step) {
    switch (step.kind) {
        case TransformKind::Translate: return translation(step.amount);
        case TransformKind::Scale: return scaling(step.amount);
        case TransformKind::Rotate: return axisRotation(step.axis, static_cast<double>(step.amount.x));
    }
    return glm::mat4(1.0f);
}

glm::mat4 composeTransform(const std::vector<TransformStep>& steps) {
    glm::mat4 m(1.0f);
    for (const TransformStep& step : steps) m = m * stepMatrix(step);
    return m;
}

std::string composedTransformProblem(const glm::mat4& objectToWorld) {
    const glm::dmat4 m(objectToWorld);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return "the composed transform overflows float (its steps multiply beyond 3.4e38)";
    const double det = glm::determinant(glm::dmat3(m));
    if (det == 0.0 || !std::isfinite(1.0 / det)) return "the composed transform is singular in float (its steps shrink it to nothing)";
    const glm::dmat4 inverse = glm::inverse(m);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!(std::abs(inverse[c][r]) <= std::numeric_limits<float>::max()))
                return "the composed transform's inverse overflows float (its steps shrink it below 3e-39)";
    return "";
}

std::string motionProblem(const glm::mat4& start, const glm::mat4& end) {
    const double a = glm::determinant(glm::dmat3(glm::dmat4(start)));
    const double b = glm::determinant(glm::dmat3(glm::dmat4(end)));
    if ((a < 0.0) == (b < 0.0)) return "";
    return std::string("the end transform ") + (b < 0.0 ? "mirrors the object and the start transform does not"
                                                        : "does not mirror the object and the start transform does") +
           ": no rigid motion joins them (the stretch would pass through a singular matrix)";
}

void placeInstance(Instance& instance, const Placement& placement) {
    instance.steps = placement.steps;
    instance.objectToWorld = placement.objectToWorld;
    instance.moving = placement.moving;
    instance.stepsEnd = placement.stepsEnd;
    instance.objectToWorldEnd = placement.objectToWorldEnd;
}

void addPlainShape(Scene& scene, Shape shape, const Placement* placement) {
    if (!placement) {
        scene.shapes.push_back(std::move(shape));
        return;
    }
    Instance instance;
    instance.name = shape.name;
    instance.prototype = static_cast<int>(scene.prototypes.size());
    placeInstance(instance, *placement);
    instance.ownPrototype = true;
    instance.where = shape.where;
    scene.prototypes.push_back(std::move(shape));
    scene.instances.push_back(std::move(instance));
}

std::string resolveScenePath(const std::filesystem::path& sceneDirectory, const std::string& relative) {
    return (sceneDirectory / relative).lexically_normal().string();
}

std::string missingTextureProblem(const std::string& loadError, const std::string& textureName) {
    return loadError + "; shaders using texture '" + textureName + "' show their tint colour";
}

}  // namespace vkrt::rules
