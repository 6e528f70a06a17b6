#!/usr/bin/env python3
"""Writes bench_mesh.cpp's torus100k (224 x 224 rings and sides, 100,352 triangles, major radius 3, minor 1,
every vertex its own position, normal and uv) as a Wavefront OBJ, so that `ctess mesh` can be timed on the
mesh the library benchmark times:

    python3 bench/torus_obj.py torus100k.obj
    build/release/tools/ctess/ctess mesh --in torus100k.obj --factor 8 --out out.ply --stats --threads 1
"""
import math
import sys

RINGS = SIDES = 224
MAJOR, MINOR = 3.0, 1.0


def main(path):
    lines = []
    for r in range(RINGS):
        a = 2 * math.pi * r / RINGS
        for s in range(SIDES):
            b = 2 * math.pi * s / SIDES
            nx, ny, nz = math.cos(a) * math.cos(b), math.sin(a) * math.cos(b), math.sin(b)
            lines.append(f"v {MAJOR * math.cos(a) + MINOR * nx:.9g} {MAJOR * math.sin(a) + MINOR * ny:.9g} "
                         f"{MINOR * nz:.9g}")
    for r in range(RINGS):
        a = 2 * math.pi * r / RINGS
        for s in range(SIDES):
            b = 2 * math.pi * s / SIDES
            lines.append(f"vn {math.cos(a) * math.cos(b):.9g} {math.sin(a) * math.cos(b):.9g} {math.sin(b):.9g}")
    for r in range(RINGS):
        for s in range(SIDES):
            lines.append(f"vt {r / RINGS:.9g} {s / SIDES:.9g}")

    def at(r, s):
        return (r % RINGS) * SIDES + s % SIDES + 1

    for r in range(RINGS):
        for s in range(SIDES):
            a, b, c, d = at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s + 1)
            lines.append(f"f {a}/{a}/{a} {b}/{b}/{b} {c}/{c}/{c}")
            lines.append(f"f {a}/{a}/{a} {c}/{c}/{c} {d}/{d}/{d}")
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: torus_obj.py OUT.obj")
    main(sys.argv[1])
