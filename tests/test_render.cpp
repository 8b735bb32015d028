// Rendering with a real OpenGL implementation (Mesa OSMesa). The key check: the input drawn as
// GL_TRIANGLES and our strip drawn as ONE GL_TRIANGLE_STRIP from our index buffer, flat colour,
// back faces culled, same camera, give identical pictures — so the GL's own strip decoding,
// winding rule and rasterizer agree that the strip covers exactly the input surface with the
// input's orientation. Pixels hold the number of front-facing layers (additive blending), which
// is stronger than a 0/1 mask. Negative checks: a strip whose parity is shifted (all windings
// flipped) or flipped half-way must give a different picture.
// SKIPs when render/ was not built (no OSMesa or libpng).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "cgal_data.hpp"
#include "fixtures.hpp"
#include "singlestrip/attributes.hpp"
#include "singlestrip/cycles.hpp"
#include "singlestrip/encode.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/io.hpp"
#include "singlestrip/mesh.hpp"
#include "singlestrip/pipeline.hpp"
#include "singlestrip/strip.hpp"
#include "singlestrip/validate.hpp"

#ifdef SINGLESTRIP_HAVE_RENDER
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include <cstring>

#include "render/render.hpp"
#include "singlestrip/gltf_scene.hpp"
#endif

using namespace singlestrip;
namespace fs = std::filesystem;

#ifndef SINGLESTRIP_HAVE_RENDER

TEST(Render, NotBuilt) {
    GTEST_SKIP() << "render/ not built (needs libosmesa6-dev and libpng-dev)";
}

#else

namespace {

constexpr int kW = 320, kH = 256;
constexpr size_t kSliverPixels = 2;  ///< see check_coverage()

struct Case {
    std::string name;
    TriangleSoup soup;
    StripOptions options;
    bool open;  ///< has boundary: a fully flipped strip must change the coverage itself
};

std::vector<uint32_t> flatten(const std::vector<Triangle>& t) {
    std::vector<uint32_t> v;
    v.reserve(3 * t.size());
    for (const Triangle& f : t) v.insert(v.end(), f.begin(), f.end());
    return v;
}

size_t differing(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    size_t n = 0;
    for (size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
    return n;
}
size_t covered(const std::vector<uint8_t>& a) {
    size_t n = 0;
    for (uint8_t x : a) n += x != 0;
    return n;
}

std::vector<Case> generated_cases() {
    std::vector<Case> cs;
    cs.push_back({"icosphere", make_icosphere(2), {}, false});
    cs.push_back({"torus", make_torus(30, 14), {}, false});
    cs.push_back({"genus2_holes", make_genus_with_holes(2, 3, 8), {}, true});
    cs.push_back({"annulus", make_annulus(24, 4), {}, true});
    cs.push_back({"builtin", make_builtin_model(), {}, false});
    return cs;
}

/// libcgal-demo meshes that are available (none: the caller SKIPs).
std::vector<Case> real_cases() {
    std::vector<Case> cs;
    for (const char* name : {"fandisk.off", "eight.off", "head.off"}) {
        const std::string p = test::cgal_mesh_path(name);
        if (p.empty()) continue;
        TriangleSoup s = read_mesh_file(p);
        cs.push_back({name, s, {}, mesh_info(s).boundary_edges > 0});
    }
    return cs;
}

const std::vector<render::View> kViews = {{35, 25, false}, {200, -30, false}, {90, 80, false}, {0, 5, true}};

void check_coverage(const std::vector<Case>& cases) {
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        std::cerr << "[ render   ] " << c.name << '\n';
        const TriangleSoup soup = prepare_soup(c.soup, {}, c.name);
        const StripArrays a = strip_arrays(build_strip(Mesh::from_soup(soup), c.options));
        const std::vector<uint32_t> strip = encode_triangle_strip(a.faces);
        const std::vector<uint32_t> tris = flatten(soup.triangles);
        ASSERT_GT(a.faces.size(), soup.triangles.size() / 2);
        for (size_t v = 0; v < kViews.size(); ++v) {
            SCOPED_TRACE("view " + std::to_string(v));
            const auto in = render::render_coverage(soup.points, tris, render::Primitive::Triangles, soup.points, kViews[v], kW, kH);
            const auto out = render::render_coverage(a.points, strip, render::Primitive::TriangleStrip, soup.points, kViews[v], kW, kH);
            const auto split =
                render::render_coverage(a.points, flatten(a.faces), render::Primitive::Triangles, soup.points, kViews[v], kW, kH);
            // The strip draws exactly its own triangles, each with the same winding.
            EXPECT_EQ(differing(split, out), 0u) << "pixels whose front-layer count differs between the strip and its triangles";
            // A split's midpoint, projected and snapped, is off its projected edge by a fraction
            // of a pixel: where that edge is a silhouette (one side culled), a pixel centre in the
            // sliver between the two can flip (builtin, view 2: 1 pixel).
            EXPECT_LE(differing(in, split), kSliverPixels) << "pixels whose front-layer count differs between input and split mesh";

            // Negative checks. Shifting the parity by one leading repeated index flips every
            // triangle's winding: front and back swap.
            std::vector<uint32_t> flipped = strip;
            flipped.insert(flipped.begin(), strip[0]);
            const auto fl = render::render_coverage(a.points, flipped, render::Primitive::TriangleStrip, soup.points, kViews[v], kW, kH);
            // The model is in the picture (an open surface may show only its back from here).
            ASSERT_GT(covered(in) + covered(fl), static_cast<size_t>(kW * kH / 50));
            if (c.open) {
                EXPECT_GT(differing(in, fl), kSliverPixels) << "a flipped strip must not look like the input";
            }
            // Flipping the second half only (one repeated index in the middle).
            std::vector<uint32_t> half = strip;
            half.insert(half.begin() + static_cast<std::ptrdiff_t>(half.size() / 2), half[half.size() / 2]);
            const auto hf = render::render_coverage(a.points, half, render::Primitive::TriangleStrip, soup.points, kViews[v], kW, kH);
            EXPECT_GT(differing(in, hf), kSliverPixels) << "a strip flipped half-way must not look like the input";
        }
    }
}

}  // namespace

