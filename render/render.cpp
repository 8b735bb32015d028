// Offscreen rendering through OSMesa (legacy fixed-function GL) and PNG I/O through libpng.
#include "render/render.hpp"

#include <GL/gl.h>
#include <GL/osmesa.h>
#include <png.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "app/exit_codes.hpp"
#include "singlestrip/cycles.hpp"
#include "singlestrip/encode.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/gltf.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/pipeline.hpp"
#include "singlestrip/route.hpp"
#include "singlestrip/strip.hpp"
#include "singlestrip/vec3.hpp"
#include "singlestrip/verify.hpp"

namespace singlestrip::render {
namespace {

using Vec = Point3;
using vec3::cross;
using vec3::dot;
using vec3::normalized;
using vec3::sub;

/// An OSMesa context with its own RGBA colour buffer, current for its lifetime.
class Context {
public:
    Context(int w, int h) : w_(w), h_(h), pixels_(static_cast<size_t>(w) * static_cast<size_t>(h) * 4) {
        ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
        if (!ctx_) throw InternalError("render: cannot create an OSMesa context");
        if (!OSMesaMakeCurrent(ctx_, pixels_.data(), GL_UNSIGNED_BYTE, w, h)) {
            OSMesaDestroyContext(ctx_);
            throw InternalError("render: cannot make the OSMesa context current");
        }
        glViewport(0, 0, w, h);
        glDisable(GL_DITHER);
    }
    ~Context() { OSMesaDestroyContext(ctx_); }
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    /// The colour buffer, rows top to bottom (OSMesa stores them bottom-up).
    std::vector<uint8_t> pixels_top_down() {
        glFinish();
        std::vector<uint8_t> out(pixels_.size());
        const size_t row = static_cast<size_t>(w_) * 4;
        for (int y = 0; y < h_; ++y)
            std::copy_n(pixels_.data() + static_cast<size_t>(h_ - 1 - y) * row, row, out.data() + static_cast<size_t>(y) * row);
        return out;
    }

private:
    OSMesaContext ctx_ = nullptr;
    int w_, h_;
    std::vector<uint8_t> pixels_;
};

struct Camera {
    Vec eye, centre, up;
    double radius, distance;
};

Camera make_camera(const std::vector<Point3>& pts, const View& v) {
    Vec lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    Vec hi{-lo[0], -lo[1], -lo[2]};
    for (const Point3& p : pts)
        for (int d = 0; d < 3; ++d) {
            if (!std::isfinite(p[d])) continue;
            lo[d] = std::min(lo[d], p[d]);
            hi[d] = std::max(hi[d], p[d]);
        }
    if (!(lo[0] <= hi[0])) lo = hi = Vec{0, 0, 0};
    Camera c;
    c.centre = {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
    c.radius = std::max(1e-12, std::sqrt(dot(sub(hi, lo), sub(hi, lo))) / 2);
    const double az = v.azimuth_deg * M_PI / 180.0, el = v.elevation_deg * M_PI / 180.0;
    Vec dir = v.z_up ? Vec{std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)}
                     : Vec{std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az)};
    c.up = v.z_up ? Vec{0, 0, 1} : Vec{0, 1, 0};
    // Looking straight down the up axis: any horizontal up vector will do.
    if (std::abs(dot(normalized(dir), c.up)) > 0.999) c.up = v.z_up ? Vec{0, 1, 0} : Vec{0, 0, -1};
    c.distance = c.radius / std::sin(15.0 * M_PI / 180.0) * 1.02;
    c.eye = {c.centre[0] + dir[0] * c.distance, c.centre[1] + dir[1] * c.distance, c.centre[2] + dir[2] * c.distance};
    return c;
}

/// Loads the projection and modelview matrices. The frustum is fitted to the projection of
/// `pts` (5% margin) so the model fills the picture whatever its shape.
void load_camera(const Camera& c, const std::vector<Point3>& pts, int w, int h) {
    const double aspect = static_cast<double>(w) / static_cast<double>(h);
    const double near = std::max(c.distance - 1.5 * c.radius, c.distance * 0.01);
    const double far = c.distance + 1.5 * c.radius;
    // gluLookAt, written out (no GLU dependency).
    const Vec f = normalized(sub(c.centre, c.eye));
    const Vec s = normalized(cross(f, c.up));
    const Vec u = cross(s, f);
    double l = 0, r = 0, b = 0, t = 0;  // extents of x/depth and y/depth around the centre
    bool any = false;
    for (const Point3& p : pts) {
        const Vec d = sub(p, c.eye);
        const double depth = dot(d, f);
        if (!(depth > 0) || !std::isfinite(depth)) continue;
        const double x = dot(d, s) / depth, y = dot(d, u) / depth;
        l = std::min(l, x), r = std::max(r, x), b = std::min(b, y), t = std::max(t, y);
        any = true;
    }
    if (!any) l = b = -std::tan(15.0 * M_PI / 180.0), r = t = -l;
    // Grow the smaller extent to the picture's aspect ratio, keeping the model centred.
    double cx = (l + r) / 2, cy = (b + t) / 2, hw = (r - l) / 2 * 1.05, hh = (t - b) / 2 * 1.05;
    if (hw <= 0 && hh <= 0) hw = hh = 1e-3;
    if (hw / hh > aspect)
        hh = hw / aspect;
    else
        hw = hh * aspect;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum((cx - hw) * near, (cx + hw) * near, (cy - hh) * near, (cy + hh) * near, near, far);
    const double m[16] = {s[0], u[0], -f[0], 0, s[1],           u[1],           -f[1],         0,
                          s[2], u[2], -f[2], 0, -dot(s, c.eye), -dot(u, c.eye), dot(f, c.eye), 1};
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixd(m);
}

/// Colour along the strip: blue -> cyan -> green -> yellow -> red.
std::array<float, 3> ramp(double t) {
    static const float stops[5][3] = {
        {0.19f, 0.30f, 0.78f}, {0.25f, 0.70f, 0.90f}, {0.38f, 0.80f, 0.35f}, {0.98f, 0.80f, 0.25f}, {0.85f, 0.22f, 0.18f}};
    t = std::clamp(t, 0.0, 1.0) * 4.0;
    const int i = std::min(3, static_cast<int>(t));
    const float a = static_cast<float>(t - i);
    return {stops[i][0] * (1 - a) + stops[i + 1][0] * a, stops[i][1] * (1 - a) + stops[i + 1][1] * a,
            stops[i][2] * (1 - a) + stops[i + 1][2] * a};
}

/// Position in the ramp of a face at `t` in [0, 1] along the strip, with the ramp repeated
/// `bands` times (saw-tooth; the last face still ends on red).
double band_position(double t, int bands) {
    if (bands <= 1 || t >= 1.0) return t;
    const double x = t * bands;
    return x - std::floor(x);
}

void check_indices(const std::vector<Point3>& points, const std::vector<uint32_t>& indices) {
    for (uint32_t i : indices)
        if (i >= points.size())
            throw RequestError("render: index " + std::to_string(i) + " out of range (" + std::to_string(points.size()) + " vertices)");
}

/// Draws the overlays; `alpha` < 1 for the faint "hidden" pass.
void draw_overlays(const Overlays& o, const Style& st, int scale, float alpha) {
    static const float palette[6][3] = {{0.85f, 0.0f, 0.75f}, {0.05f, 0.05f, 0.05f}, {1.0f, 0.55f, 0.0f},
                                        {0.45f, 0.0f, 0.85f}, {0.0f, 0.55f, 0.55f},  {0.6f, 0.3f, 0.0f}};
    glLineWidth(st.line_width * static_cast<float>(scale));
    for (size_t c = 0; c < o.closed_polylines.size(); ++c) {
        const float* col = palette[c % 6];
        glColor4f(col[0], col[1], col[2], alpha);
        glBegin(GL_LINE_LOOP);
        for (const Point3& p : o.closed_polylines[c]) glVertex3d(p[0], p[1], p[2]);
        glEnd();
    }
    if (!o.segments.empty()) {
        glColor4f(0.0f, 0.0f, 0.0f, alpha);
        glBegin(GL_LINES);
        for (const auto& [a, b] : o.segments) {
            glVertex3d(a[0], a[1], a[2]);
            glVertex3d(b[0], b[1], b[2]);
        }
        glEnd();
    }
    if (o.route.size() >= 2) {
        glColor4f(0.1f, 0.1f, 0.1f, alpha);
        glLineWidth(std::max(1.0f, st.line_width * 0.5f) * static_cast<float>(scale));
        glBegin(GL_LINE_STRIP);
        for (const Point3& p : o.route) glVertex3d(p[0], p[1], p[2]);
        glEnd();
    }
    glPointSize(st.point_size * static_cast<float>(scale));
    glBegin(GL_POINTS);
    if (!o.route.empty()) {  // route start green, end red, like source and target
        glColor4f(0.0f, 0.65f, 0.1f, alpha);
        glVertex3d(o.route.front()[0], o.route.front()[1], o.route.front()[2]);
        glColor4f(0.9f, 0.0f, 0.0f, alpha);
        glVertex3d(o.route.back()[0], o.route.back()[1], o.route.back()[2]);
    }
    if (o.source) {
        glColor4f(0.0f, 0.65f, 0.1f, alpha);
        glVertex3d((*o.source)[0], (*o.source)[1], (*o.source)[2]);
    }
    if (o.target) {
        glColor4f(0.9f, 0.0f, 0.0f, alpha);
        glVertex3d((*o.target)[0], (*o.target)[1], (*o.target)[2]);
    }
    glEnd();
}

}  // namespace

