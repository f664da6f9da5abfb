#include "transform_parsing.h"

#include <string>
#include <string_view>

#include "scene_rules.h"
#include "value_parsing.h"

namespace vkrt {

std::vector<TransformStep> parseTransform(const ParseContext& context, pugi::xml_node transform) {
    checkAttributes(context, transform, {});
    std::vector<TransformStep> steps;
    for (pugi::xml_node step : transform.children()) {
        if (step.type() != pugi::node_element) continue;
        const std::string_view kind = step.name();
        if (kind == "translate") {
            checkAttributes(context, step, {});
            steps.push_back({TransformKind::Translate, parseVec3(context, step), 0});
        } else if (kind == "scale") {
            checkAttributes(context, step, {});
            const glm::vec3 s = parseVec3(context, step);
            if (const std::string p = rules::scaleProblem(s); !p.empty()) context.fail(step, p, elementText(step));
            steps.push_back({TransformKind::Scale, s, 0});
        } else if (kind == "rotate") {
            checkAttributes(context, step, {"axis"});
            const std::string axisName = requireAttribute(context, step, "axis");
            const std::optional<int> axis = rules::rotationAxis(axisName);
            if (!axis) context.fail(step, rules::kBadRotationAxis, axisName);
            steps.push_back({TransformKind::Rotate, glm::vec3(parseScalar(context, step), 0.0f, 0.0f), *axis});
        } else {
            context.warn(step, "unknown element inside <transform>, ignored");
        }
    }
    if (const std::string p = rules::composedTransformProblem(rules::composeTransform(steps)); !p.empty())
        context.fail(transform, p);
    return steps;
}

}  // namespace vkrt
