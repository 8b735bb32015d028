"""Tests of the Python module `singlestrip` (pybind11 + numpy).

Run: PYTHONPATH=<build>/python /usr/bin/python3 -m pytest tests/python
Optional environment: SINGLESTRIP_CLI (path of the built CLI, to compare error messages) and
SINGLESTRIP_SOURCE_DIR (repository root; default: two levels above this file).
"""
import math
import os
import subprocess

import numpy as np
import pytest

import singlestrip as ss

SOURCE_DIR = os.environ.get("SINGLESTRIP_SOURCE_DIR",
                            os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
DATA = os.path.join(SOURCE_DIR, "tests", "data")


def read_off(path):
    """Minimal OFF reader for the test data (triangles and polygons, fan-triangulated)."""
    tokens = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0]
            tokens.extend(line.split())
    assert tokens[0] == "OFF"
    nv, nf = int(tokens[1]), int(tokens[2])
    pos = 4
    v = np.array([[float(t) for t in tokens[pos + 3 * i: pos + 3 * i + 3]] for i in range(nv)])
    pos += 3 * nv
    faces = []
    for _ in range(nf):
        k = int(tokens[pos])
        ids = [int(t) for t in tokens[pos + 1: pos + 1 + k]]
        pos += 1 + k
        for i in range(1, k - 1):
            faces.append([ids[0], ids[i], ids[i + 1]])
    return v, np.array(faces, dtype=np.int64)


def torus(n_major=16, n_minor=8, R=2.0, r=0.7):
    v = []
    for i in range(n_major):
        a = 2 * math.pi * i / n_major
        for j in range(n_minor):
            b = 2 * math.pi * j / n_minor
            v.append([(R + r * math.cos(b)) * math.cos(a), (R + r * math.cos(b)) * math.sin(a), r * math.sin(b)])
    f = []
    for i in range(n_major):
        for j in range(n_minor):
            a = i * n_minor + j
            b = ((i + 1) % n_major) * n_minor + j
            c = ((i + 1) % n_major) * n_minor + (j + 1) % n_minor
            d = i * n_minor + (j + 1) % n_minor
            f += [[a, b, c], [a, c, d]]
    return np.array(v), np.array(f)


def grid(n=6):
    v = np.array([[x, y, 0.0] for y in range(n + 1) for x in range(n + 1)])
    f = []
    for y in range(n):
        for x in range(n):
            a = y * (n + 1) + x
            f += [[a, a + 1, a + n + 2], [a, a + n + 2, a + n + 1]]
    return v, np.array(f)


def rotations(t):
    t = tuple(int(x) for x in t)
    return min(t, t[1:] + t[:1], t[2:] + t[:2])


def check_result(v, f, r):
    faces, parent, strip = r["faces"], r["parent"], r["strip"]
    assert r["vertices"].dtype == np.float64 and r["vertices"].shape[1] == 3
    assert faces.dtype == np.uint32 and faces.shape[1] == 3
    assert parent.shape == (len(faces),)
    # Input vertices unchanged, midpoints appended.
    assert np.array_equal(r["vertices"][: len(v)], np.asarray(v, dtype=np.float64))
    # One strip: consecutive faces share an edge.
    for a, b in zip(faces[:-1], faces[1:]):
        assert len(set(a.tolist()) & set(b.tolist())) == 2
    # The strip indices decode (independently, here in Python) to the faces in order.
    decoded = []
    for i in range(len(strip) - 2):
        a, b, c = (int(x) for x in strip[i: i + 3])
        if a == b or b == c or a == c:
            continue
        decoded.append((a, b, c) if i % 2 == 0 else (b, a, c))
    assert [rotations(t) for t in decoded] == [rotations(t) for t in faces]
    assert [rotations(t) for t in ss.decode_strip(strip)] == [rotations(t) for t in faces]
    # Every input face has a child; areas add up.
    assert set(parent.tolist()) == set(range(len(f)))
    rep = r["report"]
    assert rep["input_triangles"] == len(f)
    assert rep["output_triangles"] == len(faces)
    assert rep["strip_indices"] == len(strip)
    # The independent verifier agrees.
    vr = ss.verify(v, f, r)
    assert vr["ok"], vr["text"]