Image render_strip(const std::vector<Point3>& points, const std::vector<uint32_t>& s, const Overlays& overlays, const View& view,
                   const Style& style) {
    if (style.width <= 0 || style.height <= 0 || style.width > 8192 || style.height > 8192)
        throw RequestError("render: picture size must be between 1 and 8192 pixels");
    check_indices(points, s);
    // OSMesa has no multisampling: render at twice the size and average 2x2 blocks.
    constexpr int kScale = 2;
    const int W = style.width * kScale, H = style.height * kScale;
    Context ctx(W, H);
    const Camera cam = make_camera(points, view);
    load_camera(cam, points, W, H);
    glClearColor(style.background[0], style.background[1], style.background[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glShadeModel(GL_FLAT);  // provoking vertex = last vertex of each strip triangle
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);  // overlays drawn on the surface stay in front of it

    // Count the real (non-degenerate) triangles to spread the colour ramp over them.
    size_t real = 0;
    for (size_t i = 0; i + 2 < s.size(); ++i)
        if (s[i] != s[i + 1] && s[i + 1] != s[i + 2] && s[i] != s[i + 2]) ++real;
    const double denom = real > 1 ? static_cast<double>(real - 1) : 1.0;

    // One GL_TRIANGLE_STRIP whose vertex sequence is the index buffer; each position carries the
    // colour (and shading) of the strip triangle it completes.
    glBegin(GL_TRIANGLE_STRIP);
    size_t ordinal = 0;
    for (size_t k = 0; k < s.size(); ++k) {
        std::array<float, 3> col = ramp(0.0);
        if (k >= 2) {
            const size_t i = k - 2;
            const uint32_t a = s[i], b = s[i + 1], c = s[i + 2];
            if (a != b && b != c && a != c) {
                col = ramp(band_position(static_cast<double>(ordinal++) / denom, style.bands));
                if (style.light) {
                    const Triangle t = (i % 2 == 0) ? Triangle{a, b, c} : Triangle{b, a, c};
                    const Vec n = normalized(cross(sub(points[t[1]], points[t[0]]), sub(points[t[2]], points[t[0]])));
                    const Point3& p = points[t[0]];
                    const Vec to_eye = normalized(sub(cam.eye, p));
                    // Headlight; back faces (open surfaces) lit like front faces but darker.
                    const double d = dot(n, to_eye);
                    const double shade = d >= 0 ? 0.35 + 0.65 * d : 0.25 + 0.35 * (-d);
                    for (float& x : col) x = static_cast<float>(x * shade);
                }
            }
        }
        glColor3f(col[0], col[1], col[2]);
        const Point3& p = points[s[k]];
        glVertex3d(p[0], p[1], p[2]);
    }
    glEnd();

    // Overlays: faint where hidden, solid where visible.
    glShadeModel(GL_SMOOTH);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_LINE_SMOOTH);
    glEnable(GL_POINT_SMOOTH);
    glDisable(GL_DEPTH_TEST);
    draw_overlays(overlays, style, kScale, 0.3f);
    glEnable(GL_DEPTH_TEST);
    draw_overlays(overlays, style, kScale, 1.0f);

    const std::vector<uint8_t> big = ctx.pixels_top_down();
    Image img;
    img.width = style.width;
    img.height = style.height;
    img.rgba.resize(static_cast<size_t>(img.width) * static_cast<size_t>(img.height) * 4);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            for (int ch = 0; ch < 4; ++ch) {
                unsigned sum = 0;
                for (int dy = 0; dy < kScale; ++dy)
                    for (int dx = 0; dx < kScale; ++dx)
                        sum +=
                            big[(static_cast<size_t>(y * kScale + dy) * static_cast<size_t>(W) + static_cast<size_t>(x * kScale + dx)) * 4 +
                                static_cast<size_t>(ch)];
                img.rgba[(static_cast<size_t>(y) * static_cast<size_t>(img.width) + static_cast<size_t>(x)) * 4 + static_cast<size_t>(ch)] =
                    static_cast<uint8_t>((sum + kScale * kScale / 2) / (kScale * kScale));
            }
    for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;  // opaque picture
    return img;
}

