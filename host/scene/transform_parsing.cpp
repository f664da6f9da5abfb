#include "transform_parsing.h"

#include <string>
#include <string_view>

#include "local_origin.h"
#include "name_suggestion.h"
#include "scene_rules.h"
#include "value_parsing.h"

namespace vkrt {

rules::Placement parseTransform(const ParseContext& context, pugi::xml_node transform) {
    if (transform) checkAttributes(context, transform, {});
    std::vector<TransformStep> steps;
    std::vector<glm::dvec3> exactTranslations;  // one per step, read by translate steps
    for (pugi::xml_node step : transform.children()) {
        if (step.type() != pugi::node_element) continue;
        const std::string_view kind = step.name();
        glm::dvec3 exact(0.0);
        if (kind == "translate") {
            checkAttributes(context, step, {});
            steps.push_back({TransformKind::Translate, parseVec3(context, step, &exact), 0});
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
            context.warn(step, "unknown element inside <transform>, ignored", "", didYouMean(kind, {"translate", "scale", "rotate"}));
            continue;
        }
        exactTranslations.push_back(exact);
    }
    const glm::mat4 objectToWorld = context.localOrigin ? rules::placeRelativeTo(steps, exactTranslations, context.origin)
                                                        : rules::composeTransform(steps);
    if (const std::string p = rules::composedTransformProblem(objectToWorld); !p.empty()) context.fail(transform, p);
    return {std::move(steps), objectToWorld};
}

}  // namespace vkrt