def test_torus_strip_with_cycles():
    v, f = torus()
    r = ss.strip(v, f, cycles=True)
    check_result(v, f, r)
    assert r["report"]["genus"] == 1
    assert len(r["cycles"]) == 2  # 2g for a closed surface
    for c in r["cycles"]:
        assert c.dtype == np.uint32 and len(c) >= 3
    vr = ss.verify(v, f, r)
    assert vr["ok"] and vr["cycles_checked"] == 2 and vr["cycle_rank"] == 2, vr["text"]


def test_grid_with_constraints_source_target():
    v, f = grid(6)
    # A horizontal polyline through the middle of the grid: vertices (x, 3) for x = 1..5.
    line = [3 * 7 + x for x in range(1, 6)]
    r = ss.strip(v, f, constraints=[line], source=0, target=48, seed_face=None)
    check_result(v, f, r)
    assert 0 in r["faces"][0].tolist()
    assert 48 in r["faces"][-1].tolist()
    assert r["report"]["options"]["constraint_edges"] == 4
    vr = ss.verify(v, f, r, constraints=[line], source=0, target=48)
    assert vr["ok"], vr["text"]
    # Constraints as an (E, 2) array work too.
    pairs = np.array([[line[i], line[i + 1]] for i in range(4)])
    r2 = ss.strip(v, f, constraints=pairs, source=0, target=48)
    assert ss.verify(v, f, r2, constraints=pairs, source=0, target=48)["ok"]


