#!/usr/bin/env python3
"""Regenerates the small sample meshes in this directory (valid and deliberately broken ones).
Run from anywhere: python3 tests/data/make_data.py"""
import os, struct

D = os.path.dirname(os.path.abspath(__file__))

def w(name, text, mode="w"):
    with open(os.path.join(D, name), mode) as f:
        f.write(text)

# Tetrahedron, outward oriented.
TV = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TF = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]

def off(vs, fs, extra=""):
    s = "OFF\n%d %d 0\n" % (len(vs), len(fs)) + extra
    s += "".join("%r %r %r\n" % tuple(map(float, v)) for v in vs)
    s += "".join("%d %s\n" % (len(f), " ".join(map(str, f))) for f in fs)
    return s

def obj(vs, fs):
    return "".join("v %r %r %r\n" % tuple(map(float, v)) for v in vs) + \
        "".join("f %s\n" % " ".join(str(i + 1) for i in f) for f in fs)

def ply_ascii(vs, fs):
    s = "ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n" % len(vs)
    s += "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % len(fs)
    s += "".join("%r %r %r\n" % tuple(map(float, v)) for v in vs)
    s += "".join("%d %s\n" % (len(f), " ".join(map(str, f))) for f in fs)
    return s

def ply_binary(vs, fs, truncate=0, extra_face_prop=True):
    h = "ply\nformat binary_little_endian 1.0\ncomment tetra\nelement vertex %d\n" % len(vs)
    h += "property double x\nproperty double y\nproperty double z\nproperty uchar red\n"
    h += "element face %d\nproperty list uchar uint vertex_indices\n" % len(fs)
    if extra_face_prop:
        h += "property uint parent\n"
    h += "end_header\n"
    b = h.encode()
    for v in vs:
        b += struct.pack("<dddB", *map(float, v), 200)
    for i, f in enumerate(fs):
        b += struct.pack("<B", len(f)) + struct.pack("<%dI" % len(f), *f)
        if extra_face_prop:
            b += struct.pack("<I", 1000 + i)
    return b[:len(b) - truncate] if truncate else b

def normal(a, b, c):
    u = [b[i] - a[i] for i in range(3)]; v = [c[i] - a[i] for i in range(3)]
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])

def stl_ascii(vs, fs):
    s = "solid tetra\n"
    for f in fs:
        s += "  facet normal %r %r %r\n    outer loop\n" % tuple(map(float, normal(*[vs[i] for i in f])))
        s += "".join("      vertex %r %r %r\n" % tuple(map(float, vs[i])) for i in f)
        s += "    endloop\n  endfacet\n"
    return s + "endsolid tetra\n"

def stl_binary(vs, fs, truncate=0):
    b = b"binary tetra".ljust(80, b" ") + struct.pack("<I", len(fs))
    for f in fs:
        b += struct.pack("<3f", *normal(*[vs[i] for i in f]))
        for i in f:
            b += struct.pack("<3f", *map(float, vs[i]))
        b += b"\0\0"
    return b[:len(b) - truncate] if truncate else b

# --- valid files -----------------------------------------------------------------------------
w("tetra.off", off(TV, TF))
w("tetra.obj", "# tetrahedron\no tetra\n" + obj(TV, TF))
w("tetra_ascii.ply", ply_ascii(TV, TF))
w("tetra_binary.ply", ply_binary(TV, TF), "wb")
w("tetra_ascii.stl", stl_ascii(TV, TF))
w("tetra_binary.stl", stl_binary(TV, TF), "wb")
# Square pyramid with a quad base (fan-triangulated into 2 triangles) and one unused vertex.
PV = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, 0.5, 1), (9, 9, 9)]
PF = [(0, 3, 2, 1), (0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)]
w("pyramid_quad.off", off(PV, PF))
# OBJ with texture/normal index syntax and negative (relative) indices; same pyramid.
w("pyramid_slashes.obj", "".join("v %r %r %r\n" % tuple(map(float, v)) for v in PV) +
  "vt 0 0\nvn 0 0 1\n"
  "f 1/1/1 4/1/1 3/1/1 2/1/1\n"
  "f 1//1 2//1 5//1\n"
  "f 2/1 3/1 5/1\n"
  "f -4 -3 -2\n"          # 6 vertices: -4 -> 2, -3 -> 3, -2 -> 4 (0-based)
  "f 4 1 5\n")
