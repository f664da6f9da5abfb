// Every message the Vulkan validation layers send, kept so tests can fail on any of them.
#pragma once

#include <cstddef>
#include <mutex>
#include <string>
#include <vector>

namespace vkrt {

class ValidationLog {
public:
    // Thread-safe: the layers may call back from any thread.
    void record(std::string message);
    std::size_t count() const;
    std::vector<std::string> messages() const;
    // All messages, one per line (for a test failure or --validate's report).
    std::string joined() const;

private:
    mutable std::mutex mutex_;
    std::vector<std::string> messages_;
};

}  // namespace vkrt
