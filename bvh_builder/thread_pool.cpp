#include "thread_pool.h"

#include <algorithm>
#include <chrono>
#include <utility>

#include <immintrin.h>

namespace vkrt::bvh {

namespace {

// How long an idle thread spins before it blocks: on this VM a sleeping worker started ~50 us late
// on every parallelFor, and a build's gaps between parallelFors are mostly microseconds, the
// longest (one thread partitioning the root range at 100K references) ~0.5 ms (commit 590e360,
// docs/lab/2026-12-02-bvh-build.md).
constexpr std::chrono::microseconds kSpin{1000};

}  // namespace

template <class Ready>
bool ThreadPool::spinFor(const Ready& ready) {
    const auto until = std::chrono::steady_clock::now() + kSpin;
    for (;;) {
        for (int i = 0; i < 64; ++i) {
            if (ready()) return true;
            _mm_pause();
        }
        if (std::chrono::steady_clock::now() >= until) return ready();
    }
}

ThreadPool::ThreadPool(int threads) {
    if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    for (int i = 1; i < threads; ++i) workers_.emplace_back([this] { workerLoop(); });
}

ThreadPool::~ThreadPool() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
        stoppingSeen_.store(true, std::memory_order_release);
    }
    wake_.notify_all();
    for (std::thread& t : workers_) t.join();
}

// Claims and runs items of the current job until none are left. Items are coarse (a chunk of
// primitives, a subtree, a group), so a mutex per claim costs nothing measurable.
void ThreadPool::drain() {
    std::unique_lock lock(mutex_);
    while (job_ && next_ < jobCount_) {
        const std::size_t i = next_++;
        const auto* fn = job_;
        lock.unlock();
        std::exception_ptr error;
        try {
            (*fn)(i);
        } catch (...) {
            error = std::current_exception();
        }
        lock.lock();
        if (error && !error_) error_ = error;
        finishedSeen_.store(++finished_, std::memory_order_release);
        if (finished_ == jobCount_) done_.notify_all();
    }
}

void ThreadPool::workerLoop() {
    std::size_t seen = 0;
    for (;;) {
        spinFor([&] {
            return stoppingSeen_.load(std::memory_order_acquire) ||
                   generationSeen_.load(std::memory_order_acquire) != seen;
        });
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stopping_ || (job_ && generation_ != seen); });
            if (stopping_) return;
            seen = generation_;
        }
        drain();
    }
}

void ThreadPool::parallelFor(std::size_t count, const std::function<void(std::size_t)>& fn) {
    if (count == 0) return;
    if (workers_.empty() || count == 1) {
        std::exception_ptr error;
        for (std::size_t i = 0; i < count; ++i) {
            try {
                fn(i);
            } catch (...) {
                if (!error) error = std::current_exception();
            }
        }
        if (error) std::rethrow_exception(error);
        return;
    }
    {
        std::lock_guard lock(mutex_);
        job_ = &fn;
        jobCount_ = count;
        next_ = 0;
        finished_ = 0;
        error_ = nullptr;
        finishedSeen_.store(0, std::memory_order_relaxed);
        generationSeen_.store(++generation_, std::memory_order_release);
    }
    wake_.notify_all();
    drain();
    spinFor([&] { return finishedSeen_.load(std::memory_order_acquire) == count; });
    std::unique_lock lock(mutex_);
    done_.wait(lock, [&] { return finished_ == jobCount_; });
    job_ = nullptr;
    if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

}  // namespace vkrt::bvh
