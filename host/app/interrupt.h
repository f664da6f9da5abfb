// Ctrl-C handling: the first SIGINT asks the running render to stop cleanly (it finishes the
// current tile or pass, then the program exits with 130); a second one exits at once.
#pragma once

#include <atomic>

namespace vkrt {

// Installs the handler and returns the flag renderers poll (RenderOptions::cancel).
const std::atomic<bool>* installInterruptHandler();

}  // namespace vkrt