def test_verify_detects_a_broken_result():
    v, f = torus()
    r = ss.strip(v, f)
    broken = dict(r)
    faces = r["faces"].copy()
    faces[[0, len(faces) // 2]] = faces[[len(faces) // 2, 0]]  # breaks the strip
    broken["faces"] = faces
    broken["strip"] = None
    vr = ss.verify(v, f, broken)
    assert not vr["ok"] and vr["failures"]


def test_input_types_are_converted():
    v, f = torus(8, 6)
    r = ss.strip(v.astype(np.float32).tolist(), f.astype(np.int32))
    assert len(r["faces"]) >= len(f)


def test_orient_and_seed_face():
    v, f = torus(10, 6)
    f2 = f.copy()
    f2[3] = f2[3][[0, 2, 1]]  # one flipped face
    with pytest.raises(ValueError, match="inconsistent orientation"):
        ss.strip(v, f2)
    r = ss.strip(v, f2, orient=True)
    assert r["report"]["options"]["orient"] is True
    r = ss.strip(v, f, seed_face=7)
    assert 7 == r["parent"][0]


@pytest.mark.parametrize("bad_kwargs, pattern", [
    ({"source": 10 ** 6}, "source"),
    ({"seed_face": 10 ** 6}, "seed"),
    ({"constraints": [[0]]}, "fewer than 2"),
    ({"constraints": [[0, 10 ** 6]]}, "out of range"),
])
def test_bad_requests_raise_value_error(bad_kwargs, pattern):
    v, f = torus(8, 6)
    with pytest.raises(ValueError, match=pattern):
        ss.strip(v, f, **bad_kwargs)


def test_constraint_that_is_not_an_edge():
    v, f = grid(4)
    with pytest.raises(ValueError):
        ss.strip(v, f, constraints=[[0, 24]])


@pytest.mark.parametrize("vertices, faces, pattern", [
    (np.zeros((3, 2)), np.array([[0, 1, 2]]), "shape"),
    (np.zeros((3, 3)), np.array([[0, 1, 5]]), "references vertex 5"),
    (np.zeros((3, 3)), np.array([[0, 1, -1]]), "references vertex -1"),
    (np.array([[0, 0, 0], [1, 0, 0], [0, float("nan"), 0]]), np.array([[0, 1, 2]]), "non-finite"),
    (np.zeros((3, 3)), np.zeros((0, 3), dtype=int), "no faces"),
    ("not an array", np.array([[0, 1, 2]]), "shape"),
])
def test_malformed_arrays(vertices, faces, pattern):
    with pytest.raises(ValueError, match=pattern):
        ss.strip(vertices, faces)


STRUCTURAL = ["non_manifold_edge.off", "tetra_one_flipped.off", "repeated_vertex.off",
              "duplicate_face.off", "moebius.off", "non_manifold_vertex.off"]


@pytest.mark.parametrize("name", STRUCTURAL)
def test_structural_errors_match_the_cli(name, tmp_path):
    path = os.path.join(DATA, name)
    v, f = read_off(path)
    with pytest.raises(ValueError) as exc:
        ss.strip(v, f, name=path)
    message = str(exc.value)
    assert message.startswith(path + ": ")
    cli = os.environ.get("SINGLESTRIP_CLI")
    if not cli:
        pytest.skip("SINGLESTRIP_CLI not set: message not compared with the CLI")
    p = subprocess.run([cli, "strip", path, "-o", str(tmp_path / "out.ply")], capture_output=True, text=True)
    assert p.returncode == 3
    assert p.stderr.strip() == "singlestrip: error: " + message


def test_tetra_file_end_to_end():
    v, f = read_off(os.path.join(DATA, "tetra.off"))
    r = ss.strip(v, f, cycles=True)
    check_result(v, f, r)
    assert r["cycles"] == [] or len(r["cycles"]) == 0


@pytest.mark.parametrize("engine", ["matching", "growth"])
def test_engine_keyword(engine):
    v, f = torus(8, 6)
    r = ss.strip(v, f, engine=engine, cycles=True)
    check_result(v, f, r)
    assert r["report"]["engine"] == engine
    assert r["report"]["options"]["engine"] == engine


def test_polish_keyword():
    v, f = torus(24, 16)
    plain = ss.strip(v, f)
    r = ss.strip(v, f, polish=True)
    check_result(v, f, r)
    assert r["report"]["options"]["polish"] is True
    assert plain["report"]["options"]["polish"] is False
    assert r["report"]["polished"] >= 0
    assert "polished" not in plain["report"]
    assert len(r["strip"]) <= len(plain["strip"])


def test_default_engine_is_matching():
    v, f = grid(3)
    assert ss.strip(v, f)["report"]["options"]["engine"] == "matching"


def test_unknown_engine_raises_value_error():
    v, f = grid(3)
    with pytest.raises(ValueError, match=r"unknown engine 'fast' \(choices: matching, growth\)"):
        ss.strip(v, f, engine="fast")


# Issue 19: kinds and shapes are checked, never converted silently; read(); the route.

def test_float_faces_are_refused():
    v, f = grid(2)
    with pytest.raises(ValueError, match="integer array.*float64"):
        ss.strip(v, f.astype(np.float64))
    with pytest.raises(ValueError, match="integer array"):
        ss.verify(v, f.astype(np.float32), ss.strip(v, f))


@pytest.mark.parametrize("vertices, pattern", [
    (np.zeros((3, 3), dtype=complex), "real numbers.*complex"),
    (np.array([["a", "b", "c"]] * 3), "real numbers"),
    (np.zeros((3, 4)), r"shape \(n, 3\).*\(3, 4\)"),
])
def test_vertex_kind_and_shape(vertices, pattern):
    with pytest.raises(ValueError, match=pattern):
        ss.strip(vertices, np.array([[0, 1, 2]]))


def test_faces_shape_is_named():
    v, _ = grid(2)
    with pytest.raises(ValueError, match=r"shape \(m, 3\).*\(2, 4\)"):
        ss.strip(v, np.zeros((2, 4), dtype=np.int32))


def test_read_returns_numpy_arrays():
    v, f = ss.read(os.path.join(DATA, "tetra.obj"))
    assert v.dtype == np.float64 and v.shape == (4, 3)
    assert f.dtype == np.uint32 and f.shape == (4, 3)
    v2, f2 = ss.read(os.path.join(DATA, "tetra.off"))
    assert np.array_equal(v, v2) and np.array_equal(f, f2)
    # Polygons are fan-triangulated as the CLI does.
    _, fq = ss.read(os.path.join(DATA, "pyramid_quad.off"))
    assert fq.shape[1] == 3
    r = ss.strip(v, f)
    assert ss.verify(v, f, r)["ok"]


def test_read_errors_are_value_errors():
    with pytest.raises(ValueError, match="missing.off"):
        ss.read(os.path.join(DATA, "missing.off"))
    with pytest.raises(ValueError, match="references vertex"):
        ss.read(os.path.join(DATA, "index_out_of_range.off"))
    with pytest.raises(ValueError):
        ss.read(os.path.join(DATA, "tetra.off"), format="xyz")


def test_read_with_format_for_a_nameless_file(tmp_path):
    p = tmp_path / "mesh.data"
    with open(os.path.join(DATA, "tetra.off")) as src:
        p.write_text(src.read())
    v, f = ss.read(str(p), format="off")
    assert f.shape == (4, 3)


def test_route_through_centroids_and_midpoints():
    v, f = grid(4)
    r = ss.strip(v, f)
    route = r["route"]
    faces, pts = r["faces"], route["points"]
    n = len(faces)
    assert pts.dtype == np.float64 and pts.shape == (2 * n - 1, 3)
    assert route["face"].dtype == np.uint32 and list(route["face"][::2]) == list(range(n))
    centroids = r["vertices"][faces.astype(np.int64)].mean(axis=1)
    assert np.allclose(pts[::2], centroids)
    seg = np.linalg.norm(np.diff(pts, axis=0), axis=1)
    assert math.isclose(route["length"], seg.sum(), rel_tol=1e-12)
    assert np.allclose(route["distance"][1:], np.cumsum(seg))
    assert route["planar_z"]
    assert np.array_equal(route["parent"][::2], r["parent"])


def test_every_function_has_a_docstring():
    for name in ("strip", "verify", "decode_strip", "read"):
        assert len(getattr(ss, name).__doc__ or "") > 40, name


@pytest.mark.parametrize("name", STRUCTURAL + ["two_components.off"])
def test_repair_strips_every_broken_file_and_verifies(name):
    v, f = read_off(os.path.join(DATA, name))
    r = ss.strip(v, f, repair=True, join="restart")
    assert "repair" in r["report"]
    check = ss.verify(v, f, r, repair=True)
    assert check["ok"], check["text"]
    assert check["strips"] == r["report"]["strips"]


# ---- vertex attributes -----------------------------------------------------------------------

def grid_attributes(v):
    """Texture coordinates, unit normals (not all equal) and an integer id per grid() vertex."""
    n = np.stack([v[:, 0] - 2.5, v[:, 1] - 2.5, np.full(len(v), 3.0)], axis=1)
    n /= np.linalg.norm(n, axis=1)[:, None]
    return {"TEXCOORD_0": v[:, :2] / 5, "NORMAL": n, "part": np.arange(len(v)) % 5}


def midpoint_ends(r, v, f):
    """For every output vertex after the input's, the input edge (a, b) it is the midpoint of."""
    out = {}
    for face, parent in zip(r["faces"], r["parent"]):
        tri = f[parent]
        for w in face:
            if w < len(v) or w in out:
                continue
            for a, b in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])):
                if np.allclose(r["vertices"][w], (v[a] + v[b]) / 2, rtol=0, atol=1e-12):
                    out[int(w)] = (int(a), int(b))
    return out


