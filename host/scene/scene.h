// The scene model: a plain description of what a course scene file (XML or JSON) says, after
// parsing and validation (host/scene/scene_loader.h builds it). No GPU or BVH concerns live here.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace vkrt {

// Where something was defined, for error messages ("file:line", "file:line:column" for JSON).
struct SourceLocation {
    std::string file;
    int line = 0;
    int column = 0;  // JSON only (1-based byte column); 0 for XML
};

enum class CameraType { Perspective, Orthographic };

struct Camera {
    std::string name;
    CameraType type = CameraType::Perspective;
    glm::vec3 position{0.0f};
    glm::vec3 gaze{0.0f, 0.0f, -1.0f};  // lookatPoint - position, or viewDir; not normalised, non-zero,
                                        // scaled into float's comfort range (rules::conditionCamera)
    float focalLength = 1.0f;
    float imagePlaneWidth = 0.5f;
    // A thin lens (Cook 1984; docs/RENDERING.md §1): points at focusDistance along the gaze are
    // sharp, and rays leave a disc of diameter `aperture` (scene units) around the eye. 0 and 0
    // (the default) is the pinhole; the lens is used only when both are > 0.
    float focusDistance = 0.0f;
    float aperture = 0.0f;
    // vkrt's addition (XML <up>, JSON "up", --up): the world direction shown at the top of the image,
    // any length, not parallel to the gaze (camera_basis.h: upProblem). None: the course's rule,
    // (0,1,0), or (1,0,0) for a camera looking straight up or down (docs/RENDERING.md §1).
    std::optional<glm::vec3> up;
    bool thinLens() const { return focusDistance > 0.0f && aperture > 0.0f; }
    SourceLocation where;
};

enum class LightType { Point, Area };

struct Light {
    LightType type = LightType::Point;
    glm::vec3 position{0.0f};   // point position, or the area light's centre
    glm::vec3 intensity{1.0f};
    glm::vec3 normal{0.0f, -1.0f, 0.0f};  // area only; unit length
    float width = 0.0f;                   // area only; along the tangent (docs/RENDERING.md §4)
    float length = 0.0f;                  // area only; along the bitangent
    SourceLocation where;
};

// Legacy spellings are resolved by the loader: Phong -> BlinnPhong, BlinnPhong with
// mirrorCoef > 0 -> BlinnPhongMirrored. The JSON-era Diffuse and Emitter types have no type of
// their own yet: see Shader::diffuseBounce and Shader::emission.
enum class ShaderType { Lambertian, BlinnPhong, Mirror, Glaze, BlinnPhongMirrored, Dielectric, CoolToWarm };

constexpr int kNoTexture = -1;

struct Shader {
    std::string name;
    ShaderType type = ShaderType::Lambertian;
    glm::vec3 diffuse{1.0f};
    glm::vec3 specular{0.0f};
    float phongExp = 1.0f;
    float mirrorCoef = 0.0f;
    float roughness = 0.0f;
    float refractiveIndex = 1.0f;
    glm::vec3 attenuation{1.0f};   // transmittance per unit distance
    int diffuseTexture = kNoTexture;   // index into Scene::textures
    int specularTexture = kNoTexture;
    // The course's `Diffuse` (JSON era): a Lambertian that also gathers the light other surfaces
    // scatter (a path-traced diffuse bounce, docs/RENDERING.md §5). type is Lambertian (its
    // parameters and its direct light are Lambertian's); the file said Diffuse.
    bool diffuseBounce = false;
    // An `Emitter` shader's radiance (J26; no course file uses one). type is Lambertian with a
    // black diffuse colour; for renders its shapes become shape emitters (shader_emitters.h).
    glm::vec3 emission{0.0f};
    // The file names this shader but never defines it: a grey Lambertian placeholder
    // (missing_shaders.h). Renderers ignore the flag; vkrt convert says it wrote a definition.
    bool undefined = false;
    SourceLocation where;
};

// An image texture, 8-bit RGBA, row 0 = top row of the file, used linearly.
struct Texture {
    std::string name;
    std::string path;
    int width = 0;
    int height = 0;
    std::vector<std::uint32_t> rgba8;  // width*height texels, r in the low byte
    SourceLocation where;
};

// A triangle mesh loaded from OBJ. Normals are per vertex (generated when the file has none).
struct Mesh {
    std::string path;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;   // same size as positions; unit length, or zero for a vertex
                                      // that touches no non-degenerate face (renderers then use the
                                      // face normal). Generated ones are angle-weighted (mesh_normals.h).
    std::vector<glm::vec2> uvs;       // same size as positions, or empty
    std::vector<glm::uvec3> triangles;
};

enum class ShapeType { Sphere, Box, Triangle, Mesh };

// A geometric shape with its shader. In Scene::shapes it is in world space; in
// Scene::prototypes it is in object space and rendered only through instances.
struct Shape {
    std::string name;
    ShapeType type = ShapeType::Sphere;
    int shader = 0;                   // index into Scene::shaders
    glm::vec3 center{0.0f};           // sphere
    float radius = 1.0f;              // sphere
    glm::vec3 minPt{0.0f}, maxPt{0.0f};  // box
    glm::vec3 v0{0.0f}, v1{0.0f}, v2{0.0f};  // triangle
    int mesh = -1;                    // mesh: index into Scene::meshes
    SourceLocation where;
};

