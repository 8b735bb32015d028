// singlestrip — the verifier's own readers for OUTPUT files (.obj/.off here, .ply in
// verify_read_ply.cpp), index files and cycle files, and the helpers they share. Deliberately independent of src/io/*: a bug in the writer
// or the input readers must not be able to hide itself by being read back with the same code.
#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "singlestrip/errors.hpp"
#include "singlestrip/verify.hpp"
#include "verify_read_common.hpp"

namespace singlestrip {

namespace verify_read_detail {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
    throw InputError(path + ": " + what);
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, "cannot open file");
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) fail(path, "read error");
    return std::move(ss).str();
}

bool parse_double(std::string_view tok, double& out) {
    if (!tok.empty() && tok.front() == '+') tok.remove_prefix(1);
    const char* end = tok.data() + tok.size();
    auto res = std::from_chars(tok.data(), end, out);
    return res.ec == std::errc() && res.ptr == end;
}

bool parse_long(std::string_view tok, long long& out) {
    if (!tok.empty() && tok.front() == '+') tok.remove_prefix(1);
    const char* end = tok.data() + tok.size();
    auto res = std::from_chars(tok.data(), end, out);
    return res.ec == std::errc() && res.ptr == end;
}

std::vector<std::string_view> split_ws(std::string_view line) {
    std::vector<std::string_view> out;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        size_t j = i;
        while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
        if (j > i) out.push_back(line.substr(i, j - i));
        i = j;
    }
    return out;
}

std::vector<std::string_view> split_lines(std::string_view text) {
    std::vector<std::string_view> lines;
    size_t start = 0;
    while (start <= text.size()) {
        size_t nl = text.find('\n', start);
        if (nl == std::string_view::npos) nl = text.size();
        std::string_view line = text.substr(start, nl - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        lines.push_back(line);
        start = nl + 1;
    }
    return lines;
}

const OutputAttribute* find_output_attribute(const std::vector<OutputAttribute>& attrs, const std::string& name) {
    for (const OutputAttribute& a : attrs)
        if (a.name == name) return &a;
    return nullptr;
}

void check_point(const std::string& path, size_t v, const Point3& p) {
    for (double c : p)
        if (!std::isfinite(c)) fail(path, "vertex " + std::to_string(v) + " has a non-finite coordinate");
}

void check_indices(const std::string& path, const OutputMesh& m) {
    for (size_t f = 0; f < m.faces.size(); ++f)
        for (uint32_t v : m.faces[f])
            if (v >= m.points.size())
                fail(path, "face " + std::to_string(f) + " references vertex " + std::to_string(v) + " but the file has only " +
                               std::to_string(m.points.size()) + " vertices");
}
}  // namespace verify_read_detail

using namespace verify_read_detail;

