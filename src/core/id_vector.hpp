// singlestrip — internal: a flat per-id array indexed by its id type (FaceId, HalfedgeId, ...),
// so `used_[h]` says what it indexes and a face cannot index a half-edge array.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "singlestrip/mesh.hpp"

namespace singlestrip {

/// A std::vector<T> indexed by I (an Id<Tag>): element i.idx(). Unchecked, as std::vector's [].
template <class I, class T>
class IdVector {
public:
    IdVector() = default;
    IdVector(size_t n, const T& value) : v_(n, value) {}
    explicit IdVector(std::vector<T> v) noexcept : v_(std::move(v)) {}

    [[nodiscard]] T& operator[](I i) noexcept { return v_[i.idx()]; }
    [[nodiscard]] const T& operator[](I i) const noexcept { return v_[i.idx()]; }

    [[nodiscard]] size_t size() const noexcept { return v_.size(); }
    [[nodiscard]] bool empty() const noexcept { return v_.empty(); }
    [[nodiscard]] size_t capacity() const noexcept { return v_.capacity(); }
    void reserve(size_t n) { v_.reserve(n); }
    void resize(size_t n) { v_.resize(n); }
    void resize(size_t n, const T& value) { v_.resize(n, value); }
    void assign(size_t n, const T& value) { v_.assign(n, value); }
    void clear() noexcept { v_.clear(); }
    /// Empty, its memory given back (clear() keeps the capacity).
    void reset() noexcept { std::vector<T>().swap(v_); }
    void push_back(const T& value) { v_.push_back(value); }
    void pop_back() noexcept { v_.pop_back(); }
    [[nodiscard]] T& back() noexcept { return v_.back(); }
    [[nodiscard]] const T& back() const noexcept { return v_.back(); }
    void swap(IdVector& other) noexcept { v_.swap(other.v_); }
    /// The plain array, for interfaces that take one.
    [[nodiscard]] const std::vector<T>& plain() const noexcept { return v_; }
    /// The plain array moved out, for results that keep one (the array is left empty).
    [[nodiscard]] std::vector<T> release() && noexcept { return std::move(v_); }

private:
    std::vector<T> v_;
};

/// A read-only view of a per-id array indexed by I: an IdVector, or a plain std::vector that a
/// public struct keeps (StripResult::take_time, a public class's members), without a copy.
template <class I, class T>
class IdSpan {
public:
    explicit IdSpan(const std::vector<T>& v) noexcept : p_(v.data()), n_(v.size()) {}
    IdSpan(const IdVector<I, T>& v) noexcept : IdSpan(v.plain()) {}  // NOLINT(google-explicit-constructor)
    [[nodiscard]] const T& operator[](I i) const noexcept { return p_[i.idx()]; }
    [[nodiscard]] size_t size() const noexcept { return n_; }

private:
    const T* p_;
    size_t n_;
};

}  // namespace singlestrip
