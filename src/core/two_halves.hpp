// singlestrip — internal: a loop over 0..n split at `mid` between this thread and one more, for
// the whole-mesh passes whose halves touch disjoint data (Mesh::from_soup's pairing and fan
// checks). Errors come out as a sequential loop would give them: the first half's first.
#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <system_error>
#include <thread>

namespace singlestrip {

/// From this many faces a pass is split in two (a thread costs tens of microseconds; the passes
/// that use it take tens of milliseconds there).
inline constexpr size_t kTwoThreadFaces = size_t{1} << 17;

/// Calls fn(0, mid) here and fn(mid, n) on another thread when `parallel` (else fn(0, n)). If
/// the first half throws, that is rethrown (after the other half ends); else the second's.
/// Without a thread to be had, runs both halves here.
template <class Fn>
void run_in_two_halves(uint32_t mid, uint32_t n, bool parallel, Fn&& fn) {
    if (!parallel || mid == 0 || mid >= n) return fn(0u, n);
    std::exception_ptr second;
    std::thread other;
    try {
        other = std::thread([&] {
            try {
                fn(mid, n);
            } catch (...) {
                second = std::current_exception();
            }
        });
    } catch (const std::system_error&) {
        return fn(0u, n);
    }
    try {
        fn(0u, mid);
    } catch (...) {
        other.join();
        throw;
    }
    other.join();
    if (second) std::rethrow_exception(second);
}

}  // namespace singlestrip
