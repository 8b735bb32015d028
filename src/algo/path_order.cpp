// singlestrip — splay tree over faces keyed by position (path_order.hpp).
#include "path_order.hpp"

#include <cstddef>
#include <utility>

namespace singlestrip {

PathOrder::PathOrder(uint32_t n) : node_(n, Node{}) {}

void PathOrder::push(FaceId x) {
    Node& n = node_[x];
    if (!n.flip) return;
    std::swap(n.left, n.right);
    if (n.left != kNone) node_[n.left].flip ^= 1;
    if (n.right != kNone) node_[n.right].flip ^= 1;
    n.flip = 0;
}

void PathOrder::pull(FaceId x) {
    Node& n = node_[x];
    n.size = 1 + count(n.left) + count(n.right);
}

// x up one level over its parent p (both pushed).
void PathOrder::rotate(FaceId x) {
    const FaceId p = node_[x].parent, g = node_[p].parent;
    if (node_[p].left == x) {
        node_[p].left = node_[x].right;
        if (node_[x].right != kNone) node_[node_[x].right].parent = p;
        node_[x].right = p;
    } else {
        node_[p].right = node_[x].left;
        if (node_[x].left != kNone) node_[node_[x].left].parent = p;
        node_[x].left = p;
    }
    node_[p].parent = x;
    node_[x].parent = g;
    if (g != kNone) (node_[g].left == p ? node_[g].left : node_[g].right) = x;
    pull(p);
    pull(x);
}

void PathOrder::splay(FaceId x) {
    up_.clear();
    for (FaceId y = x; y != kNone; y = node_[y].parent) up_.push_back(y);
    for (std::size_t i = up_.size(); i-- > 0;) push(up_[i]);
    while (node_[x].parent != kNone) {
        const FaceId p = node_[x].parent, g = node_[p].parent;
        if (g != kNone) rotate((node_[g].left == p) == (node_[p].left == x) ? p : x);
        rotate(x);
    }
    root_ = x;
}

FaceId PathOrder::find(FaceId t, uint32_t k) {
    for (;;) {
        push(t);
        const uint32_t ls = count(node_[t].left);
        if (k == ls) break;
        if (k < ls) {
            t = node_[t].left;
        } else {
            k -= ls + 1;
            t = node_[t].right;
        }
    }
    splay(t);
    return t;
}

FaceId PathOrder::join(FaceId a, FaceId b) {
    if (a == kNone) return b;
    if (b == kNone) return a;
    root_ = a;
    const FaceId m = find(a, count(a) - 1);  // a's last node, now its root with no right child
    node_[m].right = b;
    node_[b].parent = m;
    pull(m);
    return m;
}

uint32_t PathOrder::priority(FaceId f) {
    uint32_t x = f.idx();
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
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
    splay(x);  // pushes x too: its children are in order
    return count(node_[x].left);
}

FaceId PathOrder::at(uint32_t k) {
    return find(root_, k);
}

void PathOrder::reverse_front(uint32_t k) {
    if (k == 0) return;
    if (k >= size()) {
        node_[root_].flip ^= 1;
        return;
    }
    const FaceId r = find(root_, k);  // the first face kept: [0, k) is its left subtree
    if (node_[r].left != kNone) node_[node_[r].left].flip ^= 1;
}

void PathOrder::reverse_back(uint32_t k) {
    if (k == 0) {
        if (root_ != kNone) node_[root_].flip ^= 1;
        return;
    }
    if (k >= size()) return;
    const FaceId r = find(root_, k - 1);  // the last face kept: [k, size) is its right subtree
    if (node_[r].right != kNone) node_[node_[r].right].flip ^= 1;
}

std::vector<FaceId> PathOrder::items() {
    std::vector<FaceId> out;
    std::vector<FaceId> stack;
    out.reserve(size());
    for (FaceId t = root_; t != kNone || !stack.empty();) {
        while (t != kNone) {
            push(t);
            stack.push_back(t);
            t = node_[t].left;
        }
        t = stack.back();
        stack.pop_back();
        out.push_back(t);
        t = node_[t].right;
    }
    return out;
}

}  // namespace singlestrip
