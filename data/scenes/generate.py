#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Rebuilds the test scenes of the paper's section 8 from B-spline surfaces.

    python3 data/scenes/generate.py [OUTDIR]

SCENE 1: a pan and a glass on a table in front of a mirror (9 objects, one light);
SCENE 2: 15 objects lit by two lights; SCENE 2a: SCENE 2 with one light off;
SCENE 3: a room with a candle on a glass plate (21 objects). Pan, glass,
candle, bowl, cup, plate and balls are surfaces of revolution: a profile of
rational quadratic pieces (lines, exact quarter circles) swept by the exact
nine-point rational quadratic circle, 4 Bezier patches per profile piece.
Table, mirror, walls and the glass plate are bilinear patches. Scenes go to
OUTDIR (default: this folder), models to OUTDIR/models. See docs/scenes.md.
"""
import json
import math
import os
import sys

S2 = math.sqrt(0.5)


def surface(name, degree, size, ku, kv, points, weights=None):
    s = {"name": name, "degree": list(degree), "size": list(size),
         "knots_u": ku, "knots_v": kv,
         "control_points": [[round(float(x), 12) for x in p] for p in points]}
    if weights is not None:
        s["weights"] = [round(float(w), 15) for w in weights]
    assert len(ku) == size[0] + degree[0] + 1 and len(kv) == size[1] + degree[1] + 1
    assert len(points) == size[0] * size[1]
    return s


def add(p, q):
    return tuple(a + b for a, b in zip(p, q))


def quad(name, p00, p10, p01, p11):
    """Bilinear patch; its normal dP/du x dP/dv is (p10 - p00) x (p01 - p00)."""
    return surface(name, (1, 1), (2, 2), [0, 0, 1, 1], [0, 0, 1, 1], [p00, p01, p10, p11])


def box(name, lo, hi, faces="xXyYzZ"):
    """Axis-parallel box of bilinear patches with outward normals; `faces`
    selects -x (x), +x (X), -y (y), +y (Y), -z (z), +z (Z)."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    f = {
        "x": ((x0, y0, z0), (x0, y0, z1), (x0, y1, z0), (x0, y1, z1)),
        "X": ((x1, y0, z0), (x1, y1, z0), (x1, y0, z1), (x1, y1, z1)),
        "y": ((x0, y0, z0), (x1, y0, z0), (x0, y0, z1), (x1, y0, z1)),
        "Y": ((x0, y1, z0), (x0, y1, z1), (x1, y1, z0), (x1, y1, z1)),
        "z": ((x0, y0, z0), (x0, y1, z0), (x1, y0, z0), (x1, y1, z0)),
        "Z": ((x0, y0, z1), (x1, y0, z1), (x0, y1, z1), (x1, y1, z1)),
    }
    return [quad(name + "-" + k, *f[k]) for k in faces]


def line(a, b):
    """A straight profile piece as a rational quadratic (middle point halfway)."""
    return [(a, 1.0), (((a[0] + b[0]) / 2, (a[1] + b[1]) / 2), 1.0), (b, 1.0)]


def arc(a, corner, b):
    """Exact quarter circle from a to b whose tangents meet at `corner`."""
    return [(a, 1.0), (corner, S2), (b, 1.0)]


def revolve(name, pieces, centre=(0.0, 0.0, 0.0)):
    """Surface of revolution about the vertical axis through `centre` of a
    profile in (r, z) made of rational quadratic pieces, joined C0 (double
    interior knots). The normal dP/du x dP/dv points to the right of the
    profile's direction: trace a solid's profile with the solid on the left
    and the normals point out of it."""
    prof = [pieces[0][0]]
    for p in pieces:
        assert p[0][0] == prof[-1][0], "profile pieces must join"
        prof += p[1:]
    n = len(pieces)
    kv = [0.0] * 3 + [k / n for k in range(1, n) for _ in range(2)] + [1.0] * 3
    circ = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)]
    cw = [1, S2, 1, S2, 1, S2, 1, S2, 1]
    ku = [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1]
    pts, ws = [], []
    for (cu, su), wu in zip(circ, cw):
        for (r, z), wv in prof:
            pts.append((centre[0] + cu * r, centre[1] + su * r, centre[2] + z))
            ws.append(wu * wv)
    return surface(name, (2, 2), (9, len(prof)), ku, kv, pts, ws)


# --- the objects ----------------------------------------------------------------

TABLE_Z = 0.75