TEST(Render, StripAndInputGiveIdenticalCulledCoverage) {
    check_coverage(generated_cases());
}

TEST(Render, RealMeshesStripAndInputGiveIdenticalCulledCoverage) {
    const std::vector<Case> cs = real_cases();
    if (cs.empty()) GTEST_SKIP() << "libcgal-demo meshes not available";
    check_coverage(cs);
}

namespace {

/// Pixels whose colour differs by more than `tol` in some channel (coverage in alpha included).
size_t differing_rgba(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b, int tol) {
    size_t n = 0;
    for (size_t i = 0; i + 3 < a.size(); i += 4) {
        int d = 0;
        for (size_t c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a[i + c]) - int(b[i + c])));
        n += d > tol;
    }
    return n;
}

/// `uv` with every vertex past the input's given its parent's first corner's texture
/// coordinate: what a writer that did not interpolate would draw.
std::vector<double> uv_without_interpolation(const PipelineResult& r, std::vector<double> uv) {
    const size_t n = r.input.points.size();
    const std::vector<double>& in = find_attribute(r.input.attributes, "TEXCOORD_0")->values;
    for (size_t f = 0; f < r.arrays.faces.size(); ++f)
        for (uint32_t v : r.arrays.faces[f])
            if (v >= n)
                for (size_t c = 0; c < 2; ++c) uv[2 * v + c] = in[2 * r.input.triangles[r.arrays.parent[f]][0] + c];
    return uv;
}

}  // namespace

