// Python bindings (pybind11 + numpy): `import singlestrip`.
//
//   singlestrip.strip(vertices, faces, constraints=None, source=None, target=None, cycles=False,
//                     seed_face=None, greedy=True, orient=False, name="input",
//                     engine="matching", repair=False, weld=False, join="degenerate",
//                     attributes=None, blend=None, polish=False) -> dict
//   singlestrip.verify(vertices, faces, result, constraints=None, source=None, target=None,
//                      repair=False, weld=False, orient=False, attributes=None, blend=None) -> dict
//   singlestrip.decode_strip(indices) -> (T, 3) uint32 array
//   singlestrip.read(path, format=None, attributes=False) -> (V (n, 3) float64, F (m, 3) uint32)
//       or, with attributes=True, dict(vertices, faces, attributes, blend) (strip()'s arguments)
//
// Arrays in are checked for shape and kind before any conversion: vertices must be real numbers,
// faces integers (a float face array is refused, never truncated), both of shape (k, 3);
// attributes a dict of real (n,) or (n, k) arrays (TypeError for the wrong kinds, ValueError for
// the wrong row count or a NaN). Midpoint attributes are the library's (stripify()), not Python's.
// strip() runs the CLI's pipeline (stripify(), pipeline.hpp: the same checks and messages,
// prefixed by `name` where the CLI has the file name) and its report (report.hpp). Every
// singlestrip::InputError / RequestError becomes ValueError, an InternalError RuntimeError.
// The GIL is released while the strip is built.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "singlestrip/attributes.hpp"
#include "singlestrip/encode.hpp"
#include "singlestrip/errors.hpp"
#include "singlestrip/gltf.hpp"
#include "singlestrip/pipeline.hpp"
#include "singlestrip/report.hpp"
#include "singlestrip/route.hpp"
#include "singlestrip/strip.hpp"
#include "singlestrip/verify.hpp"

namespace py = pybind11;
namespace ss = singlestrip;

