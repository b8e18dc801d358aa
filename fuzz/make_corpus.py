#!/usr/bin/env python3
"""fuzz/make_corpus.py — writes the committed seed corpus fuzz/corpus/ for mink_mdd_fuzz.

Each seed is a hand-made scene encoded in the byte layout that mdd_fuzz.cpp's Decoder
reads (the order below mirrors LLVMFuzzerTestOneInput), so the fuzzer starts from the
cases that matter: exact face-face / edge-edge / vertex-vertex contacts and grazing
lines on integer boxes, penetration, NoContact, 90-degree rotations, reflections and
non-orthonormal poses, fromMesh on hull faces and on a byte-given mesh, NaN / Inf /
huge / tiny coordinates, too few points, duplicates, capped searches. Deterministic:
`python3 fuzz/make_corpus.py` rewrites the same files. Seeds are a few dozen bytes.
"""
import os
import random
import struct

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")

# --- primitives (Decoder::u8 / i8 / i16 / f64) ---
def u8(v): return bytes([v & 0xFF])
def i8(v): return struct.pack("<b", v)
def i16(v): return struct.pack("<h", v)
def f64(v): return struct.pack("<d", v)

SPECIAL = {0.0: 0, 1.0: 1, -1.0: 2, 0.5: 3, 3.0: 4, 1e-9: 5, "1+eps": 6, "denorm": 7, "dblmin": 8, 1e-300: 9,
           1e300: 10, -1e300: 11, "max": 12, "nan": 13, "inf": 14, "-inf": 15}

def coord(style, v):
    """One coordinate in `style` (mdd_fuzz.cpp: coordinate())."""
    if style == 0: return u8(v + 2)                        # v in -2..2
    if style == 1: return i8(v)                            # v in -128..127
    if style == 2: return i16(v)                           # v * 2^scaleExp
    if style == 3: return f64(v)                           # raw double
    if style == 4:                                         # v: grid int or a SPECIAL key
        if isinstance(v, int) and -2 <= v <= 2 and not isinstance(v, bool): return u8(0) + u8(v + 2)
        return u8(1) + u8(SPECIAL[v])
    if style == 5:                                         # grid + v[1] * 2^-40
        v = v if isinstance(v, tuple) else (v, 0)
        return u8(v[0] + 2) + i8(v[1])
    raise ValueError(style)

def point_set(style, pts, scale_exp=0):
    """pointSet(): n, style, scaleExp, multiplier, then per point a dup byte + 3 coords.
    A point ("dup", k) is a dup byte 8*k: a copy of an earlier point (of pts[8k mod i])."""
    n = len(pts)
    nb = n - 4 if n >= 4 else 250 + n
    b = u8(nb) + u8(style) + i8(scale_exp) + u8(1)
    for i, p in enumerate(pts):
        if isinstance(p, tuple) and p and p[0] == "dup":
            b += u8(8 * p[1])  # dup % 8 == 0 -> copy pts[(8*src) % size]
            continue
        b += u8(1)
        for c in p: b += coord(style, c)
    return b

def shape(mode=0, tol=None, faces=None, n=0):
    """buildShape(): mode (0,1 fromPoints; 2 fromMesh(hull loops); 3 fromMesh(hull fans);
    4 fromMesh(faces given here over the points)), tolerance byte [+ special]."""
    b = u8(mode) + (u8(0) + u8(SPECIAL[tol]) if tol is not None else u8(1))
    if mode == 4:
        b += u8(len(faces) - 1)
        for f in faces:
            b += u8(len(f) - 3)
            for v in f: b += u8(v) + u8(1)
    return b

def pose(kind=0, extra=b"", t=(0, 0, 0), tstyle=0, texp=0):
    """decodePose(): kind (0 identity, 1 signed permutation, 2 unit quaternion, 3 raw
    quaternion, 4 nine specials, 5 perturbed unit quaternion), kind bytes, translation."""
    b = u8(kind) + extra + u8(tstyle) + i8(texp)
    for c in t: b += coord(4 if tstyle == 3 else tstyle, c)
    return b

def direction(s, style=0, exp=0, head_on=False):
    b = u8(style) + i8(exp)
    for c in s: b += coord(style, c)
    return b + u8(0 if head_on else 1)