// Issue 18, item 4: the pictures of input and output compared with the textures on. The input's
// texture coordinates (OBJ vt with seams, PLY s/t, glTF TEXCOORD_0) are drawn on the input
// triangles, the output's (midpoints interpolated) on the strip; they must agree up to rounding
// of the interpolation (a bilinear texture: at most 2 levels; 1 measured) on every pixel, and a strip
// whose midpoints were not interpolated must not.
TEST(Render, TexturedStripLooksLikeTheTexturedInput) {
    for (const char* name : {"sphere_uv.obj", "sphere_attrs.ply", "scene.glb"}) {
        SCOPED_TRACE(name);
        const TriangleSoup soup = read_input(std::string(SINGLESTRIP_SOURCE_DIR) + "/tests/data/" + name);
        const PipelineResult r = stripify(soup, PipelineOptions{});
        ASSERT_GT(r.strip.stats.splits, 0u);
        const std::vector<double>& uv_in = find_attribute(r.input.attributes, "TEXCOORD_0")->values;
        const std::vector<double>& uv_out = find_attribute(r.arrays.attributes, "TEXCOORD_0")->values;
        const std::vector<double> uv_bad = uv_without_interpolation(r, uv_out);
        const std::vector<uint32_t> tris = flatten(r.input.triangles);
        size_t covered_px = 0, worst = 0, bad = 0;
        int largest = 0;  // largest channel difference between input and strip, for the log
        for (size_t v = 0; v < kViews.size(); ++v) {
            SCOPED_TRACE("view " + std::to_string(v));
            const auto& pts = r.input.points;
            const auto in = render::render_textured(pts, uv_in, tris, render::Primitive::Triangles, pts, kViews[v], kW, kH);
            const auto out =
                render::render_textured(r.arrays.points, uv_out, r.indices, render::Primitive::TriangleStrip, pts, kViews[v], kW, kH);
            const auto wrong =
                render::render_textured(r.arrays.points, uv_bad, r.indices, render::Primitive::TriangleStrip, pts, kViews[v], kW, kH);
            for (size_t i = 3; i < in.size(); i += 4) covered_px += in[i] != 0;
            EXPECT_EQ(differing_rgba(in, out, 255 - 1), 0u) << "coverage differs";
            worst = std::max(worst, differing_rgba(in, out, 2));
            for (size_t i = 0; i < in.size(); ++i) largest = std::max(largest, std::abs(int(in[i]) - int(out[i])));
            bad += differing_rgba(in, wrong, 2);
        }
        std::cerr << "[ render   ] " << name << ": " << covered_px << " textured pixels, " << worst
                  << " differ by more than 2 levels (largest difference " << largest << "); without interpolation " << bad << '\n';
        EXPECT_GT(covered_px, static_cast<size_t>(kW * kH / 20));
        EXPECT_EQ(worst, 0u) << "pixels whose colour differs by more than 2 levels";
        EXPECT_GT(bad, 20u) << "uninterpolated midpoints must show";
    }
}

namespace {

/// One accessor of a glTF model as doubles (float or unsigned integer components, normalised
/// ones scaled to [0, 1]), `components` per element; tightly packed or strided views.
std::vector<double> accessor_values(const tinygltf::Model& m, int index) {
    const tinygltf::Accessor& a = m.accessors.at(static_cast<size_t>(index));
    const tinygltf::BufferView& v = m.bufferViews.at(static_cast<size_t>(a.bufferView));
    const auto k = static_cast<size_t>(tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type)));
    const auto size = static_cast<size_t>(tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType)));
    const size_t stride = v.byteStride ? v.byteStride : k * size;
    const unsigned char* base = m.buffers.at(static_cast<size_t>(v.buffer)).data.data() + v.byteOffset + a.byteOffset;
    std::vector<double> out;
    for (size_t e = 0; e < a.count; ++e)
        for (size_t c = 0; c < k; ++c) {
            const unsigned char* p = base + e * stride + c * size;
            double x = 0;
            if (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
                float f;
                std::memcpy(&f, p, 4);
                x = f;
            } else {
                uint32_t u = 0;
                std::memcpy(&u, p, size);  // little-endian host (glTF is little-endian)
                x = a.normalized ? u / double((uint64_t{1} << (8 * size)) - 1) : u;
            }
            out.push_back(x);
        }
    return out;
}