std::vector<uint8_t> render_coverage(const std::vector<Point3>& points, const std::vector<uint32_t>& indices, Primitive primitive,
                                     const std::vector<Point3>& frame_points, const View& view, int width, int height) {
    if (width <= 0 || height <= 0 || width > 8192 || height > 8192)
        throw RequestError("render: picture size must be between 1 and 8192 pixels");
    check_indices(points, indices);
    Context ctx(width, height);
    load_camera(make_camera(frame_points, view), frame_points, width, height);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);  // each front-facing layer adds 1 to the red channel
    glColor4ub(1, 0, 0, 0);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_DOUBLE, 0, points.data());
    glDrawElements(primitive == Primitive::Triangles ? GL_TRIANGLES : GL_TRIANGLE_STRIP, static_cast<GLsizei>(indices.size()),
                   GL_UNSIGNED_INT, indices.data());
    glDisableClientState(GL_VERTEX_ARRAY);
    const std::vector<uint8_t> px = ctx.pixels_top_down();
    std::vector<uint8_t> counts(static_cast<size_t>(width) * static_cast<size_t>(height));
    for (size_t i = 0; i < counts.size(); ++i) counts[i] = px[4 * i];
    return counts;
}

namespace {

/// The texture of render_textured(): smooth ramps show a wrong interpolation, the checkerboard
/// a wrong texel.
std::vector<uint8_t> test_texture(int n) {
    std::vector<uint8_t> t(static_cast<size_t>(n) * static_cast<size_t>(n) * 3);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            uint8_t* p = &t[3 * (static_cast<size_t>(y) * static_cast<size_t>(n) + static_cast<size_t>(x))];
            p[0] = static_cast<uint8_t>(255 * x / (n - 1));
            p[1] = static_cast<uint8_t>(255 * y / (n - 1));
            p[2] = ((x / 8 + y / 8) % 2) ? 255 : 0;
        }
    return t;
}

}  // namespace

