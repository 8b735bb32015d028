// singlestrip — reading meshes, constraint files, and writing results atomically.
//
// Input formats (chosen by the file extension, case-insensitive):
//   .obj  Wavefront OBJ (v / vt / vn / f records; f entries "i", "i/t", "i/t/n", "i//n";
//         1-based, negative = relative; other records are skipped). Texture coordinates and
//         normals every corner has become TEXCOORD_0 / NORMAL, vertex colours "v x y z r g b"
//         COLOR_0 (TriangleSoup::attributes); a position used with several (vt, vn) is one
//         vertex per combination, the extra ones after the file's vertices (read_obj.cpp)
//   .off  [ST][C][N]OFF, ASCII or BINARY: vertex normals, colours and texture coordinates
//         become NORMAL, COLOR_0 (in [0, 1]) and TEXCOORD_0; face colours are checked, not kept
//   .ply  PLY, ASCII or binary (little/big endian); faces from `face` and `tristrips` elements;
//         scalar vertex properties become attributes (nx ny nz: NORMAL; red green blue [alpha]:
//         COLOR_0, integers scaled to [0, 1]; s t, u v, texture_u texture_v: TEXCOORD_0; any
//         other under its name); list properties and other elements are skipped
//   .stl  STL, ASCII or binary
// Each format has one strict parser (src/io/read_<format>.cpp, whose header states its grammar)
// that reads the bytes once and names the file, the line (text) or element and item (binary),
// and the problem of anything it refuses. Face numbers in messages are the file's polygons.
//
// Vertex numbering. Users name vertices by their index in the file, so vertices keep the file's
// order and indices (0-based; the CLI's `--index-base 1` reads user numbers 1-based through
// from_index_base() and read_constraints_based()). Unreferenced vertices are kept (algorithms
// ignore them).
// STL has no shared vertices: its corners are WELDED — corners with exactly equal coordinates
// (equal as doubles after parsing, so -0 == +0; no tolerance) are one vertex, and vertices are
// numbered in order of first appearance in the file. Corners that differ in the last bit stay
// separate vertices (the mesh then shows a boundary or several components there).
//
// Polygons with k > 3 corners (v0..v{k-1}) are fan-triangulated as (v0, vi, vi+1), i = 1..k-2,
// in file order; TriangleSoup::source_polygon[t] is the file polygon of triangle t. The triangle
// index after triangulation is what the output's `parent` refers to.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "singlestrip/soup.hpp"