tinygltf::Model load_glb(const std::string& path) {
    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    // The pictures use the renderer's own texture: the images are not decoded.
    loader.SetImageLoader(
        [](tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) { return true; }, nullptr);
    std::string err, warn;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&m, &err, &warn, path)) << path << ": " << err;
    return m;
}

/// A primitive's positions, texture coordinates and indices (0, 1, 2, ... when it has none).
struct TexturedPrimitive {
    std::vector<Point3> points;
    std::vector<double> uv;
    std::vector<uint32_t> indices;
};

TexturedPrimitive textured_primitive(const tinygltf::Model& m, const tinygltf::Primitive& p) {
    TexturedPrimitive t;
    const std::vector<double> pos = accessor_values(m, p.attributes.at("POSITION"));
    for (size_t i = 0; i + 2 < pos.size(); i += 3) t.points.push_back({pos[i], pos[i + 1], pos[i + 2]});
    t.uv = accessor_values(m, p.attributes.at("TEXCOORD_0"));
    if (p.indices >= 0)
        for (double x : accessor_values(m, p.indices)) t.indices.push_back(static_cast<uint32_t>(x));
    else
        for (uint32_t i = 0; i < t.points.size(); ++i) t.indices.push_back(i);
    return t;
}

}  // namespace

// Issue 18, item 4, through the real glTF pipeline: scene.glb (several textured primitives)
// stripped by strip_gltf_file() into a .glb; each output TRIANGLE_STRIP primitive, read back
// from the file, is drawn with its texture coordinates beside the input primitive drawn as
// GL_TRIANGLES; the pictures must agree (2 levels, as above). New vertices given a wrong texture
// coordinate must show.
TEST(Render, TexturedGltfScenePrimitivesLookLikeTheInputOnes) {
    const fs::path dir = fs::path(::testing::TempDir()) / "singlestrip_render_scene";
    fs::create_directories(dir);
    const std::string in_path = std::string(SINGLESTRIP_SOURCE_DIR) + "/tests/data/scene.glb", out_path = (dir / "scene.glb").string();
    const std::vector<GltfPrimitiveResult> results = strip_gltf_file(in_path, out_path, PipelineOptions{});
    const tinygltf::Model in = load_glb(in_path), out = load_glb(out_path);
    size_t compared = 0, with_splits = 0;
    for (const GltfPrimitiveResult& pr : results) {
        if (!pr.stripped) continue;
        SCOPED_TRACE("mesh " + std::to_string(pr.mesh) + " primitive " + std::to_string(pr.primitive));
        const tinygltf::Primitive& ip = in.meshes[static_cast<size_t>(pr.mesh)].primitives[static_cast<size_t>(pr.primitive)];
        const tinygltf::Primitive& op = out.meshes[static_cast<size_t>(pr.mesh)].primitives[static_cast<size_t>(pr.primitive)];
        ASSERT_EQ(op.mode, TINYGLTF_MODE_TRIANGLE_STRIP);
        if (!ip.attributes.count("TEXCOORD_0")) continue;
        const TexturedPrimitive a = textured_primitive(in, ip), b = textured_primitive(out, op);
        ASSERT_EQ(b.uv.size(), 2 * b.points.size());
        std::vector<double> wrong = b.uv;  // new vertices (after the input's) given vertex 0's coordinate
        for (size_t v = a.points.size(); v < b.points.size(); ++v) wrong[2 * v] = b.uv[0] + 0.37, wrong[2 * v + 1] = b.uv[1] + 0.37;
        size_t textured = 0, worst = 0, bad = 0;
        for (const render::View& view : kViews) {
            const auto pa = render::render_textured(a.points, a.uv, a.indices, render::Primitive::Triangles, a.points, view, kW, kH);
            const auto pb = render::render_textured(b.points, b.uv, b.indices, render::Primitive::TriangleStrip, a.points, view, kW, kH);
            const auto pw = render::render_textured(b.points, wrong, b.indices, render::Primitive::TriangleStrip, a.points, view, kW, kH);
            for (size_t i = 3; i < pa.size(); i += 4) textured += pa[i] != 0;
            EXPECT_EQ(differing_rgba(pa, pb, 255 - 1), 0u) << "coverage differs";
            worst = std::max(worst, differing_rgba(pa, pb, 2));
            bad += differing_rgba(pa, pw, 2);
        }
        std::cerr << "[ render   ] scene.glb mesh " << pr.mesh << " primitive " << pr.primitive << ": " << textured << " textured pixels, "
                  << pr.splits << " splits, " << worst << " differ by more than 2 levels; wrong new texture coordinates " << bad << '\n';
        EXPECT_GT(textured, static_cast<size_t>(kW * kH / 50));
        EXPECT_EQ(worst, 0u) << "pixels whose colour differs by more than 2 levels";
        if (pr.splits > 0) {
            ++with_splits;
            EXPECT_GT(bad, 20u) << "wrong texture coordinates at the new vertices must show";
        }
        ++compared;
    }
    EXPECT_GE(compared, 3u) << "scene.glb has three textured triangle primitives";
    EXPECT_GT(with_splits, 0u);
}

