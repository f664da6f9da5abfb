#include "value_parsing.h"

#include "number_text.h"
#include "scene_rules.h"

namespace vkrt {

namespace {

// Reads `Count` floats from `text` (number_text.h). Messages are issued against `owner`'s line
// with `element` as the element name (an attribute reports "<scene> bgColor", for example).
template <int Count>
std::array<float, 3> readFloats(const ParseContext& context, pugi::xml_node owner, const std::string& element,
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
    return numbers.values;
}

}  // namespace

float parseScalar(const ParseContext& context, pugi::xml_node element) {
    return readFloats<1>(context, element, element.name(), elementText(element))[0];
}

glm::vec3 parseVec3(const ParseContext& context, pugi::xml_node element) {
    const auto v = readFloats<3>(context, element, element.name(), elementText(element));
    return {v[0], v[1], v[2]};
}

glm::vec3 parseColour(const ParseContext& context, pugi::xml_node element) {
    const glm::vec3 colour = parseVec3(context, element);
    if (const std::string p = rules::negativeColourProblem(colour); !p.empty()) context.warn(element, p, elementText(element));
    return colour;
}

glm::vec3 parseVec3Text(const ParseContext& context, pugi::xml_node owner, const std::string& label,
                        const std::string& text) {
    const auto v = readFloats<3>(context, owner, label, text);
    return {v[0], v[1], v[2]};
}

}  // namespace vkrt
