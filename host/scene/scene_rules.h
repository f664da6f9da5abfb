// What makes a scene valid, written once for both formats: the type names each format spells
// the same way, the checks on values (radius > 0, a non-zero view direction, ...) and the texts of
// the messages. Each check returns the problem (empty when the value is fine); the XML and JSON
// loaders report it at their own element or key, quoting the value as the file wrote it, so both
// formats refuse and warn about exactly the same things (README.md "Errors", "Warnings").
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "scene.h"

namespace vkrt::rules {

// --- cameras ---
std::optional<CameraType> cameraType(std::string_view name);  // perspective, orthographic
// Each type parser's names, for "did you mean" after an unknown one (name_suggestion.h).
std::vector<std::string_view> cameraTypeNames();
inline constexpr const char* kUnknownCameraType = "unknown camera type, using perspective";
std::string viewDirProblem(const glm::vec3& viewDir);
std::string lookatProblem(const glm::vec3& gaze);  // gaze = lookatPoint - position
std::string focalLengthProblem(CameraType type, float focalLength);
std::string imagePlaneWidthProblem(float width);
// Depth of field: each must be >= 0 (0: the pinhole); one without the other is a warning.
std::string focusDistanceProblem(float distance);
std::string apertureProblem(float aperture);
inline constexpr const char* kLensWithoutBoth =
    "depth of field needs both a focus distance and an aperture above 0; the camera stays a pinhole";
// After the checks above: a gaze whose largest component lies outside [2^-16, 2^16] is scaled by a
// power of two (exact, so its direction does not change) into [1, 2), and so is a perspective
// camera's (focalLength, imagePlaneWidth) pair, which only their ratio matters for. The renderers
// normalise in float, where |v|^2 of viewDir 0 0 -1e-25 underflows and focalLength 1e20 overflows
// (both rendered pure background). Scenes inside the range are left bit for bit as they were.
void conditionCamera(Camera& camera);
// focalLength / imagePlaneWidth above 2^22: neighbouring pixels' directions differ by less than
// float resolves, so the image is one colour. A warning (the image is what float can show).
std::string narrowFieldProblem(const Camera& camera);
// The first camera named `name` (XML <sceneParameters><camera>, JSON sceneParameters.camera).
std::optional<int> cameraByName(const Scene& scene, const std::string& name);
inline constexpr const char* kUnknownCameraName = "no camera of that name";

// --- lights ---
std::optional<LightType> lightType(std::string_view name);  // point, area
std::vector<std::string_view> lightTypeNames();  // and "shape", which the loaders read before lightType
inline constexpr const char* kUnknownLightType = "unknown light type, light skipped";
// The unit area-light normal, or nullopt for a zero (or non-finite) length.
std::optional<glm::vec3> unitNormal(const glm::vec3& normal);
inline constexpr const char* kZeroNormal = "normal has zero length";
// Area-light width and length: zero is allowed (a 0x0 area light is exactly its point light,
// docs/RENDERING.md, so a light can shrink to nothing without being rewritten).
std::string lightSizeProblem(float size);

// --- shaders ---
// A shader type as a file spells it. Phong is BlinnPhong; the JSON-era Diffuse is Lambertian with
// diffuseBounce, Emitter is Lambertian with an emission (scene.h, shader_emitters.h).
struct ShaderTypeName {
    ShaderType type = ShaderType::Lambertian;
    const char* display = "Lambertian";  // the name messages use
    bool diffuseBounce = false;
    bool emitter = false;
};
std::optional<ShaderTypeName> shaderType(std::string_view name);
std::vector<std::string_view> shaderTypeNames();
inline constexpr const char* kUnknownShaderType = "unknown shader type, using Lambertian with its diffuse colour";
// Every parameter any shader type reads (the XML element names, the JSON keys).
const std::vector<std::string_view>& shaderParameters();
std::vector<std::string_view> shaderParametersUsedBy(const ShaderTypeName& type);
std::string unusedParameterProblem(const ShaderTypeName& type);  // "not used by a Mirror shader, ignored"
std::string nonNegativeProblem(float value);                    // phongExp, roughness
std::string refractiveIndexProblem(float value);
// attenuationCoef is a transmittance per unit distance, raised to the path length: a negative
// component has no meaning and makes pow() of a negative base, NaN on the CPU and undefined in GLSL.
std::string attenuationProblem(const glm::vec3& value);
// Values the course's files give and its renderers took as they were, so a warning each, the value
// kept: a negative colour component (diffuse, specular, intensity, background, emission; pt_test.xml's
// redMat is -11.04 12.04 12.04) subtracts light; a mirrorCoef outside [0, 1] extrapolates the blend.
// Neither can make a NaN (no root, log or power of them is taken).
std::string negativeColourProblem(const glm::vec3& colour);
std::string mirrorCoefProblem(float value);
// The colour of a used-diffuse shader that gives neither a colour nor a texture; white under a
// texture (so the texture shows as it is).
inline constexpr float kMissingDiffuseGrey = 0.5f;
// A shape's (or instance's, or shape light's) reference to a shader the file never defines.
inline constexpr const char* kUnresolvedShader = "unresolved shader reference, shown as a grey Lambertian placeholder";
// After parsing: 2011/12 files write a mirrored Blinn-Phong as BlinnPhong + mirrorCoef > 0.
void resolveLegacyShaderType(Shader& shader);

// --- shapes ---
std::optional<ShapeType> shapeType(std::string_view name);  // sphere, box, triangle, mesh
// With `instance`, also "instance": a shape's type (placing a prototype), not a prototype's.
std::vector<std::string_view> shapeTypeNames(bool instance);
inline constexpr const char* kUnknownShapeType = "unknown shape type, skipped";
std::vector<std::string_view> geometryKeys(ShapeType type); // center radius | minPt maxPt | v0 v1 v2 | file
std::string radiusProblem(float radius);
// minPt > maxPt on an axis (LittleOfEverything.json's `4.5.0` gives one): the corners are swapped
// on each such axis, so the box is the one the two corners span, as a slab test that orders its
// two distances reads it. Returns the warning naming the axes, "" when the corners were in order.
std::string orderBoxCorners(glm::vec3& minPt, glm::vec3& maxPt);
bool isDegenerateTriangle(const glm::vec3& v0, const glm::vec3& v1, const glm::vec3& v2);
// A prototype definition (XML <instance>, JSON instance[]), as both formats register it: the first
// definition of a name is kept (Duplicate), and an unknown type registers the name as skipped (-1)
// so its instances are skipped with a warning; Added means the next prototype index is the name's.
enum class PrototypeDefinition { Added, Duplicate, UnknownType };
PrototypeDefinition definePrototypeName(std::map<std::string, int>& indexByName, const std::string& name,
                                        std::optional<ShapeType> type, int nextIndex);
inline constexpr const char* kDuplicatePrototype = "duplicate instance name, the first definition is kept";
inline constexpr const char* kUnknownPrototype = "unknown prototype type, skipped";
inline constexpr const char* kDegenerateTriangle = "degenerate triangle (zero area), it is never hit";

// --- transforms: M = T0 * T1 * ... * Tn-1, so the last listed operation acts first ---
// 0, 1 or 2 for an axis named by its first character, X, Y or Z in any case (LIB-2012 compares
// the first character only).
std::optional<int> rotationAxis(std::string_view axis);
inline constexpr const char* kBadRotationAxis = "axis must be X, Y or Z, not";
glm::mat4 axisRotation(int axis, double degrees);
glm::mat4 translation(const glm::vec3& t);
glm::mat4 scaling(const glm::vec3& s);
std::string scaleProblem(const glm::vec3& s);  // a zero factor: the renderers need M^-1
glm::mat4 stepMatrix(const TransformStep& step);
// M = I * T0 * T1 * ... multiplied left to right, the order both loaders always used.
glm::mat4 composeTransform(const std::vector<TransformStep>& steps);
// What the BVH builder would refuse later as "instance N", said at the transform with its line: an
// entry beyond float (repeated scales overflow), or no inverse that float holds (they underflow).
std::string composedTransformProblem(const glm::mat4& objectToWorld);

// A transform as read: the steps as the file lists them (what a written scene gives back) and the
// matrix placing the object in the model's world (composeTransform(steps), or under
// LoadOptions::localOrigin local_origin.h's placeRelativeTo).
struct Placement {
    std::vector<TransformStep> steps;
    glm::mat4 objectToWorld{1.0f};
    // Motion blur: the pose at the end of the motion (XML <transformEnd>, JSON xformEnd).
    bool moving = false;
    std::vector<TransformStep> stepsEnd;
    glm::mat4 objectToWorldEnd{1.0f};
};

// Why an object cannot move rigidly from `start` to `end` (each already a valid transform), or
// "": one mirrors the object and the other does not, so the stretch between them would pass
// through a singular matrix (docs/RENDERING.md §9).
std::string motionProblem(const glm::mat4& start, const glm::mat4& end);

// The instance takes the placement's pose(s).
void placeInstance(Instance& instance, const Placement& placement);

// A plain shape: in Scene::shapes, or, when the file gives it a transform (`placement` not null),
// a prototype of its own placed by one instance, so the renderers keep one transformed-shape path.
void addPlainShape(Scene& scene, Shape shape, const Placement* placement);

// --- files named by the scene ---
// `relative` resolved against the scene file's directory (meshes, textures, environment maps).
std::string resolveScenePath(const std::filesystem::path& sceneDirectory, const std::string& relative);
std::string missingTextureProblem(const std::string& loadError, const std::string& textureName);

}  // namespace vkrt::rules