namespace {

// The verifier's own copy of io.hpp's lower_extension (without the dot): its readers share no
// code with the readers whose output it checks.
std::string lower_extension(const std::string& path) {
    const auto slash = path.find_last_of("/\\");
    const auto dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
    std::string ext = path.substr(dot + 1);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}
// ---------------------------------------------------------------------------------------------
// OBJ

/// One OBJ record of numbers ("vt u v", "vn x y z"): its first `k` numbers.
std::vector<double> obj_numbers(const std::string& path, const std::vector<std::string_view>& tok, size_t k, const std::string& where) {
    if (tok.size() < k + 1) fail(path, where + ": '" + std::string(tok[0]) + "' needs " + std::to_string(k) + " numbers");
    std::vector<double> x(k);
    for (size_t i = 0; i < k; ++i)
        if (!parse_double(tok[i + 1], x[i]) || !std::isfinite(x[i])) fail(path, where + ": bad number '" + std::string(tok[i + 1]) + "'");
    return x;
}

/// An OBJ index (1-based, or negative: relative to the `count` records read so far) as 0-based.
long long obj_index(long long idx, size_t count) {
    return idx > 0 ? idx - 1 : static_cast<long long>(count) + idx;
}

/// The per-vertex attribute of one OBJ index stream (vt or vn): vertex v takes the record its
/// corners name; every corner must name one (else no attribute) and all of v's the same one.
struct ObjStream {
    const char* name;
    size_t width;
    std::vector<double> records;                   // width numbers per record
    std::vector<std::array<long long, 3>> corner;  // raw index per face corner, 0 = none
    std::vector<size_t> count_at;                  // records read when the face was read
};

void obj_stream_attribute(const std::string& path, const ObjStream& st, const OutputMesh& m, std::vector<OutputAttribute>& out) {
    const size_t n_rec = st.records.size() / st.width;
    for (const auto& c : st.corner)
        for (long long x : c)
            if (x == 0) return;  // a corner without one: the stream is not an attribute
    if (st.corner.empty()) return;
    OutputAttribute a{
        st.name,       static_cast<uint32_t>(st.width), std::vector<double>(m.points.size() * st.width, std::nan("")), 1e-9, 1e-9,
        "decimal text"};
    std::vector<long long> given(m.points.size(), -1);
    for (size_t f = 0; f < st.corner.size(); ++f)
        for (size_t k = 0; k < 3; ++k) {
            const long long r = obj_index(st.corner[f][k], st.count_at[f]);
            if (r < 0 || static_cast<size_t>(r) >= n_rec)
                fail(path, "face " + std::to_string(f) + " references " + st.name + " record " + std::to_string(st.corner[f][k]) +
                               " but the file has " + std::to_string(n_rec));
            const uint32_t v = m.faces[f][k];
            if (given[v] >= 0 && given[v] != r &&
                !std::equal(&st.records[static_cast<size_t>(r) * st.width], &st.records[static_cast<size_t>(r) * st.width] + st.width,
                            &st.records[static_cast<size_t>(given[v]) * st.width]))
                fail(path, "vertex " + std::to_string(v) + " is given two different " + st.name + " values by its corners (face " +
                               std::to_string(f) + "); an output vertex has one");
            given[v] = r;
            std::copy_n(&st.records[static_cast<size_t>(r) * st.width], st.width, &a.values[v * st.width]);
        }
    out.push_back(std::move(a));
}

OutputMesh read_obj(const std::string& path) {
    const std::string text = slurp(path);
    OutputMesh m;
    std::vector<std::array<long long, 3>> raw;  // 1-based or negative, resolved below
    std::vector<size_t> nverts_at;              // vertex count when the face was read
    ObjStream uv{"TEXCOORD_0", 2, {}, {}, {}}, nrm{"NORMAL", 3, {}, {}, {}};
    std::vector<double> rgb;  // "v x y z r g b": only when every v has one
    bool every_v_coloured = true;
    const auto lines = split_lines(text);
    for (size_t li = 0; li < lines.size(); ++li) {
        std::string_view line = lines[li];
        if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        const auto tok = split_ws(line);
        if (tok.empty()) continue;
        const std::string where = "line " + std::to_string(li + 1);
        if (tok[0] == "v") {
            if (tok.size() < 4) fail(path, where + ": vertex needs 3 coordinates");
            Point3 p{};
            for (int k = 0; k < 3; ++k)
                if (!parse_double(tok[static_cast<size_t>(k) + 1], p[static_cast<size_t>(k)]))
                    fail(path, where + ": bad coordinate '" + std::string(tok[static_cast<size_t>(k) + 1]) + "'");
            check_point(path, m.points.size(), p);
            m.points.push_back(p);
            every_v_coloured = every_v_coloured && tok.size() == 7;
            if (every_v_coloured) {
                const std::vector<double> c = obj_numbers(path, {tok.begin() + 3, tok.end()}, 3, where);
                rgb.insert(rgb.end(), c.begin(), c.end());
            }
        } else if (tok[0] == "vt" || tok[0] == "vn") {
            ObjStream& st = tok[0] == "vt" ? uv : nrm;
            const std::vector<double> x = obj_numbers(path, tok, st.width, where);
            st.records.insert(st.records.end(), x.begin(), x.end());
        } else if (tok[0] == "f") {
            if (tok.size() != 4)
                fail(path, where + ": face " + std::to_string(raw.size()) + " has " + std::to_string(tok.size() - 1) +
                               " vertices, expected a triangle");
            std::array<long long, 3> f{}, t{}, n{};
            for (size_t k = 0; k < 3; ++k) {
                const std::string_view full = tok[k + 1];
                const size_t s1 = full.find('/'), s2 = s1 == std::string_view::npos ? s1 : full.find('/', s1 + 1);
                auto index = [&](std::string_view part, long long& out) {
                    if (part.empty()) return;  // "i//n": no texture coordinate
                    if (!parse_long(part, out) || out == 0) fail(path, where + ": bad vertex index '" + std::string(full) + "'");
                };
                if (!parse_long(full.substr(0, s1), f[k]) || f[k] == 0)
                    fail(path, where + ": bad vertex index '" + std::string(full) + "'");
                if (s1 != std::string_view::npos) index(full.substr(s1 + 1, s2 == std::string_view::npos ? s2 : s2 - s1 - 1), t[k]);
                if (s2 != std::string_view::npos) index(full.substr(s2 + 1), n[k]);
            }
            raw.push_back(f);
            nverts_at.push_back(m.points.size());
            uv.corner.push_back(t), uv.count_at.push_back(uv.records.size() / 2);
            nrm.corner.push_back(n), nrm.count_at.push_back(nrm.records.size() / 3);
        }
        // g, o, s, usemtl, mtllib, l: irrelevant to the check.
    }
    m.faces.resize(raw.size());
    for (size_t f = 0; f < raw.size(); ++f) {
        for (size_t k = 0; k < 3; ++k) {
            const long long idx = obj_index(raw[f][k], nverts_at[f]);
            if (idx < 0 || idx >= static_cast<long long>(m.points.size()))
                fail(path, "face " + std::to_string(f) + " references vertex " + std::to_string(raw[f][k]) + " but the file has only " +
                               std::to_string(m.points.size()) + " vertices");
            m.faces[f][k] = static_cast<uint32_t>(idx);
        }
    }
    if (m.faces.empty()) fail(path, "no faces");
    obj_stream_attribute(path, uv, m, m.attributes);
    obj_stream_attribute(path, nrm, m, m.attributes);
    if (every_v_coloured && !m.points.empty()) m.attributes.push_back({"COLOR_0", 3, std::move(rgb), 1e-9, 1e-9, "decimal text"});
    return m;
}

// ---------------------------------------------------------------------------------------------
// OFF

/// The attributes of OFF vertex rows "x y z [nx ny nz] [r g b [a]] [s t]". Colours: in a file
/// with an all-integer colour above 1 the all-integer colours are bytes (/255), else fractions.
std::vector<OutputAttribute> off_attributes(const std::string& path, const std::vector<std::vector<std::string_view>>& rows, bool nrm,
                                            bool col, bool tex) {
    OutputAttribute n{"NORMAL", 3, {}, 1e-9, 1e-9, "decimal text"}, c{"COLOR_0", 3, {}, 1e-9, 1e-9, "decimal text"},
        t{"TEXCOORD_0", 2, {}, 1e-9, 1e-9, "decimal text"};
    const size_t base = nrm ? 6 : 3, extra = tex ? 2 : 0;
    std::vector<std::vector<double>> colours;
    bool bytes = false;
    for (size_t v = 0; v < rows.size(); ++v) {
        const auto& row = rows[v];
        const size_t k = row.size() < base + extra ? 0 : row.size() - base - extra;
        if (row.size() < base + extra || (col ? k != 3 && k != 4 : k != 0))
            fail(path, "vertex " + std::to_string(v) + " has " + std::to_string(row.size()) + " numbers, which does not fit its header");
        std::vector<double> x(row.size());
        for (size_t i = 3; i < row.size(); ++i)
            if (!parse_double(row[i], x[i])) fail(path, "vertex " + std::to_string(v) + ": bad number '" + std::string(row[i]) + "'");
        if (nrm) n.values.insert(n.values.end(), x.begin() + 3, x.begin() + 6);
        if (tex) t.values.insert(t.values.end(), x.end() - 2, x.end());
        if (!col) continue;
        colours.emplace_back(x.begin() + static_cast<std::ptrdiff_t>(base), x.begin() + static_cast<std::ptrdiff_t>(base + k));
        const auto& rgb = colours.back();
        const bool whole = std::floor(rgb[0]) == rgb[0] && std::floor(rgb[1]) == rgb[1] && std::floor(rgb[2]) == rgb[2];
        bytes = bytes || (whole && std::max({rgb[0], rgb[1], rgb[2]}) > 1);
        c.components = std::max<uint32_t>(c.components, static_cast<uint32_t>(k));
    }
    for (const auto& rgb : colours) {
        const bool whole = std::floor(rgb[0]) == rgb[0] && std::floor(rgb[1]) == rgb[1] && std::floor(rgb[2]) == rgb[2];
        const double scale = bytes && whole ? 1.0 / 255 : 1.0;
        for (size_t i = 0; i < c.components; ++i)
            c.values.push_back(i < rgb.size() ? (i < 3 ? rgb[i] * scale : std::clamp(rgb[i] * scale, 0.0, 1.0)) : 1.0);
    }
    if (bytes) c.abs_tol = 0.5 / 255 + 1e-12, c.rel_tol = 0, c.storage = "8-bit";
    std::vector<OutputAttribute> out;
    if (nrm) out.push_back(std::move(n));
    if (col) out.push_back(std::move(c));
    if (tex) out.push_back(std::move(t));
    return out;
}

OutputMesh read_off(const std::string& path) {
    const std::string text = slurp(path);
    // Non-comment, non-blank lines.
    std::vector<std::vector<std::string_view>> rows;
    for (std::string_view line : split_lines(text)) {
        if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        auto tok = split_ws(line);
        if (!tok.empty()) rows.push_back(std::move(tok));
    }
    if (rows.empty()) fail(path, "empty file");
    size_t r = 0;
    auto& head = rows[0];
    const std::string_view magic = head[0];
    const bool tex = magic.substr(0, 2) == "ST";
    const std::string_view rest = magic.substr(tex ? 2 : 0);
    const bool col = rest.substr(0, 1) == "C", nrm = rest.substr(col ? 1 : 0) == "NOFF";
    if (rest.substr((col ? 1 : 0) + (nrm ? 1 : 0)) != "OFF") fail(path, "not an OFF file (header '" + std::string(magic) + "')");
    std::vector<std::string_view> counts(head.begin() + 1, head.end());
    ++r;
    if (counts.empty()) {
        if (r >= rows.size()) fail(path, "missing counts line");
        counts = rows[r++];
    }
    long long nv = 0, nf = 0;
    if (counts.size() < 2 || !parse_long(counts[0], nv) || !parse_long(counts[1], nf) || nv < 0 || nf < 0) fail(path, "bad counts line");
    if (static_cast<size_t>(nv + nf) > rows.size()) fail(path, "truncated file (fewer lines than the counts say)");
    OutputMesh m;
    m.points.resize(static_cast<size_t>(nv));
    for (size_t v = 0; v < m.points.size(); ++v, ++r) {
        if (r >= rows.size()) fail(path, "truncated at vertex " + std::to_string(v));
        if (rows[r].size() < 3) fail(path, "vertex " + std::to_string(v) + " needs 3 coordinates");
        for (size_t k = 0; k < 3; ++k)
            if (!parse_double(rows[r][k], m.points[v][k]))
                fail(path, "vertex " + std::to_string(v) + ": bad coordinate '" + std::string(rows[r][k]) + "'");
        check_point(path, v, m.points[v]);
    }
    if (tex || col || nrm)
        m.attributes = off_attributes(
            path, {rows.begin() + static_cast<std::ptrdiff_t>(r - m.points.size()), rows.begin() + static_cast<std::ptrdiff_t>(r)}, nrm,
            col, tex);
    m.faces.resize(static_cast<size_t>(nf));
    for (size_t f = 0; f < m.faces.size(); ++f, ++r) {
        if (r >= rows.size()) fail(path, "truncated at face " + std::to_string(f));
        long long k = 0;
        if (!parse_long(rows[r][0], k)) fail(path, "face " + std::to_string(f) + ": bad vertex count");
        if (k != 3) fail(path, "face " + std::to_string(f) + " has " + std::to_string(k) + " vertices, expected a triangle");
        if (rows[r].size() < 4) fail(path, "face " + std::to_string(f) + ": truncated");
        for (size_t j = 0; j < 3; ++j) {
            long long idx = 0;
            if (!parse_long(rows[r][j + 1], idx) || idx < 0 || idx > 0xffffffffLL)
                fail(path, "face " + std::to_string(f) + ": bad vertex index '" + std::string(rows[r][j + 1]) + "'");
            m.faces[f][j] = static_cast<uint32_t>(idx);
        }
    }
    check_indices(path, m);
    return m;
}

}  // namespace

