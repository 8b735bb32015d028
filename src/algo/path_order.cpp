// singlestrip — implicit treap over faces (path_order.hpp).
#include "path_order.hpp"

#include <cstddef>
#include <utility>

namespace singlestrip {

PathOrder::PathOrder(uint32_t n) : left_(n, kNone), right_(n, kNone), parent_(n, kNone), size_(n, 1), flip_(n, 0) {}

// A fixed hash as heap priority: no random state, so runs are reproducible.
uint32_t PathOrder::priority(FaceId f) {
    uint32_t x = f.idx();
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

void PathOrder::push(FaceId x) {
    if (!flip_[x]) return;
    std::swap(left_[x], right_[x]);
    if (left_[x] != kNone) flip_[left_[x]] ^= 1;
    if (right_[x] != kNone) flip_[right_[x]] ^= 1;
    flip_[x] = 0;
}

void PathOrder::pull(FaceId x) {
    size_[x] = 1;
    for (const FaceId c : {left_[x], right_[x]})
        if (c != kNone) size_[x] += size_[c], parent_[c] = x;
}

FaceId PathOrder::merge(FaceId a, FaceId b) {
    if (a == kNone) return b;
    if (b == kNone) return a;
    if (priority(a) > priority(b)) {
        push(a);
        right_[a] = merge(right_[a], b);
        pull(a);
        parent_[a] = kNone;
        return a;
    }
    push(b);
    left_[b] = merge(a, left_[b]);
    pull(b);
    parent_[b] = kNone;
    return b;
}

// First k elements of t into a, the rest into b.
void PathOrder::split(FaceId t, uint32_t k, FaceId& a, FaceId& b) {
    if (t == kNone) {
        a = b = kNone;
        return;
    }
    push(t);
    const uint32_t ls = count(left_[t]);
    if (k <= ls) {
        split(left_[t], k, a, left_[t]);
        pull(t);
        b = t;
    } else {
        split(right_[t], k - ls - 1, right_[t], b);
        pull(t);
        a = t;
    }
    if (a != kNone) parent_[a] = kNone;
    if (b != kNone) parent_[b] = kNone;
}

void PathOrder::append(const std::vector<FaceId>& items) {
    size_t i = 0;
    (void)append_from([&] { return i < items.size() ? items[i++] : FaceId(kNone); });
}

void PathOrder::prepend(const std::vector<FaceId>& items) {
    size_t i = 0;
    (void)prepend_from([&] { return i < items.size() ? items[i++] : FaceId(kNone); });
}

uint32_t PathOrder::position(FaceId x) {
    up_.clear();  // flips above x must be pushed before sizes say where x is
    for (FaceId y = x; y != kNone; y = parent_[y]) up_.push_back(y);
    for (std::size_t i = up_.size(); i-- > 0;) push(up_[i]);
    uint32_t pos = count(left_[x]);
    for (FaceId y = x; parent_[y] != kNone; y = parent_[y]) {
        const FaceId p = parent_[y];
        if (right_[p] == y) pos += 1 + count(left_[p]);
    }
    return pos;
}

FaceId PathOrder::at(uint32_t k) {
    FaceId t = root_;
    for (;;) {
        push(t);
        const uint32_t ls = count(left_[t]);
        if (k == ls) return t;
        if (k < ls) {
            t = left_[t];
        } else {
            k -= ls + 1;
            t = right_[t];
        }
    }
}

void PathOrder::reverse_front(uint32_t k) {
    FaceId a, b;
    split(root_, k, a, b);
    if (a != kNone) flip_[a] ^= 1;
    root_ = merge(a, b);
}

void PathOrder::reverse_back(uint32_t k) {
    FaceId a, b;
    split(root_, k, a, b);
    if (b != kNone) flip_[b] ^= 1;
    root_ = merge(a, b);
}

std::vector<FaceId> PathOrder::items() {
    std::vector<FaceId> out;
    std::vector<FaceId> stack;
    out.reserve(size());
    for (FaceId t = root_; t != kNone || !stack.empty();) {
        while (t != kNone) {
            push(t);
            stack.push_back(t);
            t = left_[t];
        }
        t = stack.back();
        stack.pop_back();
        out.push_back(t);
        t = right_[t];
    }
    return out;
}

}  // namespace singlestrip
