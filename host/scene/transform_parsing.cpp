#include "transform_parsing.h"

#include <string>
#include <string_view>

#include "scene_rules.h"
#include "value_parsing.h"

namespace vkrt {

glm::mat4 parseTransform(const ParseContext& context, pugi::xml_node transform) {
    checkAttributes(context, transform, {});
    glm::mat4 m(1.0f);
    for (pugi::xml_node step : transform.children()) {
        if (step.type() != pugi::node_element) continue;
        const std::string_view kind = step.name();
        if (kind == "translate") {
            checkAttributes(context, step, {});
            m = m * rules::translation(parseVec3(context, step));
        } else if (kind == "scale") {
            checkAttributes(context, step, {});
            const glm::vec3 s = parseVec3(context, step);
            if (const std::string p = rules::scaleProblem(s); !p.empty()) context.fail(step, p, elementText(step));
            m = m * rules::scaling(s);
        } else if (kind == "rotate") {
            checkAttributes(context, step, {"axis"});
            const std::string axisName = requireAttribute(context, step, "axis");
            const std::optional<int> axis = rules::rotationAxis(axisName);
            if (!axis) context.fail(step, rules::kBadRotationAxis, axisName);
            m = m * rules::axisRotation(*axis, static_cast<double>(parseScalar(context, step)));
        } else {
            context.warn(step, "unknown element inside <transform>, ignored");
        }
    }
    return m;
}

}  // namespace vkrt
