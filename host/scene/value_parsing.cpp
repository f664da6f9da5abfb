#include "value_parsing.h"

#include "local_origin.h"
#include "number_text.h"
#include "scene_rules.h"

namespace vkrt {

namespace {

// Reads `Count` floats from `text` (number_text.h). Messages are issued against `owner`'s line
// with `element` as the element name (an attribute reports "<scene> bgColor", for example).
template <int Count>
NumberText readFloats(const ParseContext& context, pugi::xml_node owner, const std::string& element,
                                const std::string& text) {
    const NumberText numbers = readNumberText(text, Count);
    if (!numbers.error.empty()) {
        Issue issue = context.issueAt(owner, numbers.error, numbers.errorValue);
        issue.element = element;
        throw SceneError(std::move(issue));
    }
    if (numbers.irregular) {
        Issue issue = context.issueAt(owner, irregularNumberProblem(numbers, Count), text);
        issue.element = element;
        context.warn(std::move(issue));
    }
    return numbers;
}

}  // namespace

float parseScalar(const ParseContext& context, pugi::xml_node element) {
    return readFloats<1>(context, element, element.name(), elementText(element)).values[0];
}

glm::vec3 parseVec3(const ParseContext& context, pugi::xml_node element, glm::dvec3* exact) {
    const NumberText numbers = readFloats<3>(context, element, element.name(), elementText(element));
    if (exact) *exact = {numbers.exact[0], numbers.exact[1], numbers.exact[2]};
    return {numbers.values[0], numbers.values[1], numbers.values[2]};
}

glm::vec3 parsePosition(const ParseContext& context, pugi::xml_node element, bool world) {
    if (!world || !context.localOrigin) return parseVec3(context, element);
    glm::dvec3 exact;
    parseVec3(context, element, &exact);
    const std::optional<glm::vec3> local = rules::localPosition(exact, context.origin);
    if (!local) context.fail(element, rules::kBeyondFloatLocally, elementText(element));
    return *local;
}

glm::vec3 parseColour(const ParseContext& context, pugi::xml_node element) {
    const glm::vec3 colour = parseVec3(context, element);
    if (const std::string p = rules::negativeColourProblem(colour); !p.empty()) context.warn(element, p, elementText(element));
    return colour;
}

glm::vec3 parseVec3Text(const ParseContext& context, pugi::xml_node owner, const std::string& label,
                        const std::string& text) {
    const NumberText numbers = readFloats<3>(context, owner, label, text);
    return {numbers.values[0], numbers.values[1], numbers.values[2]};
}

}  // namespace vkrt
