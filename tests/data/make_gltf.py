#!/usr/bin/env python3
"""Writes tests/data/scene.gltf and scene.glb: a small textured glTF scene for the glTF-input tests,
and quantized.glb (KHR_mesh_quantization: integer positions, normals and texture coordinates).
Mesh 0: a tube with a UV seam (NORMAL, TEXCOORD_0, normalised-ubyte COLOR_0, indexed) and a cube
with per-face UVs (24 vertices: every edge a seam); mesh 1 (skinned): a non-indexed grid (corners
repeated with equal attributes, JOINTS_0/WEIGHTS_0); mesh 2: a LINES primitive (kept as is). One material with
an embedded PNG texture, nodes with transforms. Run: python3 tests/data/make_gltf.py"""
import base64, json, math, os, struct, zlib

D = os.path.dirname(os.path.abspath(__file__))

def png(w, h, rgb):
    raw = b"".join(b"\0" + bytes(rgb[(y * w + x) % len(rgb)] for x in range(w)) for y in range(h))
    def chunk(t, d):
        c = t + d
        return struct.pack(">I", len(d)) + c + struct.pack(">I", zlib.crc32(c) & 0xffffffff)
    # greyscale 8-bit
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 0, 0, 0, 0)) + \
        chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")

buf = bytearray()
views, accessors = [], []

def add(data, fmt, count, typ, ctype, target=34962, normalized=False, minmax=None):
    while len(buf) % 4:
        buf.append(0)
    off = len(buf)
    buf.extend(struct.pack("<" + fmt * (len(data)), *data))
    views.append({"buffer": 0, "byteOffset": off, "byteLength": len(buf) - off, "target": target})
    a = {"bufferView": len(views) - 1, "componentType": ctype, "count": count, "type": typ}
    if normalized:
        a["normalized"] = True
    if minmax:
        a["min"], a["max"] = minmax
    accessors.append(a)
    return len(accessors) - 1

def vec3_minmax(p):
    f = [struct.unpack("<f", struct.pack("<f", x))[0] for x in p]
    xs, ys, zs = f[0::3], f[1::3], f[2::3]
    return [min(xs), min(ys), min(zs)], [max(xs), max(ys), max(zs)]

def flat(rows):
    return [c for r in rows for c in r]

# Tube: nu x nv grid, column nu duplicates column 0 (a UV seam).
nu, nv = 12, 5
P, N, T, C, I = [], [], [], [], []
for j in range(nv):
    for i in range(nu + 1):
        a = 2 * math.pi * i / nu
        P.append((math.cos(a), j * 0.5, math.sin(a)))
        N.append((math.cos(a), 0.0, math.sin(a)))
        T.append((i / nu, j / (nv - 1)))
        C.append((i * 20 % 256, j * 60 % 256, 128, 255))
for j in range(nv - 1):
    for i in range(nu):
        a, b, c, d = j * (nu + 1) + i, j * (nu + 1) + i + 1, (j + 1) * (nu + 1) + i, (j + 1) * (nu + 1) + i + 1
        I += [a, c, b, b, c, d]
tube = {"attributes": {"POSITION": add(flat(P), "f", len(P), "VEC3", 5126, minmax=vec3_minmax(flat(P))),
                       "NORMAL": add(flat(N), "f", len(N), "VEC3", 5126),
                       "TEXCOORD_0": add(flat(T), "f", len(T), "VEC2", 5126),
                       "COLOR_0": add(flat(C), "B", len(C), "VEC4", 5121, normalized=True)},
        "indices": add(I, "H", len(I), "SCALAR", 5123, target=34963), "material": 0, "mode": 4}

# Cube with 24 vertices (4 per face).
P, N, T, I = [], [], [], []
for axis in range(3):
    for s in (-1, 1):
        n = [0, 0, 0]; n[axis] = s
        u = [0, 0, 0]; u[(axis + 1) % 3] = 1
        v = [0, 0, 0]; v[(axis + 2) % 3] = 1
        base = len(P)
        for (x, y) in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            P.append(tuple(0.5 * (n[k] + x * u[k] + y * v[k]) for k in range(3)))
            N.append(tuple(float(c) for c in n))
            T.append(((x + 1) / 2, (y + 1) / 2))
        q = [base, base + 1, base + 2, base, base + 2, base + 3]
        if s < 0:
            q = [base, base + 2, base + 1, base, base + 3, base + 2]
        I += q
cube = {"attributes": {"POSITION": add(flat(P), "f", len(P), "VEC3", 5126, minmax=vec3_minmax(flat(P))),
                       "NORMAL": add(flat(N), "f", len(N), "VEC3", 5126),
                       "TEXCOORD_0": add(flat(T), "f", len(T), "VEC2", 5126)},
        "indices": add(I, "B", len(I), "SCALAR", 5121, target=34963), "material": 0, "mode": 4}

# Non-indexed 4x3 grid of quads: every corner repeated, equal attributes at shared corners.
P, T, J, W = [], [], [], []
for j in range(3):
    for i in range(4):
        quad = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j), (i + 1, j + 1), (i, j + 1)]
        for (x, y) in quad:
            P.append((x * 0.3, y * 0.3, 0.0))
            T.append((x / 4, y / 3))
            J.append((0, 1, 0, 0))
            W.append((0.75 - x / 8, 0.25 + x / 8, 0.0, 0.0))