def table(x0=-1.2, x1=1.2, y0=-0.7, y1=0.7):
    top = box("table-top", (x0, y0, TABLE_Z - 0.05), (x1, y1, TABLE_Z))
    legs = []
    for k, (x, y) in enumerate([(x0 + 0.1, y0 + 0.1), (x1 - 0.1, y0 + 0.1),
                                (x0 + 0.1, y1 - 0.1), (x1 - 0.1, y1 - 0.1)]):
        legs += box("leg%d" % k, (x - 0.03, y - 0.03, 0.0), (x + 0.03, y + 0.03, TABLE_Z - 0.05),
                    "xXyY")
    return top, legs


def pan(c):
    # Open shell: flat bottom, a rounded corner (exact quarter circle), wall.
    r, k, h = 0.3, 0.05, 0.12
    return [revolve("pan", [line((0.0, 0.0), (r - k, 0.0)),
                            arc((r - k, 0.0), (r, 0.0), (r, k)),
                            line((r, k), (r, h))], c)]


def pan_handle(c):
    x = c[0] - 0.3
    return box("pan-handle", (x - 0.32, c[1] - 0.025, c[2] + 0.08), (x + 0.01, c[1] + 0.025, c[2] + 0.1))


def glass(c):
    # Closed profile with the glass on the left: the normals point out of the
    # glass everywhere, so refraction knows entering from leaving.
    ro, ri, rt, rit, h, b = 0.11, 0.10, 0.13, 0.12, 0.3, 0.02
    return [revolve("glass", [line((0.0, 0.0), (ro, 0.0)), line((ro, 0.0), (rt, h)),
                              line((rt, h), (rit, h)), line((rit, h), (ri, b)),
                              line((ri, b), (0.0, b))], c)]


def bowl(c):
    return [revolve("bowl", [line((0.0, 0.0), (0.08, 0.0)),
                             arc((0.08, 0.0), (0.2, 0.0), (0.2, 0.12))], c)]


def cup(c):
    return [revolve("cup", [line((0.0, 0.0), (0.06, 0.0)), line((0.06, 0.0), (0.075, 0.14))], c)]


def plate(c):
    return [revolve("plate", [line((0.0, 0.0), (0.12, 0.0)), line((0.12, 0.0), (0.19, 0.025))], c)]


def ball(c, r):
    # Two exact quarter circles from the south pole to the north pole.
    return [revolve("ball", [arc((0.0, -r), (r, -r), (r, 0.0)), arc((r, 0.0), (r, r), (0.0, r))],
                    (c[0], c[1], c[2] + r))]


def candle(c):
    r, h = 0.05, 0.3
    return [revolve("candle", [line((r, 0.0), (r, h)), line((r, h), (0.0, h))], c)]


def wick(c):
    r, z0, z1 = 0.005, 0.3, 0.33
    return [revolve("wick", [line((r, z0), (r, z1)), line((r, z1), (0.0, z1))], c)]


def flame(c):
    # A drop: a quarter circle from the bottom pole to the equator, then a
    # straight cone to the tip.
    r, z0 = 0.02, 0.34
    return [revolve("flame", [arc((0.0, z0), (r, z0), (r, z0 + r)),
                              line((r, z0 + r), (0.0, z0 + 0.09))], c)]


def mirror(y, x0, x1, z0, z1):
    glass_ = [quad("mirror", (x0, y, z0), (x1, y, z0), (x0, y, z1), (x1, y, z1))]
    # The frame lies just in front and overlaps the glass by `o`, so no ray
    # slips between them onto the wall behind.
    t, o, yf = 0.08, 0.01, y - 0.005
    a0, a1, b0, b1 = x0 + o, x1 - o, z0 + o, z1 - o
    frame = [quad("frame-bottom", (x0 - t, yf, z0 - t), (x1 + t, yf, z0 - t), (x0 - t, yf, b0), (x1 + t, yf, b0)),
             quad("frame-top", (x0 - t, yf, b1), (x1 + t, yf, b1), (x0 - t, yf, z1 + t), (x1 + t, yf, z1 + t)),
             quad("frame-left", (x0 - t, yf, b0), (a0, yf, b0), (x0 - t, yf, b1), (a0, yf, b1)),
             quad("frame-right", (a1, yf, b0), (x1 + t, yf, b0), (a1, yf, b1), (x1 + t, yf, b1))]
    return glass_, frame


def wall_y(name, y, x0, x1, z0, z1):
    return [quad(name, (x0, y, z0), (x0, y, z1), (x1, y, z0), (x1, y, z1))]


def floor(name, z, x0, x1, y0, y1):
    return [quad(name, (x0, y0, z), (x1, y0, z), (x0, y1, z), (x1, y1, z))]


# --- materials ------------------------------------------------------------------

