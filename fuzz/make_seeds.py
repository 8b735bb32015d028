#!/usr/bin/env python3
"""Writes initial seed inputs for the fuzz targets into OUTDIR/<target>/ from tests/data and the
small libcgal-demo meshes (including the deliberately broken ones), converting a few small OFF
meshes into every other format. scripts/fuzz --seed merges them into fuzz/corpus/ (-merge=1), so
only inputs that add coverage are kept in the repository.
Usage: make_seeds.py REPO OUTDIR [CGAL_MESH_DIR]"""
import os, struct, sys, glob, shutil

repo, out = sys.argv[1], sys.argv[2]
cgal = sys.argv[3] if len(sys.argv) > 3 else "/tmp/cgaldata/data/meshes"
targets = ["obj", "off", "ply_ascii", "ply_binary", "stl_ascii", "stl_binary", "constraints", "pipeline"]
for t in targets:
    os.makedirs(os.path.join(out, t), exist_ok=True)

def put(target, name, data):
    with open(os.path.join(out, target, name), "wb") as f:
        f.write(data)

def read_off(path):
    toks = []
    for line in open(path, errors="replace"):
        line = line.split("#")[0]
        toks += line.split()
    if not toks or "OFF" not in toks[0]:
        return None
    i = 1
    nv, nf = int(toks[i]), int(toks[i + 1]); i += 3
    pts = []
    for _ in range(nv):
        pts.append(tuple(float(x) for x in toks[i:i + 3])); i += 3
        if "C" in toks[0]: i += 4  # COFF: skip rgba (approximately)
    faces = []
    for _ in range(nf):
        k = int(toks[i]); faces.append([int(x) for x in toks[i + 1:i + 1 + k]]); i += 1 + k
    return pts, faces

def tris(faces):
    return [(f[0], f[j], f[j + 1]) for f in faces for j in range(1, len(f) - 1)]

def to_obj(pts, faces):
    s = "".join("v %g %g %g\n" % p for p in pts)
    return (s + "".join("f " + " ".join(str(i + 1) for i in f) + "\n" for f in faces)).encode()

def to_ply_ascii(pts, faces):
    h = "ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n" \
        "element face %d\nproperty list uchar int vertex_indices\nend_header\n" % (len(pts), len(faces))
    return (h + "".join("%g %g %g\n" % p for p in pts) + "".join("%d %s\n" % (len(f), " ".join(map(str, f))) for f in faces)).encode()

def to_ply_binary(pts, faces, big=False, dbl=False):
    e = ">" if big else "<"
    h = ("ply\nformat binary_%s_endian 1.0\nelement vertex %d\nproperty %s x\nproperty %s y\nproperty %s z\n"
         "element face %d\nproperty list uchar int vertex_indices\nend_header\n") % (
        "big" if big else "little", len(pts), *(["double" if dbl else "float"] * 3), len(faces))
    b = h.encode()
    for p in pts:
        b += struct.pack(e + ("ddd" if dbl else "fff"), *p)
    for f in faces:
        b += struct.pack(e + "B" + "i" * len(f), len(f), *f)
    return b

def to_stl_ascii(pts, faces):
    s = "solid seed\n"
    for t in tris(faces):
        s += " facet normal 0 0 0\n  outer loop\n" + "".join("   vertex %g %g %g\n" % pts[i] for i in t) + "  endloop\n endfacet\n"
    return (s + "endsolid seed\n").encode()

def to_stl_binary(pts, faces):
    ts = tris(faces)
    b = b"seed".ljust(80, b"\0") + struct.pack("<I", len(ts))
    for t in ts:
        b += struct.pack("<fff", 0, 0, 0) + b"".join(struct.pack("<fff", *pts[i]) for i in t) + b"\0\0"
    return b

# Test data, by format.
for p in sorted(glob.glob(os.path.join(repo, "tests/data/*"))):
    name = os.path.basename(p)
    data = open(p, "rb").read()
    ext = name.rsplit(".", 1)[-1].lower()
    if ext in ("obj", "off"):
        put(ext, name, data)
    elif ext == "ply":
        put("ply_binary" if b"format binary" in data[:512] else "ply_ascii", name, data)
    elif ext == "stl":
        put("stl_ascii" if data.lstrip().startswith(b"solid") else "stl_binary", name, data)
    elif name.startswith("constraints"):
        put("constraints", name, b"\x80\x00" + data)
        put("constraints", name + ".n", b"\x00\x04" + data)

# Small libcgal-demo meshes, as OFF and converted.
if os.path.isdir(cgal):
    for p in sorted(glob.glob(os.path.join(cgal, "*"))):
        if os.path.getsize(p) > 4000:
            continue
        name = os.path.basename(p)
        data = open(p, "rb").read()
        ext = name.rsplit(".", 1)[-1].lower()
        if ext == "off":
            put("off", name, data)
            try:
                m = read_off(p)
            except Exception:
                m = None
            if m and len(m[1]) <= 60:
                pts, faces = m
                base = name[:-4]
                put("obj", base + ".obj", to_obj(pts, faces))
                put("ply_ascii", base + ".ply", to_ply_ascii(pts, faces))
                put("ply_binary", base + ".le.ply", to_ply_binary(pts, faces))
                put("ply_binary", base + ".be.ply", to_ply_binary(pts, faces, big=True, dbl=True))
                put("stl_ascii", base + ".stl", to_stl_ascii(pts, faces))
                put("stl_binary", base + ".bin.stl", to_stl_binary(pts, faces))
        elif ext == "ply":
            put("ply_binary" if b"format binary" in data[:512] else "ply_ascii", name, data)
        elif ext == "stl":
            put("stl_ascii" if data.lstrip().startswith(b"solid") else "stl_binary", name, data)

# Constraint polylines against the 5x5 grid (first byte 0x80 = use the grid).
for i, text in enumerate(["0 1 2\n", "6 7 8 13\n# c\n0 5\n", "12 13 18 17 12\n", "\n\n", "24 23\n1 1\n"]):
    put("constraints", "grid%d.txt" % i, b"\x80\x00" + text.encode())
# Pipeline: a few byte strings (any bytes decode to some mesh).
for k in range(14):
    put("pipeline", "kind%02d" % k, bytes([k, 5, 5, 3, 1, 0, 7, 9, 2, 1, 0, 1, 1, 0, 2, 3, 4, 5, 6, 7] * 3))