std::vector<uint8_t> render_textured(const std::vector<Point3>& points, const std::vector<double>& uv, const std::vector<uint32_t>& indices,
                                     Primitive primitive, const std::vector<Point3>& frame_points, const View& view, int width,
                                     int height) {
    if (width <= 0 || height <= 0 || width > 8192 || height > 8192)
        throw RequestError("render: picture size must be between 1 and 8192 pixels");
    if (uv.size() != 2 * points.size()) throw RequestError("render: texture coordinates must be 2 per vertex");
    check_indices(points, indices);
    Context ctx(width, height);
    load_camera(make_camera(frame_points, view), frame_points, width, height);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    constexpr int kTex = 64;
    const std::vector<uint8_t> tex = test_texture(kTex);
    GLuint name = 0;
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, kTex, kTex, 0, GL_RGB, GL_UNSIGNED_BYTE, tex.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
    glEnable(GL_TEXTURE_2D);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(3, GL_DOUBLE, 0, points.data());
    glTexCoordPointer(2, GL_DOUBLE, 0, uv.data());
    glDrawElements(primitive == Primitive::Triangles ? GL_TRIANGLES : GL_TRIANGLE_STRIP, static_cast<GLsizei>(indices.size()),
                   GL_UNSIGNED_INT, indices.data());
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDeleteTextures(1, &name);
    return ctx.pixels_top_down();
}

