#!/usr/bin/env python3
"""Writes the rock-shape library cases/shapes/rock_{a,b,c}.stl used by rock feeds.

Each rock is an icosphere (subdivided twice, 320 faces) whose vertex radii are perturbed by a
few low-order random harmonics and squashed along its axes, giving angular, star-shaped,
closed meshes with outward normals (sphericity 0.87-0.94, like natural gravel). A scanned rock
can replace them: any closed STL works.

    python3 tools/make_rock_library.py [out_dir]
"""
import math
import sys
from pathlib import Path

import numpy as np


def icosphere(levels):
    t = (1 + 5 ** 0.5) / 2
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
         (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    verts = [np.array(p, float) / np.linalg.norm(p) for p in v]
    for _ in range(levels):
        cache, nf = {}, []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                m = verts[a] + verts[b]
                verts.append(m / np.linalg.norm(m))
                cache[key] = len(verts) - 1
            return cache[key]

        for a, b, c in f:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            nf += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        f = nf
    return np.array(verts), f


def rock(seed, axes):
    rng = np.random.default_rng(seed)
    v, f = icosphere(2)
    r = np.ones(len(v))
    for _ in range(6):  # low-order bumps and facets
        d = rng.normal(size=3)
        d /= np.linalg.norm(d)
        r += rng.uniform(0.04, 0.10) * np.maximum(v @ d, 0) ** rng.uniform(2, 6)
        r -= rng.uniform(0.03, 0.08) * np.maximum(v @ (-d), 0) ** 8
    v = v * r[:, None] * np.array(axes)
    return v, f


def write_stl(path, name, v, faces):
    with open(path, "w") as out:
        out.write(f"solid {name}\n")
        for a, b, c in faces:
            n = np.cross(v[b] - v[a], v[c] - v[a])
            n /= np.linalg.norm(n)
            out.write(f"  facet normal {n[0]:.6e} {n[1]:.6e} {n[2]:.6e}\n    outer loop\n")
            for p in (v[a], v[b], v[c]):
                out.write(f"      vertex {p[0]:.6e} {p[1]:.6e} {p[2]:.6e}\n")
            out.write("    endloop\n  endfacet\n")
        out.write(f"endsolid {name}\n")


def sphericity(v, faces):
    vol = sum(np.dot(v[a], np.cross(v[b], v[c])) for a, b, c in faces) / 6
    area = sum(np.linalg.norm(np.cross(v[b] - v[a], v[c] - v[a])) for a, b, c in faces) / 2
    return math.pi ** (1 / 3) * (6 * vol) ** (2 / 3) / area


if __name__ == "__main__":
    out = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).parent.parent / "cases/shapes")
    out.mkdir(parents=True, exist_ok=True)
    for name, seed, axes in [("rock_a", 11, (0.014, 0.009, 0.006)),
                             ("rock_b", 23, (0.013, 0.010, 0.005)),
                             ("rock_c", 37, (0.012, 0.011, 0.0065))]:
        v, f = rock(seed, axes)
        write_stl(out / f"{name}.stl", name, v, f)
        print(f"{name}: {len(f)} facets, sphericity {sphericity(v, f):.3f}")
