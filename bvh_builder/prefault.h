// Fresh pages faulted in by all pool threads before a single thread fills them. The kernel zeroes
// every page on its first touch; a std::vector::resize (which value-initialises) or a one-thread
// writer would take all of those faults on one thread while the others wait. The profile of a
// 1M-triangle build showed the kernel's page zeroing at 11-19% of the samples, most of it under
// the one-thread resizes of the primitive records and the GPU node array.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "thread_pool.h"

namespace vkrt::bvh {

// Faults in the pages of [p, p + bytes) writable, split over the pool. Best effort: without
// MADV_POPULATE_WRITE (Linux < 5.14, or elsewhere) the pages are faulted by their first writer.
inline void prefault(void* p, std::size_t bytes, ThreadPool& pool) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    constexpr std::size_t kPage = 4096;
    // Chunks of whole 2 MiB pages, so a huge page is never split between two threads' faults.
    constexpr std::size_t kChunk = std::size_t{4} << 20;
    const auto begin = reinterpret_cast<std::uintptr_t>(p) & ~(kPage - 1);
    const auto end = (reinterpret_cast<std::uintptr_t>(p) + bytes + kPage - 1) & ~(kPage - 1);
    if (bytes < kChunk) return;  // not worth a parallel pass
    const std::uintptr_t first = begin & ~(kChunk - 1);
    const std::size_t chunks = (end - first + kChunk - 1) / kChunk;
    pool.parallelFor(chunks, [&](std::size_t c) {
        const std::uintptr_t b = std::max(begin, first + c * kChunk);
        const std::uintptr_t e = std::min(end, first + (c + 1) * kChunk);
        if (e > b) madvise(reinterpret_cast<void*>(b), e - b, MADV_POPULATE_WRITE);
    });
#else
    (void)p;
    (void)bytes;
    (void)pool;
#endif
}

// Faults in the part of v's reserved capacity that a resize to `count` elements will use.
template <class V>
void prefaultCapacity(V& v, std::size_t count, ThreadPool& pool) {
    count = std::min(count, v.capacity());
    if (count > v.size()) prefault(v.data() + v.size(), (count - v.size()) * sizeof(typename V::value_type), pool);
}

}  // namespace vkrt::bvh