MATERIALS = {
    "floor": {"color": [0.55, 0.45, 0.35], "diffuse": 0.8, "specular": 0.1, "shininess": 10},
    "wall": {"color": [0.75, 0.75, 0.7], "diffuse": 0.8, "specular": 0.0, "shininess": 1},
    "wood": {"color": [0.6, 0.38, 0.2], "diffuse": 0.75, "specular": 0.25, "shininess": 20},
    "metal": {"color": [0.35, 0.35, 0.4], "diffuse": 0.5, "specular": 0.7, "shininess": 60,
              "reflect": 0.25},
    "black": {"color": [0.1, 0.1, 0.1], "diffuse": 0.6, "specular": 0.3, "shininess": 30},
    "glass": {"color": [0.85, 0.9, 0.95], "diffuse": 0.05, "specular": 0.8, "shininess": 100,
              "reflect": 0.1, "transmit": 0.8, "ior": 1.5},
    "mirror": {"color": [0.8, 0.8, 0.8], "diffuse": 0.1, "specular": 0.5, "shininess": 200,
               "reflect": 0.8},
    "frame": {"color": [0.7, 0.55, 0.2], "diffuse": 0.7, "specular": 0.4, "shininess": 40},
    "porcelain": {"color": [0.9, 0.88, 0.82], "diffuse": 0.75, "specular": 0.4, "shininess": 50},
    "red": {"color": [0.85, 0.15, 0.1], "diffuse": 0.75, "specular": 0.5, "shininess": 60},
    "blue": {"color": [0.15, 0.3, 0.85], "diffuse": 0.75, "specular": 0.5, "shininess": 60},
    "wax": {"color": [0.95, 0.92, 0.8], "diffuse": 0.8, "specular": 0.2, "shininess": 20},
    "flame": {"color": [1.0, 0.8, 0.3], "diffuse": 1.0, "specular": 0.0, "shininess": 1},
    "picture": {"color": [0.3, 0.55, 0.35], "diffuse": 0.8, "specular": 0.1, "shininess": 10},
}


def translate(t):
    return [1, 0, 0, t[0], 0, 1, 0, t[1], 0, 0, 1, t[2], 0, 0, 0, 1]


def scene(camera_eye, look_at, lights, objects, ambient=0.15, background=(0.1, 0.12, 0.18)):
    used = sorted({o[1] for o in objects})
    objs = []
    for o in objects:
        d = {"model": "models/" + o[0] + ".json", "material": o[1]}
        if len(o) > 2:
            d["transform"] = translate(o[2])
        objs.append(d)
    return {
        "version": 1,
        "camera": {"eye": list(camera_eye), "look_at": list(look_at), "up": [0, 0, 1],
                   "fov_deg": 45, "width": 640, "height": 480},
        "levels": 16,
        "background": list(background),
        "ambient": ambient,
        "lights": [{"position": list(p), "color": list(c)} for p, c in lights],
        "materials": {k: MATERIALS[k] for k in used},
        "objects": objs,
        "max_depth": 2,
    }