def test_strip_interpolates_attributes_at_midpoints():
    v, f = grid(5)
    attrs = grid_attributes(v)
    r = ss.strip(v, f, attributes=attrs, blend={"part": "nearest"})
    assert r["blend"] == {"TEXCOORD_0": "linear", "NORMAL": "unit", "part": "nearest"}
    n_out = len(r["vertices"])
    assert n_out > len(v), "this grid needs midpoint splits"
    for name, a in attrs.items():
        got = r["attributes"][name]
        assert got.dtype == np.float64 and got.shape == (n_out, 2 if name == "TEXCOORD_0" else 3 if name == "NORMAL" else 1)
        assert np.array_equal(got[:len(v)].reshape(len(v), -1), a.reshape(len(v), -1).astype(float)), name
    ends = midpoint_ends(r, v, f)
    assert len(ends) == n_out - len(v)
    for w, (a, b) in ends.items():
        assert np.allclose(r["attributes"]["TEXCOORD_0"][w], (attrs["TEXCOORD_0"][a] + attrs["TEXCOORD_0"][b]) / 2)
        n = attrs["NORMAL"][a] + attrs["NORMAL"][b]
        assert np.allclose(r["attributes"]["NORMAL"][w], n / np.linalg.norm(n))
        assert r["attributes"]["part"][w, 0] in (attrs["part"][a], attrs["part"][b])
    assert ss.verify(v, f, r)["ok"]


def test_strip_without_attributes_returns_empty_dicts():
    v, f = grid(2)
    r = ss.strip(v, f)
    assert r["attributes"] == {} and r["blend"] == {}
    one = ss.strip(v, f, attributes={"q": np.arange(len(v), dtype=np.float32)})
    assert one["attributes"]["q"].shape == (len(one["vertices"]), 1)


