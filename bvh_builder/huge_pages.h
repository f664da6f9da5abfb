// Large builder arrays on transparent huge pages. A 1M-triangle build touches ~200 MB of fresh
// memory, and the first touch of a page (the kernel zeroing it) dominated the build: on this VM
// (THP in `madvise` mode) memset of fresh memory costs 0.7 ms/MB with 4 KiB pages, 0.13 ms/MB with
// 2 MiB pages, 0.05 ms/MB once touched. Elsewhere than Linux this is a plain allocation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace vkrt::bvh {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

// Advises the kernel to back the whole 2 MiB pages inside [p, p + bytes) with huge pages.
inline void adviseHugePages(void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (bytes < kHugePage) return;
    const auto begin = (reinterpret_cast<std::uintptr_t>(p) + kHugePage - 1) & ~(kHugePage - 1);
    const auto end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(kHugePage - 1);
    if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
    (void)p;
    (void)bytes;
#endif
}

// An uninitialised array of trivially copyable T, 2 MiB aligned when large. `huge` = false keeps
// 4 KiB pages, for arrays written sparsely (a huge page is zeroed whole on first touch).
template <class T>
class HugeArray {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

public:
    HugeArray() = default;
    explicit HugeArray(std::size_t count, bool huge = true) : size_(count) {
        if (count == 0) return;
        // Below one huge page, a plain allocation: rounding up would make the kernel zero 2 MiB
        // for a few KiB.
        const std::size_t exact = (count * sizeof(T) + 63) / 64 * 64;
        huge = huge && exact >= kHugePage;
        const std::size_t bytes = huge ? (exact + kHugePage - 1) / kHugePage * kHugePage : exact;
        void* p = std::aligned_alloc(huge ? kHugePage : 64, bytes);
        if (!p) throw std::bad_alloc();
        if (huge) adviseHugePages(p, bytes);
        data_.reset(static_cast<T*>(p));
    }
    T* get() const { return data_.get(); }
    T& operator[](std::size_t i) const { return data_.get()[i]; }
    std::size_t size() const { return size_; }
    explicit operator bool() const { return data_ != nullptr; }

private:
    struct Free {
        void operator()(T* p) const { std::free(p); }
    };
    std::unique_ptr<T, Free> data_;
    std::size_t size_ = 0;
};

// Reserves a vector's capacity and advises huge pages for it before it is written.
template <class V>
void reserveHuge(V& v, std::size_t count) {
    v.reserve(count);
    adviseHugePages(v.data(), v.capacity() * sizeof(typename V::value_type));
}

}  // namespace vkrt::bvh