void write_png(const std::string& path, const Image& img) {
    png_image pi{};
    pi.version = PNG_IMAGE_VERSION;
    pi.width = static_cast<png_uint_32>(img.width);
    pi.height = static_cast<png_uint_32>(img.height);
    pi.format = PNG_FORMAT_RGBA;
    png_alloc_size_t size = 0;
    if (!png_image_write_to_memory(&pi, nullptr, &size, 0, img.rgba.data(), 0, nullptr))
        throw OutputError(path + ": PNG encoding failed: " + pi.message);
    std::string bytes(size, '\0');
    if (!png_image_write_to_memory(&pi, bytes.data(), &size, 0, img.rgba.data(), 0, nullptr))
        throw OutputError(path + ": PNG encoding failed: " + pi.message);
    bytes.resize(size);
    write_text_atomic(path, bytes);
}

Image read_png(const std::string& path) {
    png_image pi{};
    pi.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&pi, path.c_str())) throw InputError(path + ": cannot read PNG: " + pi.message);
    pi.format = PNG_FORMAT_RGBA;
    Image img;
    img.width = static_cast<int>(pi.width);
    img.height = static_cast<int>(pi.height);
    img.rgba.resize(PNG_IMAGE_SIZE(pi));
    if (!png_image_finish_read(&pi, nullptr, img.rgba.data(), 0, nullptr)) {
        png_image_free(&pi);
        throw InputError(path + ": cannot read PNG: " + pi.message);
    }
    return img;
}

