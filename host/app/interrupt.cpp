#include "interrupt.h"

#include <csignal>

namespace vkrt {

namespace {

// Signal handlers can only touch lock-free atomics; this is the one process-wide flag.
std::atomic<bool> g_interrupted{false};

extern "C" void onInterrupt(int) {
    if (g_interrupted.exchange(true)) {
        std::signal(SIGINT, SIG_DFL);
        std::raise(SIGINT);
    }
}

}  // namespace

const std::atomic<bool>* installInterruptHandler() {
    static_assert(std::atomic<bool>::is_always_lock_free);
    std::signal(SIGINT, onInterrupt);
    return &g_interrupted;
}

}  // namespace vkrt
