#include "camera_parsing.h"

#include <cmath>
#include <string_view>

#include "value_parsing.h"

namespace vkrt {

namespace {
bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
}  // namespace

Camera parseCamera(const ParseContext& context, pugi::xml_node node) {
    checkAttributes(context, node, {"type"});
    checkChildren(context, node, {"position", "viewDir", "lookatPoint", "focalLength", "imagePlaneWidth"});
    Camera camera;
    camera.name = node.attribute("name").value();
    camera.where = {context.source.path(), context.source.lineOf(node)};

    const std::string_view type = node.attribute("type").value();
    if (type == "orthographic") {
        camera.type = CameraType::Orthographic;
    } else if (!type.empty() && type != "perspective") {
        context.warn(node, "unknown camera type, using perspective", std::string(type));
    }

    camera.position = parseVec3(context, requireChild(context, node, "position"));
    const pugi::xml_node viewDir = node.child("viewDir");
    const pugi::xml_node lookatPoint = node.child("lookatPoint");
    if (!viewDir && !lookatPoint) context.fail(node, "missing required element <viewDir> (or <lookatPoint>)");
    // viewDir is parsed even when lookatPoint overrides it, so garbage in it is still reported.
    const glm::vec3 direction = viewDir ? parseVec3(context, viewDir) : glm::vec3(0.0f);
    if (lookatPoint) {
        camera.gaze = parseVec3(context, lookatPoint) - camera.position;
        if (camera.gaze == glm::vec3(0.0f) || !isFinite(camera.gaze))
            context.fail(lookatPoint, "lookatPoint must differ from the camera position", elementText(lookatPoint));
    } else {
        camera.gaze = direction;
        if (camera.gaze == glm::vec3(0.0f)) context.fail(viewDir, "view direction has zero length", elementText(viewDir));
    }

    if (const pugi::xml_node f = node.child("focalLength")) {
        camera.focalLength = parseScalar(context, f);
        if (camera.type == CameraType::Perspective && !(camera.focalLength > 0.0f))
            context.fail(f, "focal length must be positive", elementText(f));
    }
    if (const pugi::xml_node w = node.child("imagePlaneWidth")) {
        camera.imagePlaneWidth = parseScalar(context, w);
        if (!(camera.imagePlaneWidth > 0.0f)) context.fail(w, "image plane width must be positive", elementText(w));
    }
    return camera;
}

}  // namespace vkrt