# Tetrahedron with one face flipped: orientable, inconsistently oriented (--orient fixes it).
w("tetra_one_flipped.off", off(TV, [TF[0], TF[1], (0, 2, 3), TF[3]]))

# --- broken files ----------------------------------------------------------------------------
w("empty.off", "")
w("blank.obj", "   \n\n  \n")
w("truncated_faces.off", off(TV, TF).rsplit("3 1 2 3\n", 1)[0])
w("truncated_vertices.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n")
w("index_out_of_range.off", off(TV, [TF[0], TF[1], (0, 3, 7), TF[3]]))
w("index_out_of_range.obj", obj(TV, [TF[0], TF[1], TF[2], (1, 2, 4)]))   # "f 2 3 5": vertex 4 of 4
w("nan.off", off(TV, TF).replace("0.0 1.0 0.0", "0.0 nan 0.0"))
w("inf.obj", obj(TV, TF).replace("v 0.0 0.0 1.0", "v 0.0 0.0 1e999"))
w("no_faces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n")
w("no_faces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n")
w("two_corner_face.off", off(TV, [TF[0], (1, 2), TF[2], TF[3]]))
w("garbage.ply", "this is not a ply file\n")
w("truncated_binary.ply", ply_binary(TV, TF, truncate=10), "wb")
w("truncated_binary.stl", stl_binary(TV, TF, truncate=30), "wb")
w("unknown.xyz", "0 0 0\n")
# Structural problems.
w("repeated_vertex.off", off(TV, TF + [(1, 1, 2)]))
w("duplicate_face.off", off(TV, TF + [TF[3]]))
w("non_manifold_edge.off", off([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1)],
                               [(0, 1, 2), (1, 0, 3), (0, 1, 4)]))
w("two_components.off", off(TV + [(v[0] + 5, v[1], v[2]) for v in TV] + [(9, 9, 9), (10, 9, 9), (9, 10, 9)],
                            TF + [tuple(i + 4 for i in f) for f in TF] + [(8, 9, 10)]))
# Moebius band: n=5 quads, vertices 0..4 bottom, 5..9 top; the last quad joins with a twist.
n = 5
import math
MV = []
for i in range(n):
    a = 2 * math.pi * i / n
    MV.append((math.cos(a), math.sin(a), -0.3))
for i in range(n):
    a = 2 * math.pi * i / n
    MV.append((math.cos(a), math.sin(a), 0.3))
MF = []
for i in range(n):
    a, b, c, d = i, (i + 1) % n, n + (i + 1) % n, n + i
    if i == n - 1:
        b, c = n + 0, 0      # twist: bottom of the last quad meets the top of the first
    MF += [(a, b, c), (a, c, d)]
w("moebius.off", off(MV, MF))
# Pinched tube: an open cylinder of 4 segments and 3 rings; vertex 0 of ring 0 is also used in
# place of vertex 3 of ring 2, so two separate fans of faces meet there (edge-connected).
segs = 4
CV = [(math.cos(2 * math.pi * k / segs), math.sin(2 * math.pi * k / segs), float(r)) for r in range(3) for k in range(segs)]
vid = lambda r, k: r * segs + (k % segs)
CF = []
for r in range(2):
    for k in range(segs):
        a, b, c, d = vid(r, k), vid(r, k + 1), vid(r + 1, k + 1), vid(r + 1, k)
        CF += [(a, b, c), (a, c, d)]
pinch = vid(2, 3)
CF = [tuple(0 if v == pinch else v for v in f) for f in CF]
w("non_manifold_vertex.off", off(CV, CF))

# Constraint files for the tetrahedron.
w("constraints_ok.txt", "# a polyline over tetra vertices\n0 1 2   # two edges\n\n3 0\n")
w("constraints_bad_token.txt", "0 1\n2 x 3\n")
w("constraints_out_of_range.txt", "0 1\n# comment\n1 2 4\n")