OutputMesh read_output_mesh(const std::string& path) {
    const std::string ext = lower_extension(path);
    if (ext == "ply") return read_ply(path);
    if (ext == "obj") return read_obj(path);
    if (ext == "off") return read_off(path);
    if (ext == "glb" || ext == "gltf" || ext == "stl")
        fail(path, "a ." + ext + " result cannot be read back exactly (float32 positions" + (ext == "stl" ? ", no shared vertices" : "") +
                       "); use the .ply, .obj or .off result of the same run");
    fail(path, "cannot read a result with extension '" + ext + "' (expected .ply, .obj or .off)");
}

std::vector<uint32_t> read_index_file(const std::string& path) {
    const std::string text = slurp(path);
    std::vector<uint32_t> out;
    for (std::string_view tok : split_ws(text)) {
        long long v = 0;
        if (!parse_long(tok, v) || v < 0 || v > 0xffffffffLL)
            fail(path, "index " + std::to_string(out.size()) + ": bad token '" + std::string(tok) + "'");
        out.push_back(static_cast<uint32_t>(v));
    }
    return out;
}

std::vector<std::vector<uint32_t>> read_cycles_file(const std::string& path) {
    const std::string text = slurp(path);
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        fail(path, std::string("not valid JSON: ") + e.what());
    }
    if (!j.is_object() || !j.contains("cycles") || !j["cycles"].is_array()) fail(path, "expected an object with an array \"cycles\"");
    std::vector<std::vector<uint32_t>> cycles;
    for (size_t c = 0; c < j["cycles"].size(); ++c) {
        const auto& arr = j["cycles"][c];
        if (!arr.is_array()) fail(path, "cycle " + std::to_string(c) + " is not an array");
        std::vector<uint32_t> cyc;
        for (const auto& x : arr) {
            if (!x.is_number_unsigned() || x.get<uint64_t>() > 0xffffffffULL)
                fail(path, "cycle " + std::to_string(c) + ": entries must be face indices");
            cyc.push_back(static_cast<uint32_t>(x.get<uint64_t>()));
        }
        cycles.push_back(std::move(cyc));
    }
    return cycles;
}

}  // namespace singlestrip
