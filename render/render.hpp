// singlestrip — offscreen pictures of a strip with real OpenGL (Mesa OSMesa, legacy GL 1.x).
//
// The strip is drawn as ONE GL_TRIANGLE_STRIP whose vertex sequence is exactly our index
// buffer (encode_triangle_strip of the faces in strip order), flat shaded (the provoking vertex
// of strip triangle i is index i+2), so each face gets the colour of its position along the
// strip and a headlight Lambert term from its own geometric normal. Overlays: fundamental
// cycles as closed polylines (centroids and shared-edge midpoints, cycles.hpp), constraint edges
// as lines, source (green) and target (red) as points, optionally the strip's route as a line
// with its start and end marked; hidden overlay parts are drawn faintly.
// PNG files are written with libpng, atomically (temporary + rename).
//
// Built only when OSMesa and libpng are found (render/CMakeLists.txt); then the targets that
// link singlestrip_render get SINGLESTRIP_HAVE_RENDER=1.
//
// Thread safety: every call creates and destroys its own OSMesa context; calls may run on
// different threads (Mesa's software rasterizer is re-entrant per context).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "singlestrip/soup.hpp"
#include "singlestrip/strip.hpp"

namespace singlestrip::render {

/// An 8-bit RGBA picture, rows from TOP to bottom.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgba;  ///< width * height * 4
};

/// Perspective camera (30-degree field of view) looking at the bounding-box centre of the
/// points, far enough away that the bounding sphere fits. The eye direction (from the centre)
/// is, for y-up, (cos el cos az, sin el, cos el sin az); for z-up, (cos el cos az,
/// cos el sin az, sin el).
struct View {
    double azimuth_deg = 35.0;
    double elevation_deg = 25.0;
    bool z_up = false;  ///< false: +y is up (most mesh files); true: +z is up
};

struct Style {
    int width = 1000;
    int height = 800;
    std::array<float, 3> background{1.0f, 1.0f, 1.0f};
    float line_width = 3.0f;
    float point_size = 14.0f;
    bool light = true;  ///< headlight Lambert shading; off = flat strip colours
    /// The blue-to-red ramp is repeated this many times along the strip (saw-tooth), so that on
    /// a long strip neighbouring parts get clearly different hues. At least 1.
    int bands = 1;
};

/// What to draw on top of the strip.
struct Overlays {
    std::vector<std::vector<Point3>> closed_polylines;  ///< cycles (each closed implicitly)
    std::vector<std::pair<Point3, Point3>> segments;    ///< constraint edges
    std::optional<Point3> source;
    std::optional<Point3> target;
    /// The strip's route (route.hpp), drawn as a dark open polyline over the surface with its
    /// first point marked green and its last red.
    std::vector<Point3> route;
};

/// The default view of `points`: a mesh flat in z, y or x (extent below 1e-9 of the largest) is
/// seen from straight above its plane; any other from azimuth 35, elevation 25, +y up. O(V).
View auto_view(const std::vector<Point3>& points);

/// Renders the strip. `strip_indices` is a GL_TRIANGLE_STRIP index sequence into `points`.
/// \throw RequestError if an index is out of range or the sizes are not positive;
///        Error (InternalError) if no OSMesa context can be created.
Image render_strip(const std::vector<Point3>& points, const std::vector<uint32_t>& strip_indices, const Overlays& overlays,
                   const View& view = {}, const Style& style = {});

/// Primitive type for render_coverage().
enum class Primitive { Triangles, TriangleStrip };

/// Coverage test picture: `indices` drawn with glDrawElements(GL_TRIANGLES or
/// GL_TRIANGLE_STRIP, ...) from a vertex array of `points`, flat colour, GL_CULL_FACE on (back
/// faces = clockwise on screen are discarded), no depth test, additive blending so each pixel
/// holds the number of front-facing layers covering it (saturating at 255). The camera is
/// computed from `frame_points` (so two meshes with the same bounding box get the same camera).
/// Returns width*height counts, rows top to bottom.
std::vector<uint8_t> render_coverage(const std::vector<Point3>& points, const std::vector<uint32_t>& indices, Primitive primitive,
                                     const std::vector<Point3>& frame_points, const View& view, int width, int height);

/// Textured test picture: `indices` drawn as GL_TRIANGLES or GL_TRIANGLE_STRIP with texture
/// coordinates `uv` (2 per point; a TEXCOORD_0 attribute) on a procedural 64x64 texture (red =
/// u, green = v, blue = an 8x8 checkerboard; repeated, bilinear, perspective-correct), back faces
/// culled, depth test on. Camera as render_coverage(). Two drawings of the same surface with the
/// same texture coordinates give the same picture up to rounding in the interpolation; a
/// midpoint with the wrong texture coordinate shows. Returns width*height*4 RGBA bytes, rows top
/// to bottom. \throw RequestError for an index out of range or uv.size() != 2 * points.size().
std::vector<uint8_t> render_textured(const std::vector<Point3>& points, const std::vector<double>& uv, const std::vector<uint32_t>& indices,
                                     Primitive primitive, const std::vector<Point3>& frame_points, const View& view, int width, int height);

/// Writes `img` as an 8-bit RGBA PNG, atomically. \throw OutputError.
void write_png(const std::string& path, const Image& img);

/// Reads an 8-bit RGB/RGBA PNG (tests). \throw InputError.
Image read_png(const std::string& path);

/// Arguments of `singlestrip render`.
struct RenderArgs {
    std::string input;                       ///< RESULT.ply (or .obj/.off) written by `strip`
    std::string output;                      ///< picture.png
    std::optional<std::string> cycles;       ///< cycles JSON ({"cycles": [[face, ...], ...]})
    std::optional<std::string> constraints;  ///< constraint polylines file
    std::optional<uint32_t> source, target;  ///< vertex ids to mark
    /// Set: `input` is any mesh (or builtin:genus2), stripped first with this engine
    /// (pipeline.hpp), `constraints`, `source` and `target` being the strip's request too.
    std::optional<StripEngine> engine;
    bool with_cycles = false;  ///< with `engine`: draw the computed cycles
    bool polish = false;       ///< with `engine`: StripOptions::polish
    bool route = false;        ///< draw the strip's route (route.hpp)
    /// Vertex numbers in `constraints`, `source`, `target` start at this (0 or 1).
    uint32_t index_base = 0;
    bool auto_view = true;  ///< true: `view` is ignored and auto_view() used
    View view;
    Style style;
};

/// `singlestrip render`: reads the result (read_output_mesh) and re-encodes its faces with
/// encode_triangle_strip, or with `engine` strips the input mesh (stripify()); renders, writes
/// the PNG. Returns app::kExitOk (src/app/exit_codes.hpp).
/// \throw InputError (unreadable files, an invalid mesh, a glTF result), RequestError (vertex out of range,
///        output not .png, --cycles with an engine, an impossible strip request), OutputError,
///        InternalError — for the CLI's usual mapping to exit codes.
int run_render_command(const RenderArgs& args);

}  // namespace singlestrip::render
