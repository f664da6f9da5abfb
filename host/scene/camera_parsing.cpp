#include "camera_parsing.h"

#include <string_view>

#include "camera_basis.h"
#include "local_origin.h"
#include "name_suggestion.h"
#include "scene_rules.h"
#include "value_parsing.h"

namespace vkrt {

Camera parseCamera(const ParseContext& context, pugi::xml_node node, glm::dvec3* exactPosition) {
    checkAttributes(context, node, {"type"});
    checkChildren(context, node, {"position", "viewDir", "lookatPoint", "focalLength", "imagePlaneWidth", "focusDistance", "aperture", "up"});
    Camera camera;
    camera.name = node.attribute("name").value();
    camera.where = {context.source.path(), context.source.lineOf(node)};

    const std::string_view type = node.attribute("type").value();
    if (!type.empty()) {
        const std::optional<CameraType> known = rules::cameraType(type);
        if (!known) context.warn(node, rules::kUnknownCameraType, std::string(type), didYouMean(type, rules::cameraTypeNames()));
        camera.type = known.value_or(CameraType::Perspective);
    }

    glm::dvec3 eye;
    camera.position = parseVec3(context, requireChild(context, node, "position"), &eye);
    if (exactPosition) *exactPosition = eye;
    const pugi::xml_node viewDir = node.child("viewDir");
    const pugi::xml_node lookatPoint = node.child("lookatPoint");
    if (!viewDir && !lookatPoint) context.fail(node, "missing required element <viewDir> (or <lookatPoint>)");
    // viewDir is parsed even when lookatPoint overrides it, so garbage in it is still reported.
    const glm::vec3 direction = viewDir ? parseVec3(context, viewDir) : glm::vec3(0.0f);
    if (lookatPoint) {
        glm::dvec3 target;
        const glm::vec3 lookat = parseVec3(context, lookatPoint, &target);
        // Under localOrigin the gaze is the difference of the file's numbers, taken in double (far
        // from the origin the two floats would have lost it); otherwise the floats' difference.
        camera.gaze = lookat - camera.position;
        if (context.localOrigin) {
            const std::optional<glm::vec3> gaze = rules::localPosition(target, eye);
            if (!gaze) context.fail(lookatPoint, rules::kBeyondFloatLocally, elementText(lookatPoint));
            camera.gaze = *gaze;
        }
        if (const std::string p = rules::lookatProblem(camera.gaze); !p.empty()) context.fail(lookatPoint, p, elementText(lookatPoint));
    } else {
        camera.gaze = direction;
        if (const std::string p = rules::viewDirProblem(camera.gaze); !p.empty()) context.fail(viewDir, p, elementText(viewDir));
    }

    // After the gaze, which an up vector must not be parallel to (camera_basis.h).
    if (const pugi::xml_node up = node.child("up")) {
        camera.up = parseVec3(context, up);
        if (const std::string p = upProblem(*camera.up, camera.gaze); !p.empty()) context.fail(up, p, elementText(up));
    }
    if (const pugi::xml_node f = node.child("focalLength")) {
        camera.focalLength = parseScalar(context, f);
        if (const std::string p = rules::focalLengthProblem(camera.type, camera.focalLength); !p.empty())
            context.fail(f, p, elementText(f));
    }
    if (const pugi::xml_node w = node.child("imagePlaneWidth")) {
        camera.imagePlaneWidth = parseScalar(context, w);
        if (const std::string p = rules::imagePlaneWidthProblem(camera.imagePlaneWidth); !p.empty())
            context.fail(w, p, elementText(w));
    }
    const pugi::xml_node focus = node.child("focusDistance");
    if (focus) {
        camera.focusDistance = parseScalar(context, focus);
        if (const std::string p = rules::focusDistanceProblem(camera.focusDistance); !p.empty()) context.fail(focus, p, elementText(focus));
    }
    const pugi::xml_node aperture = node.child("aperture");
    if (aperture) {
        camera.aperture = parseScalar(context, aperture);
        if (const std::string p = rules::apertureProblem(camera.aperture); !p.empty()) context.fail(aperture, p, elementText(aperture));
    }
    if ((camera.focusDistance > 0.0f) != (camera.aperture > 0.0f))
        context.warn(camera.aperture > 0.0f ? aperture : focus, rules::kLensWithoutBoth, camera.name);
    rules::conditionCamera(camera);
    if (const std::string p = rules::narrowFieldProblem(camera); !p.empty()) context.warn(node, p, camera.name);
    return camera;
}

}  // namespace vkrt
