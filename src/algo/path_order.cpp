// singlestrip — implicit treap over faces (path_order.hpp).
#include "path_order.hpp"

#include <cstddef>
#include <utility>

namespace singlestrip {

PathOrder::PathOrder(uint32_t n) : left_(n, kNil), right_(n, kNil), parent_(n, kNil), size_(n, 1), flip_(n, 0) {}

// A fixed hash as heap priority: no random state, so runs are reproducible.
uint32_t PathOrder::priority(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

void PathOrder::push(uint32_t x) {
    if (!flip_[x]) return;
    std::swap(left_[x], right_[x]);
    if (left_[x] != kNil) flip_[left_[x]] ^= 1;
    if (right_[x] != kNil) flip_[right_[x]] ^= 1;
    flip_[x] = 0;
}

void PathOrder::pull(uint32_t x) {
    size_[x] = 1;
    for (uint32_t c : {left_[x], right_[x]})
        if (c != kNil) size_[x] += size_[c], parent_[c] = x;
}

// Cartesian tree of `items` by priority, in linear time (right spine on a stack).
uint32_t PathOrder::build(const std::vector<FaceId>& items, bool reversed) {
    std::vector<uint32_t> spine;
    const std::size_t n = items.size();
    for (std::size_t i = 0; i < n; ++i) {
        const uint32_t x = items[reversed ? n - 1 - i : i].idx();
        left_[x] = right_[x] = parent_[x] = kNil;
        flip_[x] = 0;
        uint32_t last = kNil;
        while (!spine.empty() && priority(spine.back()) < priority(x)) {
            last = spine.back();
            spine.pop_back();
            pull(last);
        }
        left_[x] = last;
        if (!spine.empty()) right_[spine.back()] = x;
        spine.push_back(x);
    }
    while (!spine.empty()) {
        pull(spine.back());
        if (spine.size() == 1) break;
        spine.pop_back();
    }
    if (spine.empty()) return kNil;
    parent_[spine.front()] = kNil;
    return spine.front();
}

uint32_t PathOrder::merge(uint32_t a, uint32_t b) {
    if (a == kNil) return b;
    if (b == kNil) return a;
    if (priority(a) > priority(b)) {
        push(a);
        right_[a] = merge(right_[a], b);
        pull(a);
        parent_[a] = kNil;
        return a;
    }
    push(b);
    left_[b] = merge(a, left_[b]);
    pull(b);
    parent_[b] = kNil;
    return b;
}

// First k elements of t into a, the rest into b.
void PathOrder::split(uint32_t t, uint32_t k, uint32_t& a, uint32_t& b) {
    if (t == kNil) {
        a = b = kNil;
        return;
    }
    push(t);
    const uint32_t ls = left_[t] == kNil ? 0 : size_[left_[t]];
    if (k <= ls) {
        split(left_[t], k, a, left_[t]);
        pull(t);
        b = t;
    } else {
        split(right_[t], k - ls - 1, right_[t], b);
        pull(t);
        a = t;
    }
    if (a != kNil) parent_[a] = kNil;
    if (b != kNil) parent_[b] = kNil;
}

void PathOrder::append(const std::vector<FaceId>& items) {
    root_ = merge(root_, build(items, false));
}

void PathOrder::prepend(const std::vector<FaceId>& items) {
    root_ = merge(build(items, true), root_);
}

uint32_t PathOrder::position(FaceId f) {
    const uint32_t x = f.idx();
    up_.clear();  // flips above x must be pushed before sizes say where x is
    for (uint32_t y = x; y != kNil; y = parent_[y]) up_.push_back(y);
    for (std::size_t i = up_.size(); i-- > 0;) push(up_[i]);
    uint32_t pos = left_[x] == kNil ? 0 : size_[left_[x]];
    for (uint32_t y = x; parent_[y] != kNil; y = parent_[y]) {
        const uint32_t p = parent_[y];
        if (right_[p] == y) pos += 1 + (left_[p] == kNil ? 0 : size_[left_[p]]);
    }
    return pos;
}

FaceId PathOrder::at(uint32_t k) {
    uint32_t t = root_;
    for (;;) {
        push(t);
        const uint32_t ls = left_[t] == kNil ? 0 : size_[left_[t]];
        if (k == ls) return FaceId(t);
        if (k < ls) {
            t = left_[t];
        } else {
            k -= ls + 1;
            t = right_[t];
        }
    }
}

void PathOrder::reverse_front(uint32_t k) {
    uint32_t a, b;
    split(root_, k, a, b);
    if (a != kNil) flip_[a] ^= 1;
    root_ = merge(a, b);
}

void PathOrder::reverse_back(uint32_t k) {
    uint32_t a, b;
    split(root_, k, a, b);
    if (b != kNil) flip_[b] ^= 1;
    root_ = merge(a, b);
}

std::vector<FaceId> PathOrder::items() {
    std::vector<FaceId> out;
    std::vector<uint32_t> stack;
    out.reserve(size());
    for (uint32_t t = root_; t != kNil || !stack.empty();) {
        while (t != kNil) {
            push(t);
            stack.push_back(t);
            t = left_[t];
        }
        t = stack.back();
        stack.pop_back();
        out.push_back(FaceId(t));
        t = right_[t];
    }
    return out;
}

}  // namespace singlestrip
