#include "interrupt.h"

#include <csignal>

#include <unistd.h>

#include "output_file.h"
#include "render_options.h"

namespace vkrt {

namespace {

// Signal handlers can only touch lock-free atomics; these are the process-wide flags.
std::atomic<bool> g_interrupted{false};
std::atomic<int> g_exitAtOnceDepth{0};  // ExitAtOnceOnInterrupt scopes alive (they may nest)

constexpr int kExitInterrupted = 130;  // 128 + SIGINT, what a shell reports for Ctrl-C

extern "C" void onInterrupt(int) {
    if (g_exitAtOnceDepth.load() > 0) {
        static const char message[] = "vkrt: interrupted\n";
        [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, message, sizeof message - 1);
        ::_exit(kExitInterrupted);
    }
    if (g_interrupted.exchange(true)) {
        removeTemporaryBeingWritten();  // the second Ctrl-C may come during a write
        std::signal(SIGINT, SIG_DFL);
        std::raise(SIGINT);
    }
}

}  // namespace

const std::atomic<bool>* installInterruptHandler() {
    static_assert(std::atomic<bool>::is_always_lock_free);
    static_assert(std::atomic<int>::is_always_lock_free);
    std::signal(SIGINT, onInterrupt);
    return &g_interrupted;
}

ExitAtOnceOnInterrupt::ExitAtOnceOnInterrupt() {
    g_exitAtOnceDepth.fetch_add(1);
    if (g_interrupted.load()) {
        g_exitAtOnceDepth.fetch_sub(1);
        throw RenderCancelled{};
    }
}

ExitAtOnceOnInterrupt::~ExitAtOnceOnInterrupt() { g_exitAtOnceDepth.fetch_sub(1); }

}  // namespace vkrt
