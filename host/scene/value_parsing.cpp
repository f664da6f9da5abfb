#include "value_parsing.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

namespace vkrt {

namespace {

bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

// The whitespace-separated token around `pos`, for messages.
std::string tokenAround(const std::string& text, std::size_t pos) {
    std::size_t begin = pos;
    while (begin > 0 && !isSpace(text[begin - 1])) --begin;
    std::size_t end = pos;
    while (end < text.size() && !isSpace(text[end])) ++end;
    return text.substr(begin, end - begin);
}

std::string describe(const float* values, int count) {
    std::string out;
    for (int i = 0; i < count; ++i) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%g", static_cast<double>(values[i]));
        if (i > 0) out += ' ';
        out += buffer;
    }
    return out;
}

// Reads `count` floats from `text` like `stream >> a >> b >> c` would, but refuses what the stream
// would have turned into garbage. Messages are issued against `owner`'s line with `element` as the
// element name (an attribute reports "<scene> bgColor", for example).
template <int Count>
std::array<float, Count> readFloats(const ParseContext& context, pugi::xml_node owner, const std::string& element,
                                    const std::string& text) {
    auto fail = [&](std::string problem, std::string value) {
        Issue issue = context.issueAt(owner, std::move(problem), std::move(value));
        issue.element = element;
        throw SceneError(std::move(issue));
    };
    const std::string expected = Count == 1 ? "1 number" : std::to_string(Count) + " numbers";

    std::array<float, Count> values{};
    bool irregular = false;  // something istream would have read differently from a plain list
    std::size_t pos = 0;
    for (int i = 0; i < Count; ++i) {
        while (pos < text.size() && isSpace(text[pos])) ++pos;
        if (pos == text.size())
            fail("expected " + expected + ", found " + std::to_string(i), text);
        // istream accepts a leading '+'; from_chars does not.
        std::size_t start = pos;
        if (text[start] == '+' && start + 1 < text.size() && text[start + 1] != '-') ++start;
        // Parse as double so a value beyond float range is caught instead of becoming inf.
        double value = 0.0;
        const auto [end, error] = std::from_chars(text.data() + start, text.data() + text.size(), value,
                                                  std::chars_format::general);
        if (error == std::errc::invalid_argument) fail("not a number", tokenAround(text, pos));
        if (error == std::errc::result_out_of_range || !std::isfinite(value) ||
            std::abs(value) > std::numeric_limits<float>::max())
            fail("not a finite 32-bit number", tokenAround(text, pos));
        values[i] = static_cast<float>(value);
        pos = static_cast<std::size_t>(end - text.data());
        if (pos < text.size() && !isSpace(text[pos])) irregular = true;
    }
    while (pos < text.size() && isSpace(text[pos])) ++pos;
    if (pos < text.size()) irregular = true;

    if (irregular) {
        Issue issue = context.issueAt(
            owner, "malformed number list, read as '" + describe(values.data(), Count) + "' like the course's istream parser",
            text);
        issue.element = element;
        context.warn(std::move(issue));
    }
    return values;
}

}  // namespace

float parseScalar(const ParseContext& context, pugi::xml_node element) {
    return readFloats<1>(context, element, element.name(), elementText(element))[0];
}

glm::vec3 parseVec3(const ParseContext& context, pugi::xml_node element) {
    const auto v = readFloats<3>(context, element, element.name(), elementText(element));
    return {v[0], v[1], v[2]};
}

glm::vec3 parseVec3Text(const ParseContext& context, pugi::xml_node owner, const std::string& label,
                        const std::string& text) {
    const auto v = readFloats<3>(context, owner, label, text);
    return {v[0], v[1], v[2]};
}

}  // namespace vkrt