def test_read_returns_the_files_attributes():
    mesh = ss.read(os.path.join(DATA, "sphere_attrs.ply"), attributes=True)
    assert set(mesh) == {"vertices", "faces", "attributes", "blend"}
    n = len(mesh["vertices"])
    a = mesh["attributes"]
    assert a["NORMAL"].shape == (n, 3) and a["COLOR_0"].shape == (n, 4) and a["TEXCOORD_0"].shape == (n, 2)
    assert a["quality"].shape == (n, 1) and a["id"].shape == (n, 1)
    assert 0 <= a["COLOR_0"].min() and a["COLOR_0"].max() <= 1
    assert mesh["blend"] == {"NORMAL": "unit", "COLOR_0": "linear", "TEXCOORD_0": "linear", "quality": "linear", "id": "nearest"}
    r = ss.strip(**mesh)
    assert set(r["attributes"]) == set(a)
    assert np.array_equal(r["attributes"]["id"][:n], a["id"])
    # Without the flag read() keeps its (V, F) pair.
    v, f = ss.read(os.path.join(DATA, "sphere_attrs.ply"))
    assert np.array_equal(v, mesh["vertices"]) and np.array_equal(f, mesh["faces"])


def test_read_obj_seams_are_vertices_with_their_attributes():
    mesh = ss.read(os.path.join(DATA, "sphere_uv.obj"), attributes=True)
    uv = mesh["attributes"]["TEXCOORD_0"]
    assert len(mesh["vertices"]) > 42 and uv.shape == (len(mesh["vertices"]), 2)
    r = ss.strip(**mesh)
    assert ss.verify(mesh["vertices"], mesh["faces"], r)["ok"]


def test_read_gltf_gives_its_accessors():
    mesh = ss.read(os.path.join(DATA, "scene.glb"), attributes=True)
    assert "NORMAL" in mesh["attributes"] and mesh["blend"]["NORMAL"] == "unit"
    assert all(x.shape[0] == len(mesh["vertices"]) for x in mesh["attributes"].values())


def test_bad_attributes_are_refused_with_a_clear_message():
    v, f = grid(2)
    n = len(v)
    with pytest.raises(TypeError, match="attributes must be a dict"):
        ss.strip(v, f, attributes=[np.zeros(n)])
    with pytest.raises(TypeError, match="every name must be a str"):
        ss.strip(v, f, attributes={1: np.zeros(n)})
    with pytest.raises(TypeError, match=r"attributes\['tag'\] must hold real numbers"):
        ss.strip(v, f, attributes={"tag": np.array(["x"] * n)})
    with pytest.raises(ValueError, match=r"attributes\['NORMAL'\] must have shape \(n,\) or \(n, k\) with n = 9.*\(8, 3\)"):
        ss.strip(v, f, attributes={"NORMAL": np.zeros((n - 1, 3))})
    bad = np.zeros((n, 2))
    bad[4, 1] = np.nan
    with pytest.raises(ValueError, match=r"attributes\['TEXCOORD_0'\]: vertex 4 has a non-finite value"):
        ss.strip(v, f, attributes={"TEXCOORD_0": bad})
    with pytest.raises(ValueError, match="choices: linear, unit, nearest"):
        ss.strip(v, f, attributes={"q": np.zeros(n)}, blend={"q": "cubic"})
    with pytest.raises(TypeError, match=r"blend\['q'\] must be a str"):
        ss.strip(v, f, attributes={"q": np.zeros(n)}, blend={"q": 1})
    with pytest.raises(ValueError, match="blend names 'w', which is not in attributes"):
        ss.strip(v, f, attributes={"q": np.zeros(n)}, blend={"w": "linear"})


def test_verify_checks_the_attribute_values():
    v, f = grid(5)
    attrs = grid_attributes(v)
    blend = {"part": "nearest"}
    r = ss.strip(v, f, attributes=attrs, blend=blend)
    check = ss.verify(v, f, r, attributes=attrs, blend=blend)
    assert check["ok"], check["text"]
    assert any("attributes checked at every output vertex: TEXCOORD_0" in n for n in check["notes"])
    w = len(v)  # the first midpoint
    r["attributes"]["TEXCOORD_0"][w] += 0.01
    bad = ss.verify(v, f, r, attributes=attrs, blend=blend)
    assert not bad["ok"]
    assert any(x.startswith(f"attributes: vertex {w} TEXCOORD_0 = (") and "expected" in x for x in bad["failures"]), bad["failures"]