def options(custom=False, hierarchy=False, max_visits=None, touch=None):
    if not custom: return u8(1)
    flags = (8 if hierarchy else 0) | (16 if max_visits is not None else 0) | (32 if touch is not None else 0)
    b = u8(flags)
    if max_visits is not None: b += u8(max_visits)
    if touch is not None: b += u8(SPECIAL[touch])
    return b

BOX = [(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
TET = [(0, 0, 0), (2, 0, 0), (0, 2, 0), (0, 0, 2)]
OCT = [(2, 0, 0), (-2, 0, 0), (0, 2, 0), (0, -2, 0), (0, 0, 2), (0, 0, -2)]
SAME = u8(0)      # Q = P
OTHER = u8(1)     # Q decoded next

def boxes(t, s, tstyle=0, head_on=False, opts=None):
    return (point_set(0, BOX) + SAME + shape() + shape() + pose() + pose(t=t, tstyle=tstyle) +
            direction(s, head_on=head_on) + (opts or options()))

def perm_code(perm_index, signs):  # kind-1 byte: code % 6 = permutation, code / 6 = sign bits
    return u8(perm_index + 6 * signs)

def seeds():
    rng = random.Random(20261122)
    out = {}
    out["box_face_face_touch"] = boxes((2, 0, 0), (-1, 0, 0))
    out["box_edge_edge_touch"] = boxes((2, 2, 0), (-1, -1, 0))
    out["box_vertex_vertex_touch"] = boxes((2, 2, 2), (-1, -1, -1))
    out["box_penetrating"] = boxes((1, 0, 0), (1, 0, 0))
    out["box_coincident"] = boxes((0, 0, 0), (0, 1, 0))
    out["box_grazing_face"] = boxes((2, 0, 0), (0, 1, 0))
    out["box_grazing_edge"] = boxes((2, 2, 0), (0, 0, 1))
    out["box_no_contact"] = boxes((5, 5, 0), (0, 0, 1), tstyle=1)
    out["box_head_on"] = boxes((2, 1, 1), (0, 0, 0), head_on=True)
    out["box_zero_direction"] = boxes((2, 0, 0), (0, 0, 0))
    out["box_cap_zero"] = boxes((2, 1, 0), (-1, 0, 0), opts=options(custom=True, max_visits=0))
    out["box_touch_tolerance_nan"] = boxes((2, 1, 0), (-1, 0, 0), opts=options(custom=True, touch="nan"))
    out["box_touch_tolerance_inf"] = boxes((1, 1, 0), (-1, 0, 0), opts=options(custom=True, touch="inf"))
    out["tet_oct_rot90"] = (point_set(0, TET) + OTHER + point_set(0, OCT) + shape() + shape() + pose() +
                            pose(kind=1, extra=perm_code(3, 0), t=(2, 2, 2)) + direction((-1, -1, -1)) + options())
    out["tet_oct_reflection"] = (point_set(0, TET) + OTHER + point_set(0, OCT) + shape() + shape() + pose() +
                                 pose(kind=1, extra=perm_code(1, 0), t=(2, 2, 2)) + direction((-1, 0, 0)) + options())
    out["box_unnormalised_quaternion"] = (point_set(0, BOX) + SAME + shape() + shape() + pose() +
                                          pose(kind=3, extra=i8(2) + i8(1) + i8(0) + i8(0), t=(2, 0, 0)) +
                                          direction((-1, 0, 0)) + options())
    out["box_quaternion_rotation"] = (point_set(0, BOX) + SAME + shape() + shape() +
                                      pose(kind=2, extra=i8(7) + i8(3) + i8(-2) + i8(5)) +
                                      pose(kind=2, extra=i8(1) + i8(1) + i8(1) + i8(1), t=(2, 2, 0)) +
                                      direction((-1, -1, 0)) + options())
    out["box_rotation_near_threshold"] = (point_set(0, BOX) + SAME + shape() + shape() + pose() +
                                          pose(kind=5, extra=i8(9) + i8(4) + i8(1) + i8(0) + u8(1) + u8(10), t=(2, 0, 0)) +
                                          direction((-1, 0, 0)) + options())
    out["box_raw_rotation"] = (point_set(0, BOX) + SAME + shape() + shape() + pose() +
                               pose(kind=4, extra=bytes([1, 0, 0, 0, 1, 0, 0, 0, 13])) + direction((-1, 0, 0)) + options())
    out["hull_loops_and_fans"] = (point_set(0, BOX) + OTHER + point_set(0, OCT) + shape(mode=2) + shape(mode=3) +
                                  pose() + pose(t=(2, 1, 0)) + direction((-1, 0, 0)) + options())
    out["raw_mesh_tetrahedron"] = (point_set(0, TET) + SAME +
                                   shape(mode=4, faces=[[0, 2, 1], [0, 1, 3], [1, 2, 3], [2, 0, 3]]) + shape() +
                                   pose() + pose(t=(2, 2, 0)) + direction((-1, -1, 0)) + options())
    out["raw_mesh_open"] = (point_set(0, TET) + SAME + shape(mode=4, faces=[[0, 2, 1], [0, 1, 3], [1, 2, 3]]) +
                            shape() + pose() + pose() + direction((1, 0, 0)) + options())
    out["nan_and_inf_points"] = (point_set(4, [(0, 0, 0), (1, 0, 0), (0, "nan", 0), (0, 0, 1), ("inf", 1, 1)]) + SAME +
                                 shape() + shape() + pose() + pose() + direction((1, 0, 0)) + options())
    out["huge_and_tiny_points"] = (point_set(4, [(0, 0, 0), (1e300, 0, 0), (0, 1e-300, 0), (0, 0, "max"), (1, 1, "denorm")]) +
                                   SAME + shape() + shape() + pose() + pose(t=(2, 0, 0)) + direction((-1, 0, 0)) + options())
    out["too_few_points"] = (point_set(0, [(0, 0, 0), (1, 0, 0), (0, 1, 0)]) + SAME + shape() + shape() + pose() + pose() +
                             direction((1, 0, 0)) + options())
    out["duplicates_and_coplanar"] = (point_set(0, [(0, 0, 0), (1, 0, 0), ("dup", 0), (0, 1, 0), ("dup", 1), (1, 1, 0),
                                                    (0, 0, 1), ("dup", 2)]) + SAME + shape() + shape() + pose() +
                                      pose(t=(1, 0, 0)) + direction((-1, 0, 0)) + options())
    out["near_coplanar_grid"] = (point_set(5, [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0), ((0, 3), (0, -5), (1, 1))]) +
                                 SAME + shape(tol=0.0) + shape() + pose() + pose(t=(0, 0, 1)) + direction((0, 0, -1)) + options())
    def rand_set(style, n, lo, hi):
        return [tuple(rng.randint(lo, hi) for _ in range(3)) for _ in range(n)]
    out["random_int8_40"] = (point_set(1, rand_set(1, 40, -60, 60)) + OTHER + point_set(1, rand_set(1, 40, -60, 60)) +
                             shape() + shape() + pose(kind=2, extra=i8(3) + i8(-1) + i8(4) + i8(1)) +
                             pose(t=(30, -20, 10), tstyle=1) + direction((-3, 2, -1), style=1) + options())
    out["scaled_int16_small"] = (point_set(2, rand_set(2, 12, -3000, 3000), scale_exp=-30) + OTHER +
                                 point_set(2, rand_set(2, 12, -3000, 3000), scale_exp=-30) + shape() + shape() + pose() +
                                 pose(t=(1000, 0, 0), tstyle=2, texp=-30) + direction((-1, 0, 0), style=2, exp=-30) + options())
    out["scaled_int16_large"] = (point_set(2, rand_set(2, 12, -3000, 3000), scale_exp=40) + SAME + shape() + shape() +
                                 pose(kind=1, extra=perm_code(4, 3)) + pose(t=(6000, 10, 0), tstyle=2, texp=40) +
                                 direction((-1, 0, 0), style=2, exp=90) + options())
    out["raw_doubles"] = (point_set(3, [tuple(rng.uniform(-3, 3) for _ in range(3)) for _ in range(10)]) + OTHER +
                          point_set(3, [tuple(rng.uniform(-3, 3) for _ in range(3)) for _ in range(10)]) + shape() + shape() +
                          pose(kind=2, extra=i8(5) + i8(5) + i8(-1) + i8(2)) + pose(t=(3, 0, 0), tstyle=3) +
                          direction((-1.0, 0.25, 0.125), style=3) + options())
    return out

def main():
    os.makedirs(OUT, exist_ok=True)
    for f in os.listdir(OUT):
        os.remove(os.path.join(OUT, f))
    for name, data in sorted(seeds().items()):
        with open(os.path.join(OUT, name), "wb") as fh:
            fh.write(data)
    print(f"wrote {len(seeds())} seeds to {OUT}")

if __name__ == "__main__":
    main()
