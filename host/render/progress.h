// A progress bar on stderr for long renders: shown only when stderr is a terminal, the render
// has run for more than a second, and the user did not ask for --quiet.
#pragma once

#include <chrono>
#include <mutex>
#include <string>

namespace vkrt {

class Progress {
public:
    Progress(std::string label, bool quiet);
    ~Progress();  // finishes the line if a bar was drawn
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    // Thread-safe; fraction in [0, 1]. Redraws at most ~10 times per second.
    void update(double fraction);

private:
    std::string label_;
    bool enabled_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point lastDraw_;
    std::mutex mutex_;
};

}  // namespace vkrt
