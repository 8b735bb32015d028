// singlestrip — procedural test meshes and random manifold-preserving perturbations.
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

#include "singlestrip/soup.hpp"

namespace singlestrip {

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

/// Planar ring: n_around segments around, n_radial quad rings between radius 1 and 2.
/// \pre n_around >= 3, n_radial >= 1. V=n_around (n_radial+1), F=2 n_around n_radial,
/// chi=0, b=2, g=0.
TriangleSoup make_annulus(uint32_t n_around, uint32_t n_radial);

/// Planar grid of (2k+1)r x 3r cells (r = resolution) with k square holes of r x r cells in a row
/// (hole i covers cells x in [(2i+1)r, (2i+2)r), y in [r, 2r)). \pre resolution >= 1.
/// V=(nx+1)(ny+1) - k(r-1)^2, F=2(nx ny - k r^2) with nx=(2k+1)r, ny=3r;
/// chi=1-k, b=k+1, g=0.
TriangleSoup make_disk_with_holes(uint32_t k, uint32_t resolution);

/// Unit sphere from an icosahedron, each face split into 4 per subdivision.
/// \pre subdivisions <= 10. V=10*4^s+2, F=20*4^s, chi=2, b=0, g=0.
TriangleSoup make_icosphere(uint32_t subdivisions);

/// Unit latitude/longitude sphere with two poles. \pre n_lon >= 3, n_lat >= 2.
/// V=n_lon (n_lat-1) + 2, F=2 n_lon (n_lat-1), chi=2, b=0, g=0.
TriangleSoup make_uv_sphere(uint32_t n_lon, uint32_t n_lat);

/// Torus with radii 1 and 0.35. \pre n_major, n_minor >= 3.
/// V=n_major n_minor, F=2 n_major n_minor, chi=0, b=0, g=1.
TriangleSoup make_torus(uint32_t n_major, uint32_t n_minor);

/// Closed surface of genus g: a thickened make_disk_with_holes(g, resolution) plate (cells of
/// size 1/r, so the plate is (2g+1) x 3 units). The top grid (z=+0.3) and a mirrored bottom grid
/// (z=-0.3, vertex i+Vt below vertex i) are joined by one band of quads along the outer border
/// and around each hole. \pre resolution >= 1.
/// With Vt, Ft the counts of make_disk_with_holes(g, resolution) and Bt = 2(nx+ny) + 4gr its
/// boundary edges: V=2 Vt, F=2 Ft + 2 Bt, chi=2-2g, b=0.
TriangleSoup make_genus_surface(uint32_t g, uint32_t resolution);

/// make_genus_surface(g, resolution) with h faces removed by remove_random_faces_as_holes()
/// (fixed seed). V as make_genus_surface, F = its F - h, chi=2-2g-h, b=h.
/// \throw RequestError if the surface has too few isolated interior faces for h holes.
TriangleSoup make_genus_with_holes(uint32_t g, uint32_t h, uint32_t resolution);

/// A Möbius band of n quads (2n triangles, 2n vertices). NOT orientable: some edge is used by
/// two faces in the same direction. For error tests only. \pre n >= 3.
TriangleSoup make_moebius_soup(uint32_t n);

/// The demo model: a gently waved genus-2 plate, make_genus_surface(2, 8) displaced
/// (V=1854, F=3712, chi=-2, b=0, g=2).
TriangleSoup make_builtin_model();

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
