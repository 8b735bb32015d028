#!/usr/bin/env python3
"""Writes room.off (a 30 x 20 m floor with two obstacles cut out) and walls.txt (two walls
given as constraint polylines of vertex indices). Start: vertex 0 (south-west corner); end:
the north-east corner. Used by the README's worked example."""
import os

NX, NY = 30, 20
OBSTACLES = [(5, 10, 5, 10), (18, 24, 8, 14)]  # cells [x0, x1) x [y0, y1) removed


def vid(i, j):
    return j * (NX + 1) + i


def blocked(i, j):
    return any(x0 <= i < x1 and y0 <= j < y1 for x0, x1, y0, y1 in OBSTACLES)


here = os.path.dirname(os.path.abspath(__file__))
faces = []
for j in range(NY):
    for i in range(NX):
        if blocked(i, j):
            continue
        a, b, c, d = vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1)
        if (i + j) % 2 == 0:
            faces += [(a, b, c), (a, c, d)]
        else:
            faces += [(a, b, d), (b, c, d)]
with open(os.path.join(here, "room.off"), "w") as f:
    f.write("OFF\n# 30 x 20 m room, two obstacles; vertex (i, j) has index j*31 + i\n")
    f.write(f"{(NX + 1) * (NY + 1)} {len(faces)} 0\n")
    for j in range(NY + 1):
        for i in range(NX + 1):
            f.write(f"{i} {j} 0\n")
    for t in faces:
        f.write(f"3 {t[0]} {t[1]} {t[2]}\n")
with open(os.path.join(here, "walls.txt"), "w") as f:
    f.write("# wall from the north side down to y = 6 (a door below it), x = 14\n")
    f.write(" ".join(str(vid(14, j)) for j in range(NY, 5, -1)) + "\n")
    f.write("# wall from the east side to x = 24, y = 15\n")
    f.write(" ".join(str(vid(i, 15)) for i in range(NX, 23, -1)) + "\n")
print("start vertex", vid(0, 0), "end vertex", vid(NX, NY))