def build(out):
    models = {}
    top, legs = table()
    models["table_top"] = top
    models["table_legs"] = legs
    pan_c = (-0.4, -0.05, TABLE_Z + 0.001)
    models["pan"] = pan(pan_c)
    models["pan_handle"] = pan_handle(pan_c)
    glass_c = (0.35, 0.05, TABLE_Z + 0.001)
    models["glass"] = glass(glass_c)
    m, f = mirror(1.18, -0.9, 0.9, 0.95, 1.85)
    models["mirror"], models["mirror_frame"] = m, f
    models["floor"] = floor("floor", 0.0, -3.0, 3.0, -4.0, 1.2)
    models["back_wall"] = wall_y("back-wall", 1.2, -3.0, 3.0, 0.0, 3.0)
    on_table = (0.0, 0.0, TABLE_Z + 0.001)
    models["bowl"] = bowl(add(on_table, (0.75, 0.35, 0.0)))
    models["cup"] = cup(add(on_table, (-0.85, 0.4, 0.0)))
    models["plate"] = plate(add(on_table, (0.0, -0.4, 0.0)))
    models["ball"] = ball((0.0, 0.0, 0.0), 0.1)
    # SCENE 3: a closed room, a candle on a glass plate on the table.
    R = (-2.5, 2.5, -3.0, 2.5, 2.6)  # x0 x1 y0 y1 height
    models["room_floor"] = floor("room-floor", 0.0, R[0], R[1], R[2], R[3])
    models["room_ceiling"] = [quad("room-ceiling", (R[0], R[2], R[4]), (R[0], R[3], R[4]),
                                   (R[1], R[2], R[4]), (R[1], R[3], R[4]))]
    models["room_back"] = wall_y("room-back", R[3], R[0], R[1], 0.0, R[4])
    models["room_front"] = [quad("room-front", (R[0], R[2], 0.0), (R[1], R[2], 0.0),
                                 (R[0], R[2], R[4]), (R[1], R[2], R[4]))]
    models["room_left"] = [quad("room-left", (R[0], R[2], 0.0), (R[0], R[2], R[4]),
                                (R[0], R[3], 0.0), (R[0], R[3], R[4]))]
    models["room_right"] = [quad("room-right", (R[1], R[2], 0.0), (R[1], R[3], 0.0),
                                 (R[1], R[2], R[4]), (R[1], R[3], R[4]))]
    models["glass_plate"] = box("glass-plate", (-0.35, -0.3, TABLE_Z + 0.001),
                                (0.35, 0.3, TABLE_Z + 0.021))
    candle_c = (0.0, 0.0, TABLE_Z + 0.022)
    models["candle"] = candle(candle_c)
    models["wick"] = wick(candle_c)
    models["flame"] = flame(candle_c)
    pm, pf = mirror(R[3] - 0.01, -2.2, -0.8, 1.0, 2.0)
    models["picture"], models["picture_frame"] = [dict(pm[0], name="picture")], pf
    rm, rf = mirror(R[3] - 0.01, 0.6, 1.9, 0.9, 2.1)
    models["room_mirror"], models["room_mirror_frame"] = rm, rf
    models["shelf"] = box("shelf", (1.7, 1.9, 0.0), (2.4, 2.4, 1.1), "xyZ")

    os.makedirs(os.path.join(out, "models"), exist_ok=True)
    for name, surfs in models.items():
        with open(os.path.join(out, "models", name + ".json"), "w") as fh:
            json.dump({"version": 1, "surfaces": surfs}, fh, indent=1)
            fh.write("\n")

    cam1 = ((0.9, -3.4, 1.75), (0.0, 0.3, 1.0))
    light1 = ((-1.5, -2.0, 3.0), (1.0, 1.0, 1.0))
    scene1 = [("floor", "floor"), ("back_wall", "wall"), ("mirror", "mirror"),
              ("mirror_frame", "frame"), ("table_top", "wood"), ("table_legs", "wood"),
              ("pan", "metal"), ("pan_handle", "black"), ("glass", "glass")]
    scene2 = scene1 + [("glass", "glass", (-0.6, 0.35, 0.0)), ("bowl", "porcelain"),
                       ("cup", "porcelain"), ("plate", "porcelain"),
                       ("ball", "red", (0.05, -0.4, TABLE_Z + 0.002)),
                       ("ball", "blue", (0.8, -0.35, TABLE_Z + 0.001))]
    light2a = ((2.0, -2.5, 2.5), (0.6, 0.55, 0.5))
    light2b = ((-2.0, -1.0, 2.8), (0.5, 0.5, 0.6))
    scene3 = [("room_floor", "floor"), ("room_ceiling", "wall"), ("room_back", "wall"),
              ("room_front", "wall"), ("room_left", "wall"), ("room_right", "wall"),
              ("table_top", "wood"), ("table_legs", "wood"), ("glass_plate", "glass"),
              ("candle", "wax"), ("wick", "black"), ("flame", "flame"),
              ("picture", "picture"), ("picture_frame", "frame"), ("room_mirror", "mirror"),
              ("room_mirror_frame", "frame"), ("bowl", "porcelain"), ("cup", "porcelain"),
              ("ball", "red", (0.6, -0.3, TABLE_Z + 0.001)), ("ball", "blue", (-1.2, -1.0, 0.0)),
              ("shelf", "wood")]
    flame_top = (candle_c[0], candle_c[1], candle_c[2] + 0.47)
    scenes = {
        "scene1.json": scene(cam1[0], cam1[1], [light1], scene1),
        "scene2.json": scene(cam1[0], cam1[1], [light2a, light2b], scene2),
        "scene2a.json": scene(cam1[0], cam1[1], [light2a, (light2b[0], (0.0, 0.0, 0.0))], scene2),
        "scene3.json": scene((1.2, -2.7, 1.7), (0.0, 0.3, 0.9),
                             [(flame_top, (1.0, 0.9, 0.7)), ((0.0, -1.0, 2.5), (0.35, 0.35, 0.4))],
                             scene3, ambient=0.12, background=(0.0, 0.0, 0.0)),
    }
    for name, s in scenes.items():
        with open(os.path.join(out, name), "w") as fh:
            json.dump(s, fh, indent=1)
            fh.write("\n")
        print("wrote", os.path.join(out, name), len(s["objects"]), "objects")


if __name__ == "__main__":
    build(sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__)))