namespace {

using Pairs = std::vector<std::pair<uint32_t, uint32_t>>;

std::string shape_of(const py::handle& obj) {
    return py::str(py::array::ensure(obj).attr("shape"));
}

/// The array behind `obj` (converting lists) with its kind checked: 'f' for real numbers, 'i' for
/// integers; numpy's own conversion would silently truncate 1.7 to 1 in a face array.
void check_kind(const py::handle& obj, bool integers, const std::string& what) {
    py::array a;
    try {
        a = py::array::ensure(obj);
    } catch (const py::error_already_set&) {
    }
    if (!a) throw py::value_error(what + " must be a numpy array (or nested sequence) of shape (k, 3)");
    const char kind = a.dtype().kind();
    const bool ok = a.size() == 0 || integers ? (kind == 'i' || kind == 'u') : (kind == 'f' || kind == 'i' || kind == 'u');
    if (ok) return;
    const std::string dtype = py::str(a.dtype());
    if (integers)
        throw py::value_error(what + " must be an integer array of shape (m, 3) (vertex indices), got dtype " + dtype +
                              "; convert explicitly, e.g. F.astype(np.uint32), if the values are whole numbers");
    throw py::value_error(what + " must be an array of shape (n, 3) of real numbers (coordinates), got dtype " + dtype);
}

std::vector<ss::Point3> to_points(const py::handle& obj, const char* what) {
    check_kind(obj, false, what);
    py::array_t<double, py::array::c_style | py::array::forcecast> a;
    try {
        a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(obj);
    } catch (const py::error_already_set&) {
        a = {};
    }
    if (!a || a.ndim() != 2 || a.shape(1) != 3)
        throw py::value_error(std::string(what) + " must be an array of shape (n, 3) of numbers, got shape " + shape_of(obj));
    std::vector<ss::Point3> pts(static_cast<size_t>(a.shape(0)));
    auto r = a.unchecked<2>();
    for (py::ssize_t i = 0; i < a.shape(0); ++i)
        for (py::ssize_t d = 0; d < 3; ++d) {
            const double x = r(i, d);
            // Same wording as the file readers (io.hpp) for a NaN or infinite coordinate.
            if (!std::isfinite(x))
                throw py::value_error(std::string(what) + ": vertex " + std::to_string(i) + " has a non-finite coordinate");
            pts[static_cast<size_t>(i)][static_cast<size_t>(d)] = x;
        }
    return pts;
}

std::vector<ss::Triangle> to_faces(const py::handle& obj, size_t num_vertices, const char* what) {
    check_kind(obj, true, what);
    py::array_t<int64_t, py::array::c_style | py::array::forcecast> a;
    try {
        a = py::array_t<int64_t, py::array::c_style | py::array::forcecast>::ensure(obj);
    } catch (const py::error_already_set&) {
        a = {};
    }
    if (!a || a.ndim() != 2 || a.shape(1) != 3)
        throw py::value_error(std::string(what) + " must be an integer array of shape (m, 3), got shape " + shape_of(obj));
    std::vector<ss::Triangle> f(static_cast<size_t>(a.shape(0)));
    auto r = a.unchecked<2>();
    for (py::ssize_t i = 0; i < a.shape(0); ++i)
        for (py::ssize_t k = 0; k < 3; ++k) {
            const int64_t v = r(i, k);
            if (v < 0 || static_cast<uint64_t>(v) >= num_vertices)
                throw py::value_error(std::string(what) + ": face " + std::to_string(i) + " references vertex " + std::to_string(v) +
                                      " but there are only " + std::to_string(num_vertices) + " vertices");
            f[static_cast<size_t>(i)][static_cast<size_t>(k)] = static_cast<uint32_t>(v);
        }
    return f;
}

/// A Python int (or None) as an optional index; ValueError naming `what` if it is negative or too large.
std::optional<uint32_t> to_index(const py::object& o, const char* what) {
    if (o.is_none()) return std::nullopt;
    const long long v = o.cast<long long>();
    if (v < 0 || v > 0xfffffffeLL) throw py::value_error(std::string(what) + " " + std::to_string(v) + " is out of range");
    return static_cast<uint32_t>(v);
}

/// A vertex number for the verifier, which keeps plain indices.
std::optional<uint32_t> to_vertex(const py::object& o, const char* what) {
    return to_index(o, what);
}

std::optional<ss::VertexId> to_vertex_id(const py::object& o, const char* what) {
    const auto v = to_index(o, what);
    return v ? std::optional<ss::VertexId>(ss::VertexId(*v)) : std::nullopt;
}

std::optional<ss::FaceId> to_face_id(const py::object& o, const char* what) {
    const auto f = to_index(o, what);
    return f ? std::optional<ss::FaceId>(ss::FaceId(*f)) : std::nullopt;
}

/// Constraints: a sequence of polylines (each a sequence of >= 2 vertex ids, like one line of a
/// constraint file) or an (E, 2) array of edges.
Pairs to_constraints(const py::object& o, size_t num_vertices) {
    Pairs pairs;
    if (o.is_none()) return pairs;
    size_t line = 0;
    for (const py::handle& poly : o) {
        std::vector<long long> ids;
        for (const py::handle& x : poly) ids.push_back(x.cast<long long>());
        if (ids.size() < 2) throw py::value_error("constraints: polyline " + std::to_string(line) + " has fewer than 2 vertices");
        for (long long v : ids)
            if (v < 0 || static_cast<unsigned long long>(v) >= num_vertices)
                throw py::value_error("constraints: polyline " + std::to_string(line) + ": vertex " + std::to_string(v) +
                                      " is out of range (" + std::to_string(num_vertices) + " vertices)");
        for (size_t i = 0; i + 1 < ids.size(); ++i) pairs.emplace_back(static_cast<uint32_t>(ids[i]), static_cast<uint32_t>(ids[i + 1]));
        ++line;
    }
    return pairs;
}

template <class T>
py::array_t<T> vec_array(const std::vector<T>& v) {
    py::array_t<T> a(static_cast<py::ssize_t>(v.size()));
    std::copy(v.begin(), v.end(), a.mutable_data());
    return a;
}

template <class T, size_t N, class Src>
py::array_t<T> rows_array(const std::vector<std::array<Src, N>>& v) {
    py::array_t<T> a({static_cast<py::ssize_t>(v.size()), static_cast<py::ssize_t>(N)});
    T* p = a.mutable_data();
    for (const auto& row : v)
        for (size_t k = 0; k < N; ++k) *p++ = static_cast<T>(row[k]);
    return a;
}

/// Runs `f`, translating singlestrip errors into Python exceptions.
template <class F>
auto translate(F&& f) -> decltype(f()) {
    try {
        return f();
    } catch (const ss::InputError& e) {
        throw py::value_error(e.what());
    } catch (const ss::RequestError& e) {
        throw py::value_error(e.what());
    } catch (const ss::Error& e) {
        throw std::runtime_error(std::string("singlestrip: ") + e.what());
    }
}

ss::StripEngine to_engine(const std::string& name) {
    if (const auto e = ss::parse_engine(name)) return *e;
    throw py::value_error("unknown engine '" + name + "' (choices: matching, growth)");
}

/// The route (route.hpp) as numpy arrays.
py::dict route_dict(const ss::Route& route) {
    std::vector<ss::Point3> pts;
    std::vector<uint32_t> face, parent;
    std::vector<double> distance;
    for (const ss::RoutePoint& p : route.points) {
        pts.push_back(p.position);
        face.push_back(p.face);
        parent.push_back(p.parent);
        distance.push_back(p.distance);
    }
    py::dict d;
    d["points"] = rows_array<double>(pts);
    d["face"] = vec_array(face);
    d["parent"] = vec_array(parent);
    d["distance"] = vec_array(distance);
    d["length"] = route.length;
    d["planar_z"] = route.planar_z;
    return d;
}

const char* blend_name(ss::AttributeBlend b) {
    switch (b) {
        case ss::AttributeBlend::Unit:
            return "unit";
        case ss::AttributeBlend::Nearest:
            return "nearest";
        case ss::AttributeBlend::Linear:
            break;
    }
    return "linear";
}

ss::AttributeBlend to_blend(const py::handle& o, const std::string& name) {
    if (!py::isinstance<py::str>(o))
        throw py::type_error("blend['" + name + "'] must be a str (\"linear\", \"unit\" or \"nearest\"), got " +
                             std::string(py::str(py::type::of(o).attr("__name__"))));
    const auto s = o.cast<std::string>();
    if (s == "linear") return ss::AttributeBlend::Linear;
    if (s == "unit") return ss::AttributeBlend::Unit;
    if (s == "nearest") return ss::AttributeBlend::Nearest;
    throw py::value_error("blend['" + name + "'] is '" + s + "'; choices: linear, unit, nearest");
}

/// One attribute array: (n,) or (n, k) real numbers, finite, n = the vertex count.
ss::VertexAttribute to_attribute(const std::string& name, const py::handle& obj, size_t num_vertices) {
    py::array a;
    try {
        a = py::array::ensure(obj);
    } catch (const py::error_already_set&) {
    }
    const std::string what = "attributes['" + name + "']";
    if (!a) throw py::type_error(what + " must be a numpy array (or nested sequence) of numbers");
    const char kind = a.dtype().kind();
    if (a.size() != 0 && kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b')
        throw py::type_error(what + " must hold real numbers, got dtype " + std::string(py::str(a.dtype())));
    if ((a.ndim() != 1 && a.ndim() != 2) || static_cast<size_t>(a.shape(0)) != num_vertices || (a.ndim() == 2 && a.shape(1) < 1))
        throw py::value_error(what + " must have shape (n,) or (n, k) with n = " + std::to_string(num_vertices) +
                              " (one row per vertex), got shape " + shape_of(obj));
    const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    ss::VertexAttribute out{name, a.ndim() == 2 ? static_cast<uint32_t>(a.shape(1)) : 1u, ss::blend_for(name),
                            std::vector<double>(d.data(), d.data() + d.size())};
    for (size_t i = 0; i < out.values.size(); ++i)
        if (!std::isfinite(out.values[i]))
            throw py::value_error(what + ": vertex " + std::to_string(i / out.components) + " has a non-finite value");
    return out;
}

/// `attributes` (dict name -> array) and `blend` (dict name -> kind; default from the name,
/// attributes.hpp blend_for) as the soup's attributes.
std::vector<ss::VertexAttribute> to_attributes(const py::object& attributes, const py::object& blend, size_t num_vertices) {
    std::vector<ss::VertexAttribute> out;
    if (!attributes.is_none() && !py::isinstance<py::dict>(attributes))
        throw py::type_error("attributes must be a dict (name -> array of shape (n, k)), got " +
                             std::string(py::str(py::type::of(attributes).attr("__name__"))));
    if (!blend.is_none() && !py::isinstance<py::dict>(blend))
        throw py::type_error("blend must be a dict (name -> \"linear\", \"unit\" or \"nearest\")");
    if (!attributes.is_none())
        for (const auto& [key, value] : attributes.cast<py::dict>()) {
            if (!py::isinstance<py::str>(key))
                throw py::type_error("attributes: every name must be a str, got " + std::string(py::repr(key)));
            out.push_back(to_attribute(key.cast<std::string>(), value, num_vertices));
        }
    if (!blend.is_none())
        for (const auto& [key, value] : blend.cast<py::dict>()) {
            const std::string name = py::str(key);
            ss::VertexAttribute* a = nullptr;
            for (ss::VertexAttribute& x : out)
                if (x.name == name) a = &x;
            if (!a) throw py::value_error("blend names '" + name + "', which is not in attributes");
            a->blend = to_blend(value, name);
        }
    return out;
}

/// Attributes as {name: (n, k) float64 array} and {name: blend kind}.
std::pair<py::dict, py::dict> attributes_dicts(const std::vector<ss::VertexAttribute>& attrs) {
    py::dict values, blends;
    for (const ss::VertexAttribute& a : attrs) {
        const auto k = static_cast<py::ssize_t>(a.components);
        py::array_t<double> arr({k == 0 ? py::ssize_t{0} : static_cast<py::ssize_t>(a.values.size()) / k, k});
        std::copy(a.values.begin(), a.values.end(), arr.mutable_data());
        values[py::str(a.name)] = arr;
        blends[py::str(a.name)] = blend_name(a.blend);
    }
    return {values, blends};
}

/// The file as (V, F), or with `attributes` as the dict strip() takes: strip(**read(p, attributes=True)).
py::object read_mesh(const std::string& path, const py::object& format, bool attributes) {
    ss::ReadOptions o;
    if (!format.is_none()) o.format = format.cast<std::string>();
    ss::TriangleSoup soup;
    translate([&] {
        py::gil_scoped_release release;
        // glTF as the CLI reads it for a plain (non-scene) output: every triangle primitive, one soup.
        soup = ss::is_gltf_path(path) && o.format.empty() ? ss::read_gltf_soup(path) : ss::read_input(path, o);
        return 0;
    });
    if (!attributes) return py::make_tuple(rows_array<double>(soup.points), rows_array<uint32_t>(soup.triangles));
    py::dict d;
    d["vertices"] = rows_array<double>(soup.points);
    d["faces"] = rows_array<uint32_t>(soup.triangles);
    const auto [values, blends] = attributes_dicts(soup.attributes);
    d["attributes"] = values;
    d["blend"] = blends;
    return d;
}

py::dict strip(const py::object& vertices, const py::object& faces, const py::object& constraints, const py::object& source,
               const py::object& target, bool cycles, const py::object& seed_face, bool greedy, bool orient, const std::string& name,
               const std::string& engine, bool repair, bool weld, const std::string& join, const py::object& attributes,
               const py::object& blend, bool polish) {
    ss::TriangleSoup soup;
    soup.points = to_points(vertices, name.c_str());
    soup.triangles = to_faces(faces, soup.points.size(), name.c_str());
    soup.attributes = to_attributes(attributes, blend, soup.points.size());
    if (soup.triangles.empty()) throw py::value_error(name + ": the mesh has no faces");
    ss::PipelineOptions opt;
    opt.strip.engine = to_engine(engine);
    opt.strip.greedy = greedy;
    opt.strip.polish = polish;
    opt.strip.source = to_vertex_id(source, "source");
    opt.strip.target = to_vertex_id(target, "target");
    opt.strip.seed_face = to_face_id(seed_face, "seed_face");
    for (const auto& [a, b] : to_constraints(constraints, soup.points.size())) opt.strip.constraint_edges.push_back({a, b});
    opt.orient = orient;
    opt.repair = repair;
    opt.weld = weld;
    const auto join_mode = ss::parse_join_mode(join);
    if (!join_mode) throw py::value_error("unknown join '" + join + "' (choices: degenerate, restart)");
    opt.join = *join_mode;
    opt.cycles = cycles;
    opt.name = name;

    ss::PipelineResult r;
    translate([&] {
        py::gil_scoped_release release;
        r = ss::stripify(std::move(soup), opt);
        return 0;
    });

    py::dict out;
    out["vertices"] = rows_array<double>(r.arrays.points);
    out["faces"] = rows_array<uint32_t>(r.arrays.faces);
    out["parent"] = vec_array(r.arrays.parent);
    out["strip"] = vec_array(r.indices);
    if (r.cycles) {
        py::list cl;
        for (const auto& c : r.cycles->cycles) cl.append(vec_array(c));
        out["cycles"] = cl;
        out["cycle_lengths"] = vec_array(r.cycles->lengths);
    } else {
        out["cycles"] = py::none();
    }
    out["route"] = route_dict(ss::strip_route(r.arrays));
    // Interpolated by the library (stripify(), attributes.hpp): midpoints blended in their parent face.
    const auto [values, blends] = attributes_dicts(r.arrays.attributes);
    out["attributes"] = values;
    out["blend"] = blends;
    // The CLI's --report keys (report.hpp), minus file names and timings.
    ss::ReportInput rep;
    rep.result = &r;
    out["report"] = py::module_::import("json").attr("loads")(ss::report_json(rep));
    return out;
}

py::dict verify(const py::object& vertices, const py::object& faces, const py::dict& result, const py::object& constraints,
                const py::object& source, const py::object& target, bool repair, bool weld, bool orient, const py::object& attributes,
                const py::object& blend) {
    ss::VerifyInput in;
    in.in_points = to_points(vertices, "vertices");
    in.in_faces = to_faces(faces, in.in_points.size(), "faces");
    std::vector<ss::VertexAttribute> in_attributes = to_attributes(attributes, blend, in.in_points.size());
    if (!result.contains("vertices") || !result.contains("faces"))
        throw py::value_error("result must be a dict with 'vertices' and 'faces' (as returned by singlestrip.strip)");
    in.out_points = to_points(result["vertices"], "result['vertices']");
    in.out_faces = to_faces(result["faces"], in.out_points.size(), "result['faces']");
    if (result.contains("parent") && !result["parent"].is_none())
        in.out_parent = py::cast<std::vector<uint32_t>>(py::array_t<uint32_t, py::array::forcecast>::ensure(result["parent"]));
    if (result.contains("attributes") && !result["attributes"].is_none()) {
        // Float64 arrays: the verifier's double tolerance (1e-9 absolute + relative).
        for (ss::VertexAttribute& a : to_attributes(result["attributes"], py::none(), in.out_points.size()))
            in.out_attributes.push_back({a.name, a.components, std::move(a.values)});
    }
    if (result.contains("strip") && !result["strip"].is_none())
        in.indices = py::cast<std::vector<uint32_t>>(py::array_t<uint32_t, py::array::forcecast>::ensure(result["strip"]));
    if (result.contains("cycles") && !result["cycles"].is_none()) {
        std::vector<std::vector<uint32_t>> cs;
        for (const py::handle& c : result["cycles"]) {
            std::vector<uint32_t> v;
            for (const py::handle& x : c) v.push_back(x.cast<uint32_t>());
            cs.push_back(std::move(v));
        }
        in.cycles = std::move(cs);
    }
    in.constraints = to_constraints(constraints, in.in_points.size());
    in.source = to_vertex(source, "source");
    in.target = to_vertex(target, "target");
    ss::VerifyReport rep;
    {
        py::gil_scoped_release release;
        const std::vector<std::string> notes = ss::replay_input_steps(in, {weld, repair, orient}, std::move(in_attributes));
        rep = ss::verify(in);
        rep.notes.insert(rep.notes.begin(), notes.begin(), notes.end());
    }
    py::dict d;
    d["ok"] = rep.ok();
    d["failures"] = rep.failures;
    d["notes"] = rep.notes;
    d["input_faces"] = rep.input_faces;
    d["output_faces"] = rep.output_faces;
    d["output_vertices"] = rep.output_vertices;
    d["euler_characteristic"] = rep.euler_characteristic;
    d["boundary_loops"] = rep.boundary_loops;
    d["genus"] = rep.genus;
    d["strips"] = rep.strips;
    d["cycles_checked"] = rep.cycles_checked;
    d["cycle_rank"] = rep.cycle_rank;
    d["text"] = rep.to_string();
    return d;
}

}  // namespace

PYBIND11_MODULE(singlestrip, m) {
    m.doc() = "singlestrip: one triangle strip for an oriented 2-manifold triangle mesh";
    m.attr("__version__") = "0.1.0";
    m.def("strip", &strip, py::arg("vertices"), py::arg("faces"), py::arg("constraints") = py::none(), py::arg("source") = py::none(),
          py::arg("target") = py::none(), py::arg("cycles") = false, py::arg("seed_face") = py::none(), py::arg("greedy") = true,
          py::arg("orient") = false, py::arg("name") = "input", py::arg("engine") = "matching", py::arg("repair") = false,
          py::arg("weld") = false, py::arg("join") = "degenerate", py::arg("attributes") = py::none(), py::arg("blend") = py::none(),
          py::arg("polish") = false,
          R"doc(Turn a triangle mesh into ONE triangle strip per edge-connected component.

vertices: (n, 3) floats; faces: (m, 3) vertex indices (0-based), consistently oriented
(orient=True re-orients), edge-connected, manifold.
constraints: polylines of vertex ids (or an (E, 2) array of edges) the strip must not cross.
source/target: vertex ids the first/last strip face must touch. seed_face: input face to start.
cycles: also compute the fundamental cycles (face chains into the output faces).
name: prefix of error messages (the CLI uses the file name).
engine: "matching" (default) or "growth" (the paper's builder, for comparison).
polish: matching engine, spend two to three times the strip time on fewer swaps (about 1% fewer
GL indices; report["polished"] counts the faces rematched).
repair: weld, drop degenerate/duplicate faces, cut non-manifold and non-orientable parts apart,
orient (docs/repair.md; report["repair"] says what changed). weld: only merge equal vertices.
join: "degenerate" (default) or "restart" (0xFFFFFFFF) between the strips of several components.
attributes: per-vertex attributes, a dict name -> (n,) or (n, k) array of real numbers (glTF
names: NORMAL, TEXCOORD_0, COLOR_0, ...; any other name is custom). blend: dict name -> how a
midpoint gets its value: "linear" (barycentric average), "unit" (average renormalised) or
"nearest" (copied from the nearest corner); default from the name (NORMAL/TANGENT unit,
JOINTS_n/WEIGHTS_n nearest, others linear). read(path, attributes=True) gives both dicts.

Returns a dict: vertices (n', 3) float64 (input vertices first, midpoints after), faces (m', 3)
uint32 in strip order, parent (m',) uint32 input face of each output face, attributes (dict
name -> (n', k) float64 per output vertex, midpoints interpolated by the library; empty without
input attributes), blend (dict name -> kind), strip (k,) uint32
GL_TRIANGLE_STRIP indices, cycles (list of uint32 arrays, or None), route (dict: points (k, 3)
float64 through face centroids and shared-edge midpoints in strip order, face and parent (k,)
uint32, distance (k,) float64 along the route, length, planar_z), report (dict).
Raises ValueError for arrays of the wrong shape or kind (faces must be integers), TypeError for
attributes that are not a dict of numeric arrays.
Raises ValueError for invalid input, an impossible request or an unknown engine (same messages
as the CLI).)doc");
    m.def("verify", &verify, py::arg("vertices"), py::arg("faces"), py::arg("result"), py::arg("constraints") = py::none(),
          py::arg("source") = py::none(), py::arg("target") = py::none(), py::arg("repair") = false, py::arg("weld") = false,
          py::arg("orient") = false, py::arg("attributes") = py::none(), py::arg("blend") = py::none(),
          R"doc(Independently check `result` (a dict as returned by strip(): vertices, faces, optional parent,
strip, cycles) against the input mesh. Returns a dict with ok (bool), failures, notes, counts and
text (the CLI's `verify` output). repair/weld/orient: `result` was made with them; the input is
replayed through the library's repair first (a note says what it changed).
attributes, blend: the input's vertex attributes, as given to strip(); with result["attributes"]
every output vertex's values are checked (input vertices unchanged, midpoints interpolated in
their parent face; a failure names the vertex, the attribute and both values).)doc");
    m.def(
        "decode_strip",
        [](const py::object& indices) {
            const auto idx = py::cast<std::vector<uint32_t>>(py::array_t<uint32_t, py::array::forcecast>::ensure(indices));
            return rows_array<uint32_t>(ss::decode_triangle_strip(idx));
        },
        py::arg("indices"), "Decode GL_TRIANGLE_STRIP indices into (t, 3) triangles (degenerate ones skipped).");
    m.def("read", &read_mesh, py::arg("path"), py::arg("format") = py::none(), py::arg("attributes") = false,
          R"doc(Read a mesh file (.obj, .off, .ply, .stl, .glb, .gltf, as the CLI does; or "builtin:genus2";
a glTF file gives all its triangle primitives as one mesh).

format: "obj", "off", "ply" or "stl" when the name does not tell (e.g. "/dev/stdin").
Returns (V, F): V (n, 3) float64 vertices in file order, F (m, 3) uint32 triangles (0-based;
polygons fan-triangulated; STL corners welded).
attributes=True returns a dict instead, the keyword arguments of strip(): vertices, faces,
attributes (name -> (n, k) float64: OBJ vt/vn as TEXCOORD_0/NORMAL, PLY and OFF normals,
colours in [0, 1], texture coordinates and other vertex properties, glTF accessors) and blend
(name -> "linear", "unit" or "nearest"). A vertex is a position plus its attributes: an OBJ
seam gives one vertex per (v, vt, vn) combination. strip(**read(path, attributes=True)) keeps them.
Raises ValueError with the CLI's message for a missing, unreadable or malformed file.)doc");
}
