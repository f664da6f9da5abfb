// Command-line numbers of the vkrt-bench subcommands, checked with a message naming the argument.
#pragma once

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace vkrt::bench {

inline float nonNegativeNumber(const std::string& s, const char* what) {
    char* end = nullptr;
    const float v = std::strtof(s.c_str(), &end);
    if (end == s.c_str() || *end || !(v >= 0.0f)) throw std::runtime_error(std::string(what) + " must be a number >= 0, got '" + s + "'");
    return v;
}

inline int positiveInt(const std::string& s, const char* what) {
    char* end = nullptr;
    const long v = std::strtol(s.c_str(), &end, 10);
    if (end == s.c_str() || *end || v < 1 || v > 1 << 20)
        throw std::runtime_error(std::string(what) + " must be a positive integer, got '" + s + "'");
    return static_cast<int>(v);
}

}  // namespace vkrt::bench
