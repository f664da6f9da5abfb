#include "transform_parsing.h"

#include <cctype>
#include <cmath>
#include <string>
#include <string_view>

#include <glm/gtc/matrix_transform.hpp>

#include "value_parsing.h"

namespace vkrt {

namespace {

// 0, 1 or 2 for the axis attribute.
int rotationAxis(const ParseContext& context, pugi::xml_node rotate) {
    const std::string axis = requireAttribute(context, rotate, "axis");
    // LIB-2012 compares only the first character; lower case is accepted as well.
    switch (std::toupper(static_cast<unsigned char>(axis[0]))) {
        case 'X': return 0;
        case 'Y': return 1;
        case 'Z': return 2;
        default: context.fail(rotate, "axis must be X, Y or Z, not", axis);
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

}  // namespace

glm::mat4 parseTransform(const ParseContext& context, pugi::xml_node transform) {
    checkAttributes(context, transform, {});
    glm::mat4 m(1.0f);
    for (pugi::xml_node step : transform.children()) {
        if (step.type() != pugi::node_element) continue;
        const std::string_view kind = step.name();
        if (kind == "translate") {
            checkAttributes(context, step, {});
            m = m * glm::translate(glm::mat4(1.0f), parseVec3(context, step));
        } else if (kind == "scale") {
            checkAttributes(context, step, {});
            const glm::vec3 s = parseVec3(context, step);
            if (s.x == 0.0f || s.y == 0.0f || s.z == 0.0f)
                context.fail(step, "a zero scale factor makes the transform singular", elementText(step));
            m = m * glm::scale(glm::mat4(1.0f), s);
        } else if (kind == "rotate") {
            checkAttributes(context, step, {"axis"});
            const int axis = rotationAxis(context, step);
            m = m * axisRotation(axis, static_cast<double>(parseScalar(context, step)));
        } else {
            context.warn(step, "unknown element inside <transform>, ignored");
        }
    }
    return m;
}

}  // namespace vkrt