grid = {"attributes": {"POSITION": add(flat(P), "f", len(P), "VEC3", 5126, minmax=vec3_minmax(flat(P))),
                       "TEXCOORD_0": add(flat(T), "f", len(T), "VEC2", 5126),
                       "JOINTS_0": add(flat(J), "B", len(J), "VEC4", 5121),
                       "WEIGHTS_0": add(flat(W), "f", len(W), "VEC4", 5126)}, "material": 0, "mode": 4}
LP = [0, 0, 0, 1, 1, 1]
lines = {"attributes": {"POSITION": add(LP, "f", 2, "VEC3", 5126, minmax=vec3_minmax(LP))}, "mode": 1}

image = png(4, 4, [0, 255, 128, 64])
gltf = {
    "asset": {"version": "2.0", "generator": "singlestrip tests/data/make_gltf.py"},
    "scene": 0,
    "scenes": [{"nodes": [0, 3, 4]}],
    "nodes": [{"children": [1, 2], "translation": [0, 0, 0]}, {"mesh": 0, "translation": [2, 0, 0]},
              {"mesh": 2, "scale": [1, 2, 1]}, {"skin": 0, "mesh": 1}, {"name": "bone0", "children": [5]},
              {"name": "bone1", "translation": [1, 0, 0]}],
    "skins": [{"joints": [4, 5]}],
    "meshes": [{"primitives": [tube, cube]}, {"primitives": [grid]}, {"primitives": [lines]}],
    "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
    "textures": [{"sampler": 0, "source": 0}],
    "samplers": [{"magFilter": 9729, "minFilter": 9729}],
    "images": [{"uri": "data:image/png;base64," + base64.b64encode(image).decode()}],
    "accessors": accessors,
    "bufferViews": views,
    "buffers": [{"byteLength": len(buf), "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(buf)).decode()}],
}
with open(os.path.join(D, "scene.gltf"), "w") as f:
    json.dump(gltf, f, indent=1)

def write_glb(name, gltf, buf):
    """A .glb: the JSON chunk padded with spaces, then the BIN chunk (buf, 4-byte aligned)."""
    js = json.dumps(gltf).encode()
    js += b" " * ((4 - len(js) % 4) % 4)
    glb = struct.pack("<III", 0x46546C67, 2, 12 + 8 + len(js) + 8 + len(buf)) + struct.pack("<II", len(js), 0x4E4F534A) + js + \
        struct.pack("<II", len(buf), 0x004E4942) + bytes(buf)
    with open(os.path.join(D, name), "wb") as f:
        f.write(glb)


# The same scene as .glb (buffer in the BIN chunk, image in a buffer view).
while len(buf) % 4:
    buf.append(0)
views.append({"buffer": 0, "byteOffset": len(buf), "byteLength": len(image)})
buf.extend(image)
while len(buf) % 4:
    buf.append(0)
gltf["images"] = [{"bufferView": len(views) - 1, "mimeType": "image/png"}]
gltf["buffers"] = [{"byteLength": len(buf)}]
write_glb("scene.glb", gltf, buf)

# A quantized grid (KHR_mesh_quantization): uint16 positions, normalised int8 normals, uint16
# texture coordinates; the node's scale dequantizes the positions.
buf = bytearray()
views, accessors = [], []
P, N, T, I = [], [], [], []
n = 6
for j in range(n + 1):
    for i in range(n + 1):
        P.append((i * 1000, j * 1000, (i * j) % 3 * 100))
        N.append((0, 0, 127))
        T.append((i * 65535 // n, j * 65535 // n))
for j in range(n):
    for i in range(n):
        a, b, c, d = j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i, (j + 1) * (n + 1) + i + 1
        I += [a, b, d, a, d, c]
pmin = [min(p[k] for p in P) for k in range(3)]
pmax = [max(p[k] for p in P) for k in range(3)]

def strided(data, fmt, count, typ, ctype, stride, **kw):
    """Elements padded to `stride` bytes: vertex attributes must be 4-byte aligned."""
    i = add(data, fmt, count, typ, ctype, **kw)
    views[-1]["byteStride"] = stride
    return i

quant = {"attributes": {"POSITION": strided(flat([p + (0,) for p in P]), "H", len(P), "VEC3", 5123, 8, minmax=(pmin, pmax)),
                        "NORMAL": strided(flat([q + (0,) for q in N]), "b", len(N), "VEC3", 5120, 4, normalized=True),
                        "TEXCOORD_0": add(flat(T), "H", len(T), "VEC2", 5123, normalized=True)},
         "indices": add(I, "H", len(I), "SCALAR", 5123, target=34963), "mode": 4}
while len(buf) % 4:
    buf.append(0)
gltf = {
    "asset": {"version": "2.0", "generator": "singlestrip tests/data/make_gltf.py"},
    "extensionsUsed": ["KHR_mesh_quantization"],
    "extensionsRequired": ["KHR_mesh_quantization"],
    "scene": 0,
    "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0, "scale": [0.001, 0.001, 0.001]}],
    "meshes": [{"primitives": [quant]}],
    "accessors": accessors,
    "bufferViews": views,
    "buffers": [{"byteLength": len(buf)}],
}
write_glb("quantized.glb", gltf, buf)