namespace singlestrip {

/// Limits of read_mesh_file.
struct ReadOptions {
    /// Files (and named pipes) with more bytes are refused before they are read past this size;
    /// the bytes are held in memory once. 4 GiB is a binary STL of 85M triangles.
    std::uint64_t max_input_bytes = std::uint64_t{4} << 30;
    /// "obj", "off", "ply" or "stl" (any case) reads the file as that format whatever its name
    /// (`/dev/stdin`, a pipe, a file without extension); empty: chosen by the extension.
    std::string format;
};

/// Reads a mesh file (see formats above) into a triangle soup, in file order. `path` may be a
/// regular file or a named pipe (read once, to its end); the format comes from its extension
/// unless `options.format` names it.
/// \throw InputError (message starts with the path) when the file is missing or unreadable,
///        not a regular file or a pipe (a device, a socket, a directory), larger than
///        `options.max_input_bytes`, empty, has an unknown extension (or `options.format` is
///        not one of the four), is malformed or truncated,
///        has a face index out of range ("face N references vertex K but the file has only M
///        vertices"), a NaN or infinite coordinate ("vertex N"), a polygon with fewer than 3
///        corners, or no faces (the message then names the elements or records not read).
/// PLY `tristrips`: each list holds strips separated by -1 (or, for unsigned entries, the
/// type's largest value); triangle i of a strip is (v_i, v_i+1, v_i+2) for even i and
/// (v_i+1, v_i, v_i+2) for odd i; triangles with a repeated vertex are skipped, and each strip
/// triangle is a polygon of its own in `source_polygon`.
/// Structural problems (repeated vertex, non-manifold, orientation, ...) are NOT checked here:
/// see validate.hpp. Complexity O(file size); memory O(file size), never proportional to a
/// count the file declares.
TriangleSoup read_mesh_file(const std::string& path, const ReadOptions& options = {});

/// Reads a constraint file: one polyline per line, written as whitespace-separated input vertex
/// indices (0-based); '#' starts a comment; blank lines are ignored. A polyline a b c yields the
/// vertex pairs (a,b), (b,c), in file order, each with its line (ConstraintEdge, soup.hpp).
/// Whether a pair is a mesh edge is checked by stripify() (RequestError), not here.
/// \throw InputError naming the file and line for a missing/unreadable file, a token that is
///        not a non-negative integer, a polyline with a single vertex, or an index >= num_vertices.
std::vector<ConstraintEdge> read_constraints(const std::string& path, uint32_t num_vertices);

/// The vertex pairs of `edges`, in order (VerifyInput::constraints).
std::vector<std::pair<uint32_t, uint32_t>> vertex_pairs(const std::vector<ConstraintEdge>& edges);

/// Vertex numbering chosen by the user (`--index-base`): 0 (the default, the numbering of every
/// output file and of the library) or 1 (OBJ's own numbering). Returns `number - base`.
/// \throw RequestError "<what> 0 is not a vertex number when numbering starts at 1" for 0 with
///        base 1, or for a base other than 0 and 1. O(1).
uint32_t from_index_base(uint32_t number, uint32_t base, const std::string& what);

/// read_constraints() for a file whose vertex numbers start at `index_base` (0 or 1); the pairs
/// returned are 0-based. \throw InputError as read_constraints(), naming the file, the line and
/// the number for a 0 in a 1-based file or a number above the vertex count. O(file size).
std::vector<ConstraintEdge> read_constraints_based(const std::string& path, uint32_t num_vertices, uint32_t index_base);

/// Refuses outputs that would overwrite an input or each other: two entries of `outputs` naming
/// the same file (same path after normalisation, or the same existing file through a link), or
/// an output naming one of `inputs`. "-" (standard output) may appear once. Empty strings are
/// ignored. \throw RequestError naming both uses of the file, before anything is written.
/// O(n^2) in the number of paths (a handful).
void refuse_overwrites(const std::vector<std::pair<std::string, std::string>>& inputs,
                       const std::vector<std::pair<std::string, std::string>>& outputs);

/// `s` with ASCII letters in lower case (format names and extensions are case-insensitive).
std::string ascii_lower(std::string s);

/// The extension of `path`'s file name with its dot, lower-cased (".ply"); empty when it has none.
std::string lower_extension(const std::string& path);

/// Output mesh formats, chosen by extension (glTF has its own writer, gltf.hpp).
enum class OutputFormat { Ply, Obj, Off, Stl };

/// Output format of `path` from its extension (.ply / .obj / .off / .stl, case-insensitive).
/// \throw RequestError for any other extension, listing every extension `singlestrip strip`
///        writes (.glb and .gltf included), before any work is done.
OutputFormat output_format_for(const std::string& path);

/// Writes the strip mesh: `points` (input vertices first, unchanged; midpoints after) and `faces`
/// in the given (strip) order, each with its winding.
///   .ply: binary_little_endian 1.0; `element vertex` with `property double x y z` and one
///         property per attribute component (NORMAL: float nx ny nz; TEXCOORD_0: float s t;
///         COLOR_0: uchar red green blue [alpha]; any other: double <name> or <name>_<c>, int
///         for AttributeBlend::Nearest); `element face` with `property list uchar uint
///         vertex_indices` and `property uint parent`.
///   .obj: "v x y z" lines ("v x y z r g b" with COLOR_0), one "vt u v" per vertex with
///         TEXCOORD_0, one "vn x y z" per vertex with NORMAL, then "f a/a/a b/b/b c/c/c" (1-based; "a/a", "a//a" or "a" as the
///         attributes go); OBJ has no place for `parent` or other attributes.
///   .off: "[ST][C][N]OFF" as the attributes go, counts, vertices "x y z [nx ny nz] [r g b [a]]
///         [s t]" (NORMAL, COLOR_0 as fractions clamped into [0, 1], TEXCOORD_0), "3 a b c" faces.
///   .stl: binary STL, one float32 facet per face with its unit normal; STL has no shared
///         vertices, no `parent` and float32 coordinates, so `verify` cannot check it.
/// Text formats write the shortest decimal that round-trips (std::to_chars), so coordinates read
/// back bit-exact.
/// The file is written to a temporary in the same directory and renamed into place at the end:
/// a failure never leaves a partial output.
/// \pre parent.size() == faces.size(), every face index < points.size().
/// \throw RequestError for an unknown extension (before writing), OutputError on any I/O failure.
void write_strip_mesh(const std::string& path, const std::vector<Point3>& points, const std::vector<Triangle>& faces,
                      const std::vector<uint32_t>& parent, const std::vector<VertexAttribute>& attributes = {});

/// Writes indices as whitespace-separated decimal text, 16 per line, atomically.
/// \throw OutputError.
void write_indices(const std::string& path, const std::vector<uint32_t>& indices);

/// Writes `text` to `path` atomically (temporary file in the same directory + rename).
/// \throw OutputError.
void write_text_atomic(const std::string& path, std::string_view text);

/// Writes {"cycles": [[face, ...], ...], "lengths": [...]} atomically (temporary + rename).
/// \throw OutputError if the file cannot be written.
void write_cycles_json(const std::string& path, const Cycles& cycles);

/// Writes each cycle's polyline (cycle_polylines(), cycles.hpp: face centroids and shared-edge
/// midpoints) as a closed OBJ polyline (`v` lines, then one `l` line per cycle whose last index
/// repeats its first), atomically.
/// \throw OutputError if the file cannot be written.
void write_cycles_obj(const std::string& path, const std::vector<std::vector<Point3>>& polylines);

}  // namespace singlestrip