// One operation of a transform as the file lists it. The model keeps the list beside the matrix
// it composes to, so a written scene (vkrt convert) lists the same operations and loads back to the
// same matrix bit for bit, which no decomposition of a sheared matrix could promise.
enum class TransformKind { Translate, Scale, Rotate };

struct TransformStep {
    TransformKind kind = TransformKind::Translate;
    glm::vec3 amount{0.0f};           // translate: offset; scale: factors; rotate: x = degrees
    int axis = 0;                     // rotate: 0 = X, 1 = Y, 2 = Z
};

// A placement of a prototype (`<shape type="instance" id=...>`).
struct Instance {
    std::string name;
    int prototype = 0;                // index into Scene::prototypes
    int shaderOverride = -1;          // index into Scene::shaders, or -1: the prototype's shader
    std::vector<TransformStep> steps; // in file order
    glm::mat4 objectToWorld{1.0f};    // rules::composeTransform(steps): M = T0 * T1 * ... * Tn-1
                                      // (docs/XML_FORMAT.md §3.9)
    // Motion blur (vkrt's addition): the pose at the end of the motion, XML <transformEnd> / JSON
    // xformEnd; objectToWorld is the pose at its start (docs/RENDERING.md §9).
    bool moving = false;
    std::vector<TransformStep> stepsEnd;
    glm::mat4 objectToWorldEnd{1.0f};
    // The file gave a plain shape with a transform, not an instance: the prototype is that shape's
    // own (rules::addPlainShape), and a written scene gives the shape back the same way.
    bool ownPrototype = false;
    SourceLocation where;
};

// A shape that emits light (a JSON `light` of `_type: "shape"`): radiance = the light's intensity.
// The geometry is `shape` (world space when objectToWorld is the identity), or, when prototype
// >= 0, Scene::prototypes[prototype] placed by objectToWorld. Renderers draw it and light the scene
// with it (docs/RENDERING.md §4; host/lighting/emitter_table.h); it never moves.
struct Emitter {
    std::string name;
    glm::vec3 radiance{1.0f};
    Shape shape;                      // unused when prototype >= 0; shape.shader may be -1
    int prototype = -1;               // index into Scene::prototypes, or -1
    std::vector<TransformStep> steps; // as Instance::steps
    glm::mat4 objectToWorld{1.0f};    // rules::composeTransform(steps)
    // Where the file lists it among its lights: after this many of Scene::lights (the writers put
    // it back there: writing::forEachLightInFileOrder). Non-decreasing over Scene::emitters.
    int lightsBefore = 0;
    SourceLocation where;
};

// An environment map: what every ray that leaves the scene sees (docs/RENDERING.md §10), loaded
// from the cube faces or the vertical cross the file names (environment_loading.h). The renderers
// read it through host/lighting (bordered faces, lookup, importance sampling).
struct Environment {
    int faceSize = 0;  // N; 0: no environment map (rays that leave see Scene::background)
    // +X, -X, +Y, -Y, +Z, -Z (cube_map.h's order and OpenGL orientation), N x N texels each, RGBA8
    // with r in the low byte, row 0 = the top row, used linearly (byte / 255) as textures are.
    std::array<std::vector<std::uint32_t>, 6> faces;
    // Cube faces only: whether the -Z file was read mirrored left-right (the course's 2021 face;
    // docs/RENDERING.md §10.2), and the mean seam error (per channel, 0-255) of the -Z face's four
    // edges against its neighbours read each way, from which LoadOptions' default chose. Both
    // errors are 0 when the -Z rule was forced or the map is a vertical cross.
    bool negZMirrored = false;
    double negZSeamErrorAsOpenGL = 0.0;
    double negZSeamErrorMirrored = 0.0;
    SourceLocation where;  // the envMapPrefix / envMapVertCross that named it
};

struct Scene {
    std::string path;                 // the scene file
    // Where the model's coordinates start, in the file's world: every position above is relative
    // to it. Zero (the file's own coordinates) unless loaded with LoadOptions::localOrigin, which
    // puts it at the default camera's eye (local_origin.h).
    glm::dvec3 origin{0.0};
    glm::vec3 background{0.0f};
    // Environment maps as the file names them, resolved against the scene file's directory (the
    // writers and watch mode use these): envMapPrefix names six cube faces `<prefix>posX.png` ...,
    // envMapVertCross one image holding a vertical cross. `environment` is the one loaded
    // (envMapPrefix when both are given); faceSize 0 when neither is.
    std::string envMapPrefix;
    std::string envMapVertCross;
    Environment environment;
    std::vector<Camera> cameras;      // at least one, in file order
    int defaultCamera = 0;            // index into cameras: <sceneParameters><camera>name</camera>, else 0
    std::vector<Light> lights;
    std::vector<Shader> shaders;
    std::vector<Texture> textures;
    std::vector<Mesh> meshes;
    std::vector<Shape> shapes;
    std::vector<Shape> prototypes;
    std::vector<Instance> instances;
    std::vector<Emitter> emitters;
};

}  // namespace vkrt
