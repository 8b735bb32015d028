// singlestrip — reference homology generators by tree–cotree decomposition (Eppstein, "Dynamic
// generators of topologically embedded graphs", SODA 2003), to compare with the strip's cycles.
//
// Construction. Primal graph: the mesh's referenced vertices and interior edges, with all
// boundary vertices identified into one vertex (when there is a boundary; boundary edges become
// loops and are dropped). T = a breadth-first spanning tree of it (rooted at the boundary vertex,
// else at the lowest referenced vertex). C = a breadth-first spanning tree of the dual graph
// (faces; dual edges = interior edges not in T), rooted at face 0. Each interior edge in neither
// T nor C ("leftover") yields one generator: the dual cycle made of that edge and the path in C
// between its two faces, returned as a closed chain of faces. There are exactly 2g+h-1 leftover
// edges for genus g and h >= 1 boundary loops (2g closed), and the generators are a basis of
// H1(M; Z2): generator i crosses the relative cycle (leftover edge j + T paths) iff i == j.
//
// Complexity O(V + F + sum of generator lengths); a generator has at most F faces.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "singlestrip/mesh.hpp"

namespace singlestrip {

/// Tree–cotree generators of `mesh` as closed chains of edge-adjacent faces (consecutive entries
/// and last -> first share an edge, no face repeats). Faces are written as positions in `order`
/// (order[i] = mesh face at position i, a permutation of the faces); an empty `order` means the
/// identity (mesh face indices).
/// \pre mesh is valid and edge-connected. \throw RequestError if it is not edge-connected or
///      `order` is not a permutation of its faces; InternalError on a broken invariant.
std::vector<std::vector<uint32_t>> tree_cotree_generators(const Mesh& mesh, const std::vector<uint32_t>& order = {});

/// Homology classes in H1(M; Z2) of closed face chains, by intersection parity with the
/// relative cycles (leftover edge + T paths) of the tree–cotree above: two chains are homologous
/// iff their class vectors are equal; a set is independent iff its vectors are (z2_rank()).
/// The chain's crossings of a tree edge flip the parity of every tree path through it, i.e. of
/// the leftover endpoints in the edge's subtree: numbered in preorder, a subtree is an interval,
/// so a chain costs its crossings and the leftover endpoints under them, never a pass over V.
/// Construction O(V + F); classify() O(n log n + dim/64 + endpoints under the crossed tree edges)
/// for a chain of n faces (at most O(n log n + dim)).
class HomologyClassifier {
public:
    /// \pre as tree_cotree_generators().
    explicit HomologyClassifier(const Mesh& mesh);
    /// dim H1(M; Z2) = 2g+h-1 (2g closed) = number of bits of a class vector.
    [[nodiscard]] size_t dimension() const noexcept { return leftover_.size(); }
    /// Class of a closed chain of MESH faces (consecutive entries and last -> first adjacent).
    /// \throw InternalError if two consecutive faces are not adjacent.
    [[nodiscard]] std::vector<uint64_t> classify(const std::vector<FaceId>& mesh_faces) const;
    /// The tree–cotree generator of class bit j (as tree_cotree_generators() builds it, MESH
    /// faces): its class is the j-th unit vector. \pre j < dimension(). O(its length).
    [[nodiscard]] std::vector<FaceId> generator(size_t j) const;
    /// Its number of faces, without building it. O(its length), no allocation.
    [[nodiscard]] size_t generator_length(size_t j) const;

private:
    const Mesh* mesh_;
    // Per-face and per-half-edge arrays are plain vectors, read through typed views in the
    // source: the per-id array types are internal.
    std::vector<FaceId> fparent_;          ///< cotree parent face per face (kNone at the root)
    std::vector<uint32_t> depth_;          ///< cotree depth per face
    std::vector<HalfedgeId> leftover_he_;  ///< leftover edge -> representative half-edge
    std::vector<uint32_t> edge_of_he_;     ///< half-edge -> interior edge id (kNone on boundary)
    std::vector<uint32_t> leftover_;       ///< leftover edge ids (one per class bit)
    std::vector<uint32_t> bit_of_edge_;    ///< interior edge -> its class bit if leftover, else kNone
    /// Interior edge -> preorder interval [first, last) of the leftover endpoints (indices into
    /// end_bit_) in the subtree below it, if it is a tree edge; else first == last.
    std::vector<uint32_t> under_first_, under_last_;
    std::vector<uint32_t> end_bit_;  ///< leftover endpoints in preorder of their vertex: class bit
};

/// Rank over Z2 of bit-vector rows (all of the same length). O(rows^2 * words).
size_t z2_rank(std::vector<std::vector<uint64_t>> rows);

}  // namespace singlestrip
