#include "diagnostics.h"

#include <utility>

namespace vkrt {

namespace {

// A value may be element text spanning lines, or a whole paragraph of garbage: keep the message on
// one line and short enough to read, while still showing where the text went wrong.
std::string oneLine(const std::string& value) {
    constexpr std::size_t kMaxChars = 80;
    std::string flat;
    bool lastWasSpace = false;
    for (char c : value) {
        const bool space = c == '\n' || c == '\r' || c == '\t' || c == ' ';
        if (space && lastWasSpace) continue;
        flat += space ? ' ' : c;
        lastWasSpace = space;
    }
    if (flat.size() > kMaxChars) flat = flat.substr(0, kMaxChars) + "...";
    return flat;
}

}  // namespace

std::string Issue::message() const {
    std::string text = file + ":" + std::to_string(line) + ": " + element + ": " + problem;
    if (!value.empty()) text += " '" + oneLine(value) + "'";
    return text;
}

SceneError::SceneError(Issue issue) : std::runtime_error(issue.message()), issue_(std::move(issue)) {}

void Diagnostics::warn(Issue issue) {
    if (strict_) throw SceneError(std::move(issue));
    warnings_.push_back(std::move(issue));
}

std::vector<std::string> Diagnostics::messages() const {
    std::vector<std::string> lines;
    lines.reserve(warnings_.size());
    for (const Issue& issue : warnings_) lines.push_back(issue.message());
    return lines;
}

}  // namespace vkrt
