#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Regenerates the small bundled models of data/models (version-1 model JSON).

    python3 data/models/generate.py [OUTDIR]

The Newell tea set (teapot, teacup, teaspoon) is copied from ../shared/models,
not generated. Every model here is described in data/models/README.md.
"""
import json
import math
import os
import sys


def surface(name, degree, size, ku, kv, points, weights=None):
    s = {"name": name, "degree": list(degree), "size": list(size),
         "knots_u": ku, "knots_v": kv, "control_points": [list(map(float, p)) for p in points]}
    if weights is not None:
        s["weights"] = [float(w) for w in weights]
    assert len(ku) == size[0] + degree[0] + 1 and len(kv) == size[1] + degree[1] + 1
    assert len(points) == size[0] * size[1]
    return s


def clamped(degree, n):
    """Clamped uniform knot vector on [0, 1] for n control points."""
    inner = n - degree - 1
    return [0.0] * (degree + 1) + [(k + 1) / (inner + 1) for k in range(inner)] + [1.0] * (degree + 1)


def quarter_cylinder():
    # Exact quarter cylinder of radius 1 and height 2: a rational quadratic arc
    # (weights 1, sqrt(2)/2, 1) in u swept linearly in v.
    arc = [(1, 0), (1, 1), (0, 1)]
    w = [1.0, math.sqrt(0.5), 1.0]
    pts, ws = [], []
    for i in range(3):
        for j in range(2):
            pts.append((arc[i][0], arc[i][1], 2.0 * j))
            ws.append(w[i])
    return [surface("quarter-cylinder", (2, 1), (3, 2), [0, 0, 0, 1, 1, 1], [0, 0, 1, 1], pts, ws)]


def repeated_knot():
    # Bicubic sheet with a double interior knot at u = 0.5 (C1 there) and a
    # triple one at v = 0.5 (C0: a crease).
    nu, nv = 6, 7
    ku = [0, 0, 0, 0, 0.5, 0.5, 1, 1, 1, 1]
    kv = [0, 0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1, 1]
    pts = []
    for i in range(nu):
        for j in range(nv):
            x, y = i / (nu - 1) * 2 - 1, j / (nv - 1) * 2 - 1
            z = 0.3 * math.sin(2.5 * x) * math.cos(1.5 * y) + (0.4 if j == 3 else 0.0)
            pts.append((x, y, z))
    return [surface("repeated-knot", (3, 3), (nu, nv), ku, kv, pts)]


def bilinear():
    # Degree 1 x 1 on a 3 x 3 net: four bilinear (hyperbolic paraboloid) pieces.
    pts = []
    for i in range(3):
        for j in range(3):
            pts.append((i - 1.0, j - 1.0, 0.5 * (i - 1) * (j - 1) + (0.25 if (i, j) == (1, 1) else 0.0)))
    return [surface("bilinear", (1, 1), (3, 3), [0, 0, 0.5, 1, 1], [0, 0, 0.5, 1, 1], pts)]


def periodic_torus(R=2.0, r=0.6, nu=8, nv=6):
    # Closed periodic bicubic torus: uniform unclamped knots, the first three
    # rows and columns of the net repeated at the end, so the surface closes
    # exactly (C2) at u = 3 and v = 3. The (u, v) normal points outward.
    p = 3
    # Control polygon radius chosen so the cubic B-spline circle has about the
    # wanted radius (uniform cubic: the curve passes at (2 + cos(2pi/n))/3 of it).
    def ring(n, rad):
        f = (2 + math.cos(2 * math.pi / n)) / 3
        return [(rad / f * math.cos(2 * math.pi * k / n), rad / f * math.sin(2 * math.pi * k / n)) for k in range(n)]
    big, small = ring(nu, R), ring(nv, r)
    pts = []
    for i in range(nu + p):
        cx, cy = big[i % nu]
        d = math.hypot(cx, cy)
        ex, ey = cx / d, cy / d
        for j in range(nv + p):
            a, b = small[j % nv]
            # v runs around the tube so that du x dv points away from the tube axis.
            pts.append((cx + a * ex, cy + a * ey, b))
    ku = [float(k) for k in range(nu + 2 * p + 1)]
    kv = [float(k) for k in range(nv + 2 * p + 1)]
    return [surface("torus", (3, 3), (nu + p, nv + p), ku, kv, pts)]


def cube_sphere():
    # Six bicubic patches on the faces of a cube, each control point the unit
    # vector of a cube-grid point. Control points on a shared cube edge are the
    # same cube point seen from both faces, so boundaries match bit for bit.
    grid = [-1.0, -1.0 / 3.0, 1.0 / 3.0, 1.0]
    faces = [  # (normal, a, b) with a x b = normal: the (u, v) normal points outward
        ((1, 0, 0), (0, 1, 0), (0, 0, 1)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
        ((0, 1, 0), (0, 0, 1), (1, 0, 0)), ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
        ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (0, 1, 0), (1, 0, 0))]
    names = ["+x", "-x", "+y", "-y", "+z", "-z"]
    out = []
    for (n, a, b), name in zip(faces, names):
        pts = []
        for i in range(4):
            for j in range(4):
                c = [n[k] + grid[i] * a[k] + grid[j] * b[k] for k in range(3)]
                # Snap to the exact grid values so both faces compute the same vector.
                c = [min(grid, key=lambda g: abs(g - x)) for x in c]
                l = math.sqrt(sum(x * x for x in c))
                pts.append(tuple(x / l for x in c))
        out.append(surface("sphere" + name, (3, 3), (4, 4), clamped(3, 4), clamped(3, 4), pts))
    return out


def rational_torus(R=2.0, r=0.5):
    # Exact torus: product of two nine-point rational quadratic circles,
    # knots with double interior knots at the quarter points, weights w_i * w_j.
    s2 = math.sqrt(0.5)
    circ = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)]
    cw = [1, s2, 1, s2, 1, s2, 1, s2, 1]
    knots = [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1]
    pts, ws = [], []
    for i in range(9):
        cu, su = circ[i]
        for j in range(9):
            cv, sv = circ[j]
            pts.append((cu * (R + r * cv), su * (R + r * cv), r * sv))
            ws.append(cw[i] * cw[j])
    return [surface("torus-exact", (2, 2), (9, 9), knots, knots, pts, ws)]


def extreme_weights():
    # Rational biquadratic patch with weights spanning six decades: a stiff case
    # for rational evaluation, enclosures and tessellation.
    pts, ws = [], []
    for i in range(3):
        for j in range(3):
            pts.append((i - 1.0, j - 1.0, 0.6 if (i, j) == (1, 1) else 0.0))
            ws.append(1e3 if (i, j) == (1, 1) else (1e-3 if (i + j) % 2 else 1.0))
    return [surface("extreme-weights", (2, 2), (3, 3), [0, 0, 0, 1, 1, 1], [0, 0, 0, 1, 1, 1], pts, ws)]


MODELS = {
    "quarter_cylinder.json": quarter_cylinder,
    "repeated_knot.json": repeated_knot,
    "bilinear.json": bilinear,
    "torus.json": periodic_torus,
    "sphere.json": cube_sphere,
    "torus_exact.json": rational_torus,
    "extreme_weights.json": extreme_weights,
}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    for name, make in MODELS.items():
        with open(os.path.join(out, name), "w") as f:
            json.dump({"version": 1, "surfaces": make()}, f, indent=1)
            f.write("\n")
        print("wrote", os.path.join(out, name))


if __name__ == "__main__":
    main()
