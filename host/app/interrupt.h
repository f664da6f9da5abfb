// Ctrl-C handling: the first SIGINT asks the running render to stop cleanly (it finishes the
// current tile or pass, then the program exits with 130); a second one exits at once. Work that
// has no point at which to poll (reading a scene, its meshes and textures; building the trees)
// runs inside an ExitAtOnceOnInterrupt, where the first SIGINT ends the process straight away.
#pragma once

#include <atomic>

namespace vkrt {

// Installs the handler and returns the flag renderers poll (RenderOptions::cancel).
const std::atomic<bool>* installInterruptHandler();

// While one is alive, SIGINT prints "vkrt: interrupted" and exits with 130 from the handler (only
// async-signal-safe calls: write, _exit). For work that leaves nothing behind to clean up: no file
// is written and no partial result kept, so ending mid-way loses nothing. An interrupt that came
// before the scope was entered throws RenderCancelled from the constructor.
class ExitAtOnceOnInterrupt {
public:
    ExitAtOnceOnInterrupt();
    ~ExitAtOnceOnInterrupt();
    ExitAtOnceOnInterrupt(const ExitAtOnceOnInterrupt&) = delete;
    ExitAtOnceOnInterrupt& operator=(const ExitAtOnceOnInterrupt&) = delete;
};

}  // namespace vkrt
