// Timing helpers of the benchmarks: a timed parallel loop handing out work as the peer does, and
// the median that every repeated figure is reported as (this machine drifts too much for means).
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

namespace vkrt::bench {

// Runs body(i) for i in [0, count) on `threads` threads, items handed out one at a time (the
// peer's row loop). Returns the wall-clock seconds.
template <class Body>
double overItems(int count, int threads, Body&& body) {
    std::atomic<int> next{0};
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&] {
            for (int i; (i = next++) < count;) body(i);
        });
    for (std::thread& t : pool) t.join();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

inline double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

}  // namespace vkrt::bench
