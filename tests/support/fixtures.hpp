// Test fixtures: procedural test meshes and random manifold-preserving perturbations, for the
// tests, benchmarks and fuzz targets (library target singlestrip_fixtures; not part of the
// library or the CLI). The models the library needs itself are in singlestrip/models.hpp.
//
// Every generator returns a TriangleSoup with no unreferenced vertices, an empty source_polygon
// (faces are their own polygons) and consistently oriented faces: counter-clockwise seen from +z
// for planar meshes, outward for closed ones. Counts are documented as V / F and topology as
// chi (Euler characteristic), b (boundary loops) and g (genus); all are edge-connected
// oriented 2-manifolds except make_moebius_soup().
//
// Bad parameters (e.g. a torus with fewer than 3 segments) throw RequestError.
// All generators are O(V + F).
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "singlestrip/models.hpp"
#include "singlestrip/soup.hpp"

namespace singlestrip {

/// splitmix64 of x: the one random source of the fixtures, tests and fuzz decoders (tiny, fast and
/// identical on every platform, which std's distributions are not).
inline uint64_t splitmix64(uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

/// The splitmix64 sequence from `state`.
struct Rng {
    uint64_t state;
    uint64_t next() {
        const uint64_t z = splitmix64(state);
        state += 0x9e3779b97f4a7c15ull;
        return z;
    }
    size_t below(size_t n) { return static_cast<size_t>(next() % n); }
};

/// One triangle. V=3, F=1, chi=1, b=1, g=0.
TriangleSoup make_single_triangle();

/// A unit square split along a diagonal. V=4, F=2, chi=1, b=1, g=0.
TriangleSoup make_two_triangles();

/// k triangles around a centre vertex, an open fan (spanning less than a full turn).
/// \pre k >= 1. V=k+2, F=k, chi=1, b=1, g=0. Walking the faces in order turns the same way
/// every time (the worst case for GL strips).
TriangleSoup make_fan(uint32_t k);

/// k triangles one triangle wide; face i is (i, i+1, i+2) for even i and (i+1, i, i+2) for odd i,
/// so the faces in order are exactly the GL strip 0, 1, ..., k+1. \pre k >= 1.
/// V=k+2, F=k, chi=1, b=1, g=0.
TriangleSoup make_corridor(uint32_t k);

/// Planar grid of nx x ny unit cells, each split into two triangles (diagonals alternate in a
/// checkerboard). \pre nx, ny >= 1. V=(nx+1)(ny+1), F=2 nx ny, chi=1, b=1, g=0.
TriangleSoup make_grid_disk(uint32_t nx, uint32_t ny);

/// Convex polygon of n points on a circle of the given radius around `centre`, triangulated by
/// random diagonals (seeded): the dual graph is a tree and most faces are ears thinner than
/// 1e-7 radius (n = 20000), thinner than a float32 step far from the origin. \pre n >= 3.
/// V=n, F=n-2, chi=1, b=1, g=0.
TriangleSoup make_circle_polygon(uint32_t n, double radius = 1, Point3 centre = {0, 0, 0}, uint32_t seed = 7);

/// Planar ring: n_around segments around, n_radial quad rings between radius 1 and 2.
/// \pre n_around >= 3, n_radial >= 1. V=n_around (n_radial+1), F=2 n_around n_radial,
/// chi=0, b=2, g=0.
TriangleSoup make_annulus(uint32_t n_around, uint32_t n_radial);

/// Unit sphere from an icosahedron, each face split into 4 per subdivision.
/// \pre subdivisions <= 10. V=10*4^s+2, F=20*4^s, chi=2, b=0, g=0.
TriangleSoup make_icosphere(uint32_t subdivisions);

/// Unit latitude/longitude sphere with two poles. \pre n_lon >= 3, n_lat >= 2.
/// V=n_lon (n_lat-1) + 2, F=2 n_lon (n_lat-1), chi=2, b=0, g=0.
TriangleSoup make_uv_sphere(uint32_t n_lon, uint32_t n_lat);

/// Torus with radii 1 and 0.35. \pre n_major, n_minor >= 3.
/// V=n_major n_minor, F=2 n_major n_minor, chi=0, b=0, g=1.
TriangleSoup make_torus(uint32_t n_major, uint32_t n_minor);

/// make_genus_surface(g, resolution) with h faces removed by remove_random_faces_as_holes()
/// (fixed seed). V as make_genus_surface, F = its F - h, chi=2-2g-h, b=h.
/// \throw RequestError if the surface has too few isolated interior faces for h holes.
TriangleSoup make_genus_with_holes(uint32_t g, uint32_t h, uint32_t resolution);

/// A Möbius band of n quads (2n triangles, 2n vertices). NOT orientable: some edge is used by
/// two faces in the same direction. For error tests only. \pre n >= 3.
TriangleSoup make_moebius_soup(uint32_t n);

// ---- Awkward families (docs/benchmarks.md): inputs on which strips are costly. Each scales from a few
// dozen to millions of triangles with its size parameters; make_awkward() picks them for a
// requested triangle count.

/// Constraint walls as vertex polylines along mesh edges (v0 v1 v2 ... = edges v0-v1, v1-v2, ...),
/// the shape of a constraints file.
using Polylines = std::vector<std::vector<uint32_t>>;

/// The edges of `lines` as vertex pairs, in order. O(total length).
std::vector<std::pair<uint32_t, uint32_t>> polyline_edges(const Polylines& lines);

/// Vertex pairs as StripOptions::constraint_edges (line 0: given directly, not read from a file).
std::vector<ConstraintEdge> as_constraints(const std::vector<std::pair<uint32_t, uint32_t>>& pairs);

/// A mesh with constraint walls that leave its faces edge-connected (walls may be empty).
struct WalledMesh {
    TriangleSoup soup;
    Polylines walls;
};

/// Corridors one quad wide between parallel holes: a grid of nx = length+2 by ny = 2 holes + 1
/// unit cells; cell row 2i+1 (i < holes) is a hole over columns 1..length, so rows 0, 2, 4, ...
/// are corridors joined by the end columns. \pre length >= 1.
/// V=(nx+1)(ny+1), F=2(nx ny - holes length), chi=1-holes, b=holes+1, g=0.
TriangleSoup make_hole_corridors(uint32_t holes, uint32_t length);

/// Corridors one quad wide between parallel slits (cuts): a grid of nx = length+2 by
/// ny = slits+1 unit cells cut along the lines y = 1..slits from x = 1 to x = length+1. The
/// slit's inner vertices are duplicated (same coordinates; the copy, numbered after the grid's
/// vertices, is used by the cells above), so each cut edge is boundary on both sides; the slit's
/// end vertices stay shared. \pre length >= 2 (a one-edge cut cannot be made by duplicating vertices).
/// V=(nx+1)(ny+1) + slits(length-1), F=2 nx ny, chi=1-slits, b=slits+1, g=0.
TriangleSoup make_slit_corridors(uint32_t slits, uint32_t length);

/// The same corridors with walls instead of cuts: make_grid_disk(length+2, slits+1) and one wall
/// per line y = 1..slits from x = 1 to x = length+1 (length edges, touching no boundary).
/// \pre length >= 1. V=(nx+1)(ny+1), F=2 nx ny, chi=1, b=1, g=0.
WalledMesh make_slit_walls(uint32_t slits, uint32_t length);

/// Serpentine walls two rows apart: make_grid_disk(length, 2(walls+1)); wall k = 1..walls runs
/// along y = 2k from the left border to x = length-1 (k odd) or from x = 1 to the right border
/// (k even), leaving a one-cell gap at the other end, so the corridors form one winding path.
/// \pre length >= 2. V=(length+1)(2 walls+3), F=4 length (walls+1), chi=1, b=1, g=0.
WalledMesh make_serpentine_walls(uint32_t walls, uint32_t length);

/// A disk with one small hole every ~200 triangles: a grid of nx = 10 bx by ny = 10 by unit cells,
/// one hole per 10 x 10 block (a, b), around its cell (x, y) = (10a+5, 10b+5), of kind a mod 3:
/// 0 = one triangle removed, 1 = the cell's two triangles removed, 2 = the 2 x 2 cells around
/// vertex (x, y) removed (8 triangles) and that vertex dropped. Holes share no vertex with each
/// other or the border. \pre bx, by >= 1. With h_k the holes of kind k and h = bx by:
/// V=(nx+1)(ny+1) - h_2, F=2 nx ny - h_0 - 2h_1 - 8h_2, chi=1-h, b=1+h, g=0.
TriangleSoup make_disk_many_holes(uint32_t bx, uint32_t by);

/// A grid with a hole far from every other: n x n unit cells, every diagonal from (i, j) to
/// (i+1, j+1) (its dual graph is bipartite, the two triangles of a cell of opposite colours), and
/// the cell (i, j) with i mod p = j mod p = p/2 removed, unless it touches the border. The engines'
/// searches meet each hole's colour shortfall far from any other hole's (issue 17: super-linear
/// at p = 70 before the forest's yield rule). \pre n >= 1, p >= 3.
/// V=(n+1)^2, F=2(n^2-h), chi=1-h, b=1+h, g=0, with h the holes.
TriangleSoup make_sparse_holes(uint32_t n, uint32_t period);

/// sparse_holes with each cell's diagonal drawn at random (Rng(seed)) and a hole every `period`
/// cells: cell (i, j) removed when n-2-i and n-2-j are multiples of p, so the last row and
/// column of holes leave a corridor one cell wide along two sides of the border (no hole touches
/// the border). The random diagonals make forced chains there, and the faces left short lie on
/// every side (issue 17: at 707 x 707 cells, p = 10, searches from one face at a time left 20
/// short and the engine fell back to the growth builder, +12.6%).
/// \pre n >= 1, period >= 3. V=(n+1)^2, F=2(n^2-h), chi=1-h, b=1+h, g=0, with h the holes.
TriangleSoup make_random_diagonal_holes(uint32_t n, uint32_t period, uint64_t seed);

/// Ears next to faces with two passable edges: make_grid_disk(nx, ny) with a two-triangle spike
/// on every bottom and top border edge. A spike is a face T on the border edge (two passable
/// edges: to the grid and to the ear) and an ear E on T's edge at the edge's left end (one
/// passable edge). Planar and CCW. \pre nx, ny >= 1.
/// V=(nx+1)(ny+1) + 4nx, F=2 nx ny + 4nx, chi=1, b=1, g=0.
TriangleSoup make_eared_grid(uint32_t nx, uint32_t ny);

/// Dead ends: a base row of 2·teeth unit cells with a tooth `height` cells tall on every other
/// cell (columns 0, 2, 4, ...) and an ear on each tooth's top edge. Every tooth is a chain of
/// 2·height + 1 faces hanging from the base by one edge, so each of its 2·height + 1 edges is a
/// bridge of the dual graph (the base's last cell, with no tooth, ends in one more ear). Planar
/// and CCW. \pre teeth, height >= 1.
/// V=2(2 teeth+1) + teeth(2 height+1), F=teeth(2 height+5), chi=1, b=1, g=0.
TriangleSoup make_spiked_comb(uint32_t teeth, uint32_t height);

/// A cone whose apex (vertex 0, at z=1) has valence k: k side triangles to a ring of k vertices
/// (1..k, unit circle, z=0). Open (capped=false): the ring is the boundary, the apex interior;
/// V=k+1, F=k, chi=1, b=1. Capped: a flat disk facing down closes the ring: concentric rings of
/// n_1 = max(3, ceil(k/2)), n_2 = max(3, ceil(n_1/2)), ... vertices down to 3 (each zipped to
/// the previous one), then one triangle; every cap vertex has a small valence and every face is
/// well shaped. With c = n_1 + n_2 + ... (about k): V=k+1+c, F=2(k+c)-2, chi=2, b=0. g=0.
/// \pre k >= 3.
TriangleSoup make_cone(uint32_t k, bool capped);

enum class AwkwardFamily : uint8_t {
    HoleCorridors,    ///< make_hole_corridors
    SlitCorridors,    ///< make_slit_corridors
    SlitWalls,        ///< make_slit_walls
    SerpentineWalls,  ///< make_serpentine_walls
    ManyHoles,        ///< make_disk_many_holes
    Ears,             ///< make_eared_grid(nx, 4)
    OpenCone,         ///< make_cone(k, false)
    ClosedCone,       ///< make_cone(k, true), about 4k faces
    SpikedComb,       ///< make_spiked_comb(teeth, 5)
    HoleLadder,       ///< make_disk_with_holes(k, 1): a hole every ten faces, in one row
    HighGenus,        ///< make_genus_surface(g, 1): genus g, about 36 faces per handle
    SparseHoles,      ///< make_sparse_holes(n, 70): a one-cell hole per ~9,800 faces (smaller: n/2)
    DiagonalHoles,    ///< make_random_diagonal_holes(n, 10, 1): a one-cell hole per ~200 faces
    PolygonTree,      ///< make_circle_polygon(F + 2): a tree of faces
};
inline constexpr AwkwardFamily kAwkwardFamilies[] = {
    AwkwardFamily::HoleCorridors, AwkwardFamily::SlitCorridors, AwkwardFamily::SlitWalls, AwkwardFamily::SerpentineWalls,
    AwkwardFamily::ManyHoles,     AwkwardFamily::Ears,          AwkwardFamily::OpenCone,  AwkwardFamily::ClosedCone,
    AwkwardFamily::SpikedComb,    AwkwardFamily::HoleLadder,    AwkwardFamily::HighGenus, AwkwardFamily::SparseHoles,
    AwkwardFamily::DiagonalHoles, AwkwardFamily::PolygonTree};

/// "hole_corridors", "slit_corridors", "slit_walls", "serpentine_walls", "many_holes", "ears",
/// "open_cone", "closed_cone", "spiked_comb", "hole_ladder", "high_genus", "sparse_holes", "diagonal_holes",
/// "polygon_tree".
const char* awkward_family_name(AwkwardFamily family) noexcept;

/// The family at about `triangles` faces (grids kept roughly square, except the eared grid,
/// 4 rows tall so a third of its faces are spike faces). The count is within 10% of the request
/// for requests >= 10000; small requests give a small member of the family. Walls are empty
/// for families without them.
WalledMesh make_awkward(AwkwardFamily family, uint32_t triangles);

// ---- Random relabellings (same surface, different input order).

/// Renumbers the vertices by a random permutation (points moved accordingly); returns the new
/// index of every old vertex (apply it to constraint polylines, source and target).
/// Deterministic for a given seed. O(V + F).
std::vector<uint32_t> shuffle_vertices(TriangleSoup& soup, uint64_t seed);

/// Puts the faces in a random order (source_polygon entries move with their faces) and rotates
/// each face's corners by a random amount (orientation kept). Deterministic for a given seed. O(F).
void shuffle_faces(TriangleSoup& soup, uint64_t seed);

/// Performs up to `count` random flips of interior edges; returns the number performed (at
/// most 10*count+100 candidates are tried). Edge (a,b) between faces (a,b,c) and (b,a,d) becomes
/// (c,d) with faces (a,d,c) and (d,b,c): orientation stays consistent. A flip is skipped when
/// c == d, the edge (c,d) already exists, or a or b would be left with fewer than 3 edges.
/// Topology (V, F, chi, b, g, connectivity, manifoldness) is unchanged; geometry is ignored
/// (planar meshes may fold). source_polygon entries stay with their face slots.
/// \pre soup is an oriented manifold. Deterministic for a given seed. O(F + attempts).
size_t random_edge_flips(TriangleSoup& soup, size_t count, uint64_t seed);

/// Removes k faces none of whose vertices lies on the boundary or on another removed face:
/// each removal adds one boundary loop, keeps the mesh manifold and edge-connected and every
/// vertex referenced (b += k, chi -= k). Deterministic for a given seed.
/// \pre soup is an oriented manifold. \throw RequestError if fewer than k such faces exist.
/// O(V + F).
void remove_random_faces_as_holes(TriangleSoup& soup, size_t k, uint64_t seed);

}  // namespace singlestrip