namespace {

/// What the CLI draws: a strip in order, its GL indices and the cycles (faces in strip order).
struct Drawable {
    StripArrays arrays;
    std::vector<uint32_t> indices;
    std::vector<std::vector<uint32_t>> cycles;
};

Drawable read_result(const RenderArgs& a) {
    if (is_gltf_path(a.input))
        throw InputError(a.input +
                         ": render cannot read a glTF result back (its float32 positions are not the strip's); render the .ply, "
                         ".obj or .off result, or the input mesh with --engine");
    OutputMesh m = read_output_mesh(a.input);
    if (m.faces.empty()) throw InputError(a.input + ": no faces to render");
    // encode_triangle_strip() treats a broken sequence as a bug; for a user file it is bad input.
    for (size_t i = 0; i + 1 < m.faces.size(); ++i) {
        int common = 0;
        for (uint32_t x : m.faces[i])
            for (uint32_t y : m.faces[i + 1]) common += x == y;
        if (common < 2)
            throw InputError(a.input + ": faces " + std::to_string(i) + " and " + std::to_string(i + 1) +
                             " share no edge: the file is not one strip (render a result of `singlestrip strip`)");
    }
    Drawable d;
    d.indices = encode_triangle_strip(m.faces);
    d.arrays.points = std::move(m.points);
    d.arrays.faces = std::move(m.faces);
    d.arrays.parent = std::move(m.parent);
    if (a.cycles) d.cycles = read_cycles_file(*a.cycles);
    return d;
}

/// `--engine`: the input is a mesh, stripped here with the constraints and source/target.
Drawable strip_input(const RenderArgs& a) {
    PipelineOptions o;
    o.strip.engine = *a.engine;
    o.strip.polish = a.polish;
    if (a.source) o.strip.source = VertexId(from_index_base(*a.source, a.index_base, "--source"));
    if (a.target) o.strip.target = VertexId(from_index_base(*a.target, a.index_base, "--target"));
    o.constraints_file = a.constraints;
    o.index_base = a.index_base;
    o.cycles = a.with_cycles;
    o.name = a.input;
    PipelineResult r = stripify(read_input(a.input), o);
    Drawable d;
    d.arrays = std::move(r.arrays);
    d.indices = std::move(r.indices);
    if (r.cycles) d.cycles = std::move(r.cycles->cycles);
    return d;
}

std::vector<Point3> route_polyline(const StripArrays& arrays) {
    std::vector<Point3> pts;
    for (const RoutePoint& p : strip_route(arrays).points) pts.push_back(p.position);
    return pts;
}

Overlays overlays_of(const RenderArgs& a, const Drawable& d) {
    Overlays ov;
    const auto& pts = d.arrays.points;
    const auto nv = static_cast<uint32_t>(pts.size());
    for (size_t c = 0; c < d.cycles.size(); ++c) {
        for (uint32_t f : d.cycles[c])
            if (f >= d.arrays.faces.size())
                throw InputError(a.cycles.value_or("cycles") + ": cycle " + std::to_string(c) + " names face " + std::to_string(f) +
                                 " but " + a.input + " has " + std::to_string(d.arrays.faces.size()) + " faces");
        ov.closed_polylines.push_back(cycle_polyline(d.arrays, d.cycles[c]));
    }
    if (a.constraints)
        for (const ConstraintEdge& e : read_constraints_based(*a.constraints, nv, a.index_base))
            ov.segments.emplace_back(pts[e.a], pts[e.b]);
    auto vertex = [&](uint32_t v, const char* what) {
        const uint32_t i = from_index_base(v, a.index_base, std::string("--") + what);
        if (i >= nv)
            throw RequestError(std::string("--") + what + " " + std::to_string(v) + " is out of range (" + a.input + " has " +
                               std::to_string(nv) + " vertices, numbered from " + std::to_string(a.index_base) + ")");
        return pts[i];
    };
    if (a.route) ov.route = route_polyline(d.arrays);
    if (a.source) ov.source = vertex(*a.source, "source");
    if (a.target) ov.target = vertex(*a.target, "target");
    return ov;
}

}  // namespace

View auto_view(const std::vector<Point3>& points) {
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (const Point3& p : points)
        for (int k = 0; k < 3; ++k)
            if (std::isfinite(p[k])) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    const double ext[3] = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
    const double big = std::max({ext[0], ext[1], ext[2]});
    View v;
    if (!(big > 0)) return v;
    // Seen from above the plane, the first remaining axis to the right.
    if (ext[2] <= 1e-9 * big) return View{0.0, 90.0, true};  // x right, y up
    if (ext[1] <= 1e-9 * big) return View{0.0, 90.0, false};
    if (ext[0] <= 1e-9 * big) return View{0.0, 0.0, false};
    return v;
}

int run_render_command(const RenderArgs& a) {
    const std::string out = ascii_lower(a.output);
    if (out.size() < 4 || out.substr(out.size() - 4) != ".png") throw RequestError(a.output + ": the picture must be a .png file");
    if (a.engine && a.cycles) throw RequestError("--cycles names faces of a result file; with --engine use --with-cycles");
    if (!a.engine && a.with_cycles) throw RequestError("--with-cycles needs --engine (the input is then stripped first)");
    const Drawable d = a.engine ? strip_input(a) : read_result(a);
    const Overlays ov = overlays_of(a, d);
    write_png(a.output, render_strip(d.arrays.points, d.indices, ov, a.auto_view ? auto_view(d.arrays.points) : a.view, a.style));
    return app::kExitOk;
}

}  // namespace singlestrip::render