TEST(Render, ConstrainedStripWithSplitsCoversTheInput) {
    // Constraints force extra splits; the split faces must still tile the input exactly.
    const TriangleSoup soup = prepare_soup(make_torus(24, 12), {}, "torus");
    StripOptions opt;
    for (uint32_t k = 0; k + 1 < 12; ++k) opt.constraint_edges.push_back({k, k + 1});  // part of a minor circle
    opt.source = VertexId(30);
    opt.target = VertexId(200);
    const StripResult r = build_strip(Mesh::from_soup(soup), opt);
    const StripArrays a = strip_arrays(r);
    ASSERT_GT(r.stats.splits, 0u);
    const std::vector<uint32_t> strip = encode_triangle_strip(a.faces);
    for (const render::View& v : kViews) {
        const auto in = render::render_coverage(soup.points, flatten(soup.triangles), render::Primitive::Triangles, soup.points, v, kW, kH);
        const auto out = render::render_coverage(a.points, strip, render::Primitive::TriangleStrip, soup.points, v, kW, kH);
        EXPECT_EQ(differing(in, out), 0u);
    }
}

TEST(Render, RenderCommandWritesAPictureWithOverlays) {
    const fs::path dir = fs::path(::testing::TempDir()) / "singlestrip_render_test";
    fs::create_directories(dir);
    const TriangleSoup soup = prepare_soup(make_builtin_model(), {}, "builtin");
    const StripResult r = build_strip(Mesh::from_soup(soup));
    const StripArrays a = strip_arrays(r);
    const std::string ply = (dir / "genus2.ply").string();
    write_strip_mesh(ply, a.points, a.faces, a.parent);
    const std::string cyc = (dir / "genus2.cycles.json").string();
    write_cycles_json(cyc, compute_fundamental_cycles(r));

    render::RenderArgs args;
    args.input = ply;
    args.output = (dir / "genus2.png").string();
    args.cycles = cyc;
    args.source = a.faces.front()[0];
    args.target = a.faces.back()[0];
    args.style.width = 200;
    args.style.height = 150;
    ASSERT_EQ(render::run_render_command(args), 0);
    const render::Image img = render::read_png(args.output);
    ASSERT_EQ(img.width, 200);
    ASSERT_EQ(img.height, 150);
    // Not blank: some pixels differ from the white background, and both ends of the colour ramp
    // (blue start, red end of the strip) appear.
    size_t non_bg = 0, blueish = 0, reddish = 0;
    for (size_t i = 0; i < img.rgba.size(); i += 4) {
        const int R = img.rgba[i], G = img.rgba[i + 1], B = img.rgba[i + 2];
        non_bg += (R < 250 || G < 250 || B < 250);
        blueish += B > R + 40 && B > G;
        reddish += R > G + 40 && R > B + 40;
    }
    EXPECT_GT(non_bg, 200u * 150u / 10);
    EXPECT_GT(blueish, 0u);
    EXPECT_GT(reddish, 0u);

    // Errors, with the CLI's types.
    render::RenderArgs bad = args;
    bad.output = (dir / "x.jpg").string();
    EXPECT_THROW(render::run_render_command(bad), RequestError);
    bad = args;
    bad.source = static_cast<uint32_t>(a.points.size());
    EXPECT_THROW(render::run_render_command(bad), RequestError);
    bad = args;
    bad.input = (dir / "missing.ply").string();
    EXPECT_THROW(render::run_render_command(bad), InputError);
    // A face order that is not a strip is bad input, not an internal error.
    std::vector<Triangle> shuffled = a.faces;
    std::swap(shuffled[1], shuffled[shuffled.size() / 2]);
    const std::string notstrip = (dir / "notstrip.ply").string();
    write_strip_mesh(notstrip, a.points, shuffled, a.parent);
    bad = args;
    bad.input = notstrip;
    bad.cycles.reset();
    EXPECT_THROW(render::run_render_command(bad), InputError);
}

