#include "input_limits.h"

#include <cctype>
#include <stdexcept>

namespace vkrt {

namespace {

InputLimits& current() {
    static InputLimits limits;
    return limits;
}

struct Named {
    const char* name;
    std::uint64_t InputLimits::*field;
};
constexpr Named kNamed[] = {
    {"scene-bytes", &InputLimits::sceneFileBytes}, {"mesh-bytes", &InputLimits::meshFileBytes},
    {"image-texels", &InputLimits::imageTexels},   {"scene-texels", &InputLimits::sceneTexels},
    {"read-pixels", &InputLimits::readPixels},
};

std::string names() {
    std::string out;
    for (const Named& n : kNamed) out += (out.empty() ? "" : ", ") + std::string(n.name);
    return out;
}

// "64M" -> 64 << 20; nothing but digits and one suffix, no overflow, not zero.
std::uint64_t parseAmount(const std::string& text, const std::string& assignment) {
    const auto bad = [&](const std::string& why) {
        return std::invalid_argument("'" + assignment + "': " + why + " (a positive whole number, optionally with K, M or G)");
    };
    std::size_t digits = 0;
    std::uint64_t value = 0;
    for (; digits < text.size() && std::isdigit(static_cast<unsigned char>(text[digits])); ++digits) {
        const std::uint64_t d = static_cast<std::uint64_t>(text[digits] - '0');
        if (value > (UINT64_MAX - d) / 10) throw bad("too large");
        value = value * 10 + d;
    }
    if (digits == 0) throw bad("no number");
    int shift = 0;
    if (digits + 1 == text.size()) {
        switch (std::toupper(static_cast<unsigned char>(text[digits]))) {
            case 'K': shift = 10; break;
            case 'M': shift = 20; break;
            case 'G': shift = 30; break;
            default: throw bad("unknown suffix");
        }
    } else if (digits != text.size()) {
        throw bad("unexpected text after the number");
    }
    if (value > (UINT64_MAX >> shift)) throw bad("too large");
    value <<= shift;
    if (value == 0) throw bad("a limit of 0 would refuse every file");
    return value;
}

}  // namespace

const InputLimits& inputLimits() { return current(); }

void setInputLimit(const std::string& assignment) {
    const std::size_t eq = assignment.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("'" + assignment + "': expected NAME=VALUE, NAME one of " + names());
    const std::string name = assignment.substr(0, eq);
    for (const Named& n : kNamed)
        if (name == n.name) {
            current().*n.field = parseAmount(assignment.substr(eq + 1), assignment);
            return;
        }
    throw std::invalid_argument("'" + assignment + "': no input limit '" + name + "' (there are " + names() + ")");
}

void resetInputLimits() { current() = InputLimits{}; }

std::string inputLimitHint(const char* name) { return " (--input-limit " + std::string(name) + "=N raises it)"; }

}  // namespace vkrt
