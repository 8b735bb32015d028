// singlestrip programs — large arrays on transparent huge pages (the CLI and the benchmark link
// this file; the library does not, so it imposes no allocator on its users).
//
// Why: a fresh array is paid for at first touch, one page fault per 4 KB page. On the 2-core VMs
// where singlestrip is built and measured those faults cost about two thirds of a 10M-triangle
// run (`strip`, same output: torus 13.6 -> 4.2 s, disk with 1000 holes 24.0 -> 6.6 s; peak
// memory +0-1%: docs/benchmarks.md). Debian's kernels give huge pages only where madvise() asks
// for them, so every block of 4 MB or more is 2 MB-aligned and asked for. Smaller blocks are
// plain malloc().
//
// Every replaced form allocates with the malloc family, so every form of delete frees with free().
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#if defined(__linux__) && defined(MADV_HUGEPAGE)

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
constexpr std::size_t kLarge = std::size_t{4} << 20;  ///< smaller blocks: plain malloc()

// The tail past the last whole huge page stays on 4 KB pages: a huge page there would hold up
// to 2 MB the array never uses, for each array alive at the peak.
void* allocate(std::size_t n) noexcept {
    if (n < kLarge) return std::malloc(n == 0 ? 1 : n);
    if (n > SIZE_MAX - kHugePage) return nullptr;  // the rounding below would wrap round
    void* p = std::aligned_alloc(kHugePage, (n + kHugePage - 1) & ~(kHugePage - 1));
    if (p != nullptr) (void)madvise(p, n & ~(kHugePage - 1), MADV_HUGEPAGE);  // a hint: 4 KB pages if refused
    return p;
}

void* allocate_or_throw(std::size_t n) {
    for (;;) {
        if (void* p = allocate(n)) return p;
        std::new_handler handler = std::get_new_handler();
        if (handler == nullptr) throw std::bad_alloc();
        handler();
    }
}

}  // namespace

void* operator new(std::size_t n) {
    return allocate_or_throw(n);
}
void* operator new[](std::size_t n) {
    return allocate_or_throw(n);
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
    return allocate(n);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
    return allocate(n);
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}

#endif
