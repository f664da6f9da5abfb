#include "number_text.h"

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

}  // namespace

std::optional<float> finiteFloat(double value) {
    // Beyond float range means rounding to infinity: from 2^128 - 2^103, the midpoint between the
    // largest float and 2^128, on. Decimals just above the largest float round down to it
    // (3.4028235e38, its shortest spelling, is one).
    constexpr double kRoundsToInfinity = 0x1.ffffffp127;
    if (!std::isfinite(value) || std::abs(value) >= kRoundsToInfinity) return std::nullopt;
    constexpr double kLargest = std::numeric_limits<float>::max();
    if (std::abs(value) > kLargest) return static_cast<float>(std::copysign(kLargest, value));
    return static_cast<float>(value);
}

NumberText readNumberText(const std::string& text, int count) {
    NumberText out;
    const std::string expected = count == 1 ? "1 number" : std::to_string(count) + " numbers";
    std::size_t pos = 0;
    for (int i = 0; i < count; ++i) {
        while (pos < text.size() && isSpace(text[pos])) ++pos;
        if (pos == text.size()) {
            out.error = "expected " + expected + ", found " + std::to_string(i);
            out.errorValue = text;
            return out;
        }
        // istream accepts a leading '+'; from_chars does not.
        std::size_t start = pos;
        if (text[start] == '+' && start + 1 < text.size() && text[start + 1] != '-') ++start;
        // Parse as double so a value beyond float range is caught instead of becoming inf.
        double value = 0.0;
        const auto [end, error] = std::from_chars(text.data() + start, text.data() + text.size(), value,
                                                  std::chars_format::general);
        if (error == std::errc::invalid_argument) {
            out.error = "not a number";
            out.errorValue = tokenAround(text, pos);
            return out;
        }
        const std::optional<float> f = error == std::errc::result_out_of_range ? std::nullopt : finiteFloat(value);
        if (!f) {
            out.error = kNotAFiniteFloat;
            out.errorValue = tokenAround(text, pos);
            return out;
        }
        out.values[static_cast<std::size_t>(i)] = *f;
        out.exact[static_cast<std::size_t>(i)] = value;
        pos = static_cast<std::size_t>(end - text.data());
        if (pos < text.size() && !isSpace(text[pos])) out.irregular = true;
    }
    while (pos < text.size() && isSpace(text[pos])) ++pos;
    if (pos < text.size()) out.irregular = true;
    return out;
}

std::string irregularNumberProblem(const NumberText& numbers, int count) {
    std::string readAs;
    for (int i = 0; i < count; ++i) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%g", static_cast<double>(numbers.values[static_cast<std::size_t>(i)]));
        if (i > 0) readAs += ' ';
        readAs += buffer;
    }
    return "malformed number list, read as '" + readAs + "' like the course's istream parser";
}

}  // namespace vkrt
