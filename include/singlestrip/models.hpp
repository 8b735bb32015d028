// singlestrip — the procedural models the library itself needs: `builtin:genus2` (read_input(),
// pipeline.hpp) and the grid and genus surfaces it is made of. The test meshes and random
// perturbations built on them live in tests/support/fixtures.hpp, outside the library.
//
// Every model is a TriangleSoup with no unreferenced vertices, an empty source_polygon and
// consistently oriented faces (counter-clockwise seen from +z when planar, outward when closed).
// Counts: V / F, chi (Euler characteristic), b (boundary loops), g (genus). Bad parameters throw
// RequestError. All are O(V + F).
#pragma once

#include <cstdint>
#include <functional>

#include "singlestrip/soup.hpp"

namespace singlestrip {

/// Planar grid of nx x ny cells of size `cell` in z=0, keeping the cells for which keep(i, j) is
/// true; each kept cell is two triangles, diagonals alternating in a checkerboard. Vertices no
/// kept cell uses are dropped (indices compacted, row-major order kept). \pre nx, ny >= 1.
TriangleSoup make_grid_cells(uint32_t nx, uint32_t ny, double cell, const std::function<bool(uint32_t, uint32_t)>& keep);

/// Planar grid of (2k+1)r x 3r cells (r = resolution) with k square holes of r x r cells in a row
/// (hole i covers cells x in [(2i+1)r, (2i+2)r), y in [r, 2r)). \pre resolution >= 1.
/// V=(nx+1)(ny+1) - k(r-1)^2, F=2(nx ny - k r^2) with nx=(2k+1)r, ny=3r;
/// chi=1-k, b=k+1, g=0.
TriangleSoup make_disk_with_holes(uint32_t k, uint32_t resolution);

/// Closed surface of genus g: a thickened make_disk_with_holes(g, resolution) plate (cells of
/// size 1/r, so the plate is (2g+1) x 3 units). The top grid (z=+0.3) and a mirrored bottom grid
/// (z=-0.3, vertex i+Vt below vertex i) are joined by one band of quads along the outer border
/// and around each hole. \pre resolution >= 1.
/// With Vt, Ft the counts of make_disk_with_holes(g, resolution) and Bt = 2(nx+ny) + 4gr its
/// boundary edges: V=2 Vt, F=2 Ft + 2 Bt, chi=2-2g, b=0.
TriangleSoup make_genus_surface(uint32_t g, uint32_t resolution);

/// The demo model `builtin:genus2`: a gently waved genus-2 plate, make_genus_surface(2, 8)
/// displaced (V=1854, F=3712, chi=-2, b=0, g=2).
TriangleSoup make_builtin_model();

}  // namespace singlestrip
