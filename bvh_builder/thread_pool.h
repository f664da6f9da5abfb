// A small fixed pool of worker threads for the builder: parallelFor over an index range, with the
// calling thread taking part. Items are claimed one at a time through an atomic counter, so a few
// large items (subtrees) and many small ones (groups) both balance across threads.
// Nothing the pool does may change a build's result: callers give every item its own output.
// Idle threads spin for a while before they sleep (see kSpin in thread_pool.cpp): a build calls
// parallelFor ~20 times in a row, and waking a sleeping thread took ~50 us on this VM each time.
#pragma once

#include <atomic>
#include <condition_variable>
#include <exception>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace vkrt::bvh {

class ThreadPool {
public:
    // threads <= 0: one per hardware thread. A pool of 1 runs everything on the caller.
    explicit ThreadPool(int threads);
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    int size() const { return static_cast<int>(workers_.size()) + 1; }

    // Calls fn(i) for every i in [0, count), on all threads; returns when all calls are done.
    // Not reentrant: fn must not call parallelFor. The first exception thrown by fn is rethrown
    // here after every other item has run.
    void parallelFor(std::size_t count, const std::function<void(std::size_t)>& fn);

private:
    void workerLoop();
    void drain();
    // Spins until ready() or kSpin has passed; returns ready().
    template <class Ready>
    static bool spinFor(const Ready& ready);

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable done_;
    const std::function<void(std::size_t)>* job_ = nullptr;
    std::size_t jobCount_ = 0;
    std::size_t next_ = 0;       // next item to claim (under mutex_)
    std::size_t finished_ = 0;   // items completed (under mutex_)
    std::size_t generation_ = 0; // bumped per parallelFor so workers join each job once
    bool stopping_ = false;
    std::exception_ptr error_;   // first exception of the current job (under mutex_)
    // Mirrors of generation_, finished_ and stopping_ that spinning threads read without the mutex
    // (written under it).
    std::atomic<std::size_t> generationSeen_{0};
    std::atomic<std::size_t> finishedSeen_{0};
    std::atomic<bool> stoppingSeen_{false};
};

}  // namespace vkrt::bvh