TEST(Render, FlatMeshesAreSeenFromAbove) {
    const std::vector<Point3> floor = {{0, 0, 2}, {30, 0, 2}, {30, 20, 2}};
    const render::View top = render::auto_view(floor);
    EXPECT_TRUE(top.z_up);
    EXPECT_EQ(top.elevation_deg, 90.0);
    const std::vector<Point3> y_flat = {{0, 1, 0}, {3, 1, 0}, {0, 1, 2}};
    EXPECT_FALSE(render::auto_view(y_flat).z_up);
    EXPECT_EQ(render::auto_view(y_flat).elevation_deg, 90.0);
    const std::vector<Point3> solid = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    EXPECT_EQ(render::auto_view(solid).elevation_deg, render::View{}.elevation_deg);
}

TEST(Render, RouteIsDrawnWithItsEnds) {
    TriangleSoup soup;
    for (int y = 0; y <= 4; ++y)
        for (int x = 0; x <= 4; ++x) soup.points.push_back({double(x), double(y), 0});
    for (uint32_t y = 0; y < 4; ++y)
        for (uint32_t x = 0; x < 4; ++x) {
            const uint32_t a = y * 5 + x;
            soup.triangles.push_back({a, a + 1, a + 6});
            soup.triangles.push_back({a, a + 6, a + 5});
        }
    const fs::path dir = fs::path(::testing::TempDir()) / "singlestrip_render_route";
    fs::create_directories(dir);
    const PipelineResult res = stripify(soup, PipelineOptions{});
    const std::string ply = (dir / "grid.ply").string();
    write_strip_mesh(ply, res.arrays.points, res.arrays.faces, res.arrays.parent);
    render::RenderArgs args;
    args.input = ply;
    args.output = (dir / "plain.png").string();
    args.style.width = 200;
    args.style.height = 200;
    ASSERT_EQ(render::run_render_command(args), 0);
    args.route = true;
    args.output = (dir / "route.png").string();
    ASSERT_EQ(render::run_render_command(args), 0);
    const render::Image plain = render::read_png((dir / "plain.png").string());
    const render::Image route = render::read_png(args.output);
    // The route adds dark pixels and a green start mark the plain picture does not have.
    auto count = [](const render::Image& img, auto pred) {
        size_t n = 0;
        for (size_t i = 0; i + 3 < img.rgba.size(); i += 4) n += pred(img.rgba[i], img.rgba[i + 1], img.rgba[i + 2]);
        return n;
    };
    auto dark = [](int r, int g, int b) { return r < 60 && g < 60 && b < 60; };
    auto green = [](int r, int g, int b) { return g > 120 && r < 60 && b < 80; };
    EXPECT_GT(count(route, dark), count(plain, dark) + 50);
    EXPECT_GT(count(route, green), count(plain, green));
    fs::remove_all(dir);
}

#endif
