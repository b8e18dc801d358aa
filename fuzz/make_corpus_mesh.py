#!/usr/bin/env python3
"""fuzz/make_corpus_mesh.py — writes the committed seed corpus fuzz/corpus_mesh/ for
mink_mesh_fuzz (fuzz/mesh_fuzz.cpp).

Each seed is a hand-made input in the byte layout that mesh_fuzz.cpp's Decoder reads (the
functions below mirror decodeMesh, decodePose, moved and checkUpdates, in that order), so
that the fuzzer starts from the cases issue 14 names: valid closed meshes (tetrahedron,
octahedron, box, tori, two components) against a box, an octahedron or each other under
identity, 90-degree, quaternion and nudged poses; hostile meshes (open, non-manifold,
inverted, one triangle flipped, folded, NaN / Inf / 1e300 / denormal coordinates, a
collapsed vertex, indices out of range or negative, an unused vertex, random soups); and
hostile queries (radius 0, negative, NaN, Inf, 1e300; a NaN or huge centre; reflections
and non-orthonormal poses). Balls are small (a quarter to one unit of A's scale): a ball
holding all of M makes one execution slow. Deterministic: `python3 fuzz/make_corpus_mesh.py`
rewrites the same files.
"""
import os
import struct

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus_mesh")

def u8(v): return bytes([v & 0xFF])
def i8(v): return struct.pack("<b", v)
def f64(v): return struct.pack("<d", v)

SPECIAL = {0.0: 0, 1.0: 1, -1.0: 2, 0.5: 3, 3.0: 4, 1e-9: 5, "1+eps": 6, "denorm": 7, "dblmin": 8, 1e-300: 9,
           1e300: 10, -1e300: 11, "max": 12, "nan": 13, "inf": 14, "-inf": 15}
KIND = {"random": 0, "tetrahedron": 2, "octahedron": 3, "box": 4, "torus": 5, "lattice torus": 6, "two": 7}

def exponent(e):
    """exponent(): i8 b, then a byte; 7 selects 8*b (up to 2^+-1016), otherwise b % 8 (C++ %)."""
    if -7 <= e <= 7: return i8(e) + u8(0)
    assert e % 8 == 0
    return i8(e // 8) + u8(7)

def coord(style, v):
    """coordinate() in style 0 (grid -2..2 times 2^e), 1 (int8 times 2^e), 3 (raw double) or
    4 (a SPECIAL key, or a grid int)."""
    if style == 0: return u8(v + 2)
    if style == 1: return i8(v)
    if style == 3: return f64(v)
    if style == 4:
        if isinstance(v, int) and -2 <= v <= 2: return u8(0) + u8(v + 2)
        return u8(1) + u8(SPECIAL[v])
    raise ValueError(style)

# Edits (decodeMesh): (vertex, op, ...): 'special' axis key, 'nudge' axis k, 'snap' w,
# 'half' w, 'raw' axis value, 'reflect' axis.
def edit(v, op, *args):
    if op == "special": return u8(v) + u8(0) + u8(0) + u8(args[0]) + u8(SPECIAL[args[1]])
    if op == "nudge": return u8(v) + u8(0) + u8(1) + u8(args[0]) + i8(args[1])
    if op == "snap": return u8(v) + u8(args[0]) + u8(2) + u8(0)
    if op == "half": return u8(v) + u8(args[0]) + u8(3) + u8(0)
    if op == "raw": return u8(v) + u8(0) + u8(4) + u8(args[0]) + f64(args[1])
    if op == "reflect": return u8(v) + u8(0) + u8(5) + u8(args[0])
    raise ValueError(op)

# Mutations (decodeMesh): (op, triangle, corner[, payload]).
MUT = {"flip": 0, "flip_all": 1, "drop": 2, "duplicate": 3, "fold": 4, "bad_index": 5, "corner": 6,
       "rotate": 7, "swap": 8, "unused_vertex": 9}
def mutation(op, t=0, c=0, bad=None):
    b = u8(MUT[op]) + u8(t) + u8(c)
    if op == "bad_index":  # bad = ("high", k) -> nv + k, ("negative", k) -> -1 - k
        b += u8(1 if bad[0] == "high" else 0) + u8(bad[1])
    return b

def structured(kind, e=0, offset=(2, 2, 2), edits=(), mutations=(), torus=(4, 3)):
    """A base shape scaled by 2^e and moved by (offset - 2) * 2^e, then edited and mutated."""
    b = u8(KIND[kind])
    if kind in ("torus", "lattice torus"): b += u8(torus[0] - 3) + u8(torus[1] - 3)
    b += exponent(e) + b"".join(u8(o) for o in offset)
    b += u8(len(edits)) + b"".join(edits)
    b += u8(len(mutations)) + b"".join(mutations)
    return b

def random_mesh(style, points, triangles, e=0):
    """Vertices in `style` (a point ("dup", k) copies point k), then triangles (indices:
    an int in range, or ("bad", j) for the j-th entry of the bad-index table)."""
    b = u8(KIND["random"]) + u8(len(points) - 3) + u8(style) + exponent(e)
    for i, p in enumerate(points):
        if isinstance(p, tuple) and p[0] == "dup":
            # a byte d with d % 8 == 0 copies point d % i
            b += u8(next(d for d in range(0, 256, 8) if d % i == p[1]))
            continue
        b += u8(1) + b"".join(coord(style, c) for c in p)
    b += u8(len(triangles) - 1)
    for t in triangles:
        for v in t: b += u8(240 + v[1]) if isinstance(v, tuple) else u8(v)
    return b

B_BOX, B_OCT, B_DECODED, B_SAME = u8(0), u8(1), u8(2), u8(3)

def pose(kind="default", arg=None, t=(0, 0, 0)):
    """decodePose(): kind byte, its payload, a translation style-0 lattice vector (-2..2).
    'default' (byte 0) is the identity for A and a fixed generic rotation for B."""
    if kind == "default": b = u8(0)
    elif kind == "identity": b = u8(7)
    elif kind == "perm": b = u8(1) + u8(arg)
    elif kind == "quat": b = u8(2) + b"".join(i8(c) for c in arg)
    elif kind == "rawquat": b = u8(3) + b"".join(i8(c) for c in arg)
    elif kind == "specials": b = u8(4) + b"".join(u8(SPECIAL[c]) for c in arg)
    elif kind == "nudged": b = u8(5) + b"".join(i8(c) for c in arg[0]) + u8(arg[1]) + u8(arg[2] - 10)
    elif kind == "nan": b = u8(6) + u8(arg)
    else: raise ValueError(kind)
    return b + u8(0) + b"".join(coord(0, c) for c in t)

def motion(rot=(3, -2, 1), shift=(2, 0, -1)):
    return b"".join(i8(c) for c in rot) + b"".join(i8(c) for c in shift)

def ball(centre=(0, 0, 0), radius=("unit", 0.5), kind="lattice"):
    """Centre: 'near' tA - tB + half-units (-2..2), 'lattice' units, 'special' (style 4), 'raw'
    doubles. Radius: ('unit', u) for u in the units table, ('special', key), ('minus',),
    ('raw', x), ('scaled', k) = (1 + k / 128) units."""
    ck = {"near": 0, "lattice": 1, "special": 2, "raw": 3}[kind]
    style = {0: 0, 1: 0, 2: 4, 3: 3}[ck]
    b = u8(ck) + b"".join(coord(style, c) for c in centre)
    units = [0.25, 0.5, 1, 1.5, 2, 3, 5, 20]
    if radius[0] == "unit": b += u8(0) + u8(units.index(radius[1]))
    elif radius[0] == "special": b += u8(4) + u8(SPECIAL[radius[1]])
    elif radius[0] == "minus": b += u8(5)
    elif radius[0] == "raw": b += u8(6) + f64(radius[1])
    elif radius[0] == "scaled": b += u8(7) + i8(radius[1])
    return b

# A scene: mesh A, mesh B, their poses, the motions of A and of B for the second update
# (by default B turns and slides a little, A stays), the ball.
def scene(a, b=B_BOX, pa=None, pb=None, ma=None, mb=None, bl=None):
    return a + b + (pa or pose()) + (pb or pose()) + (ma or motion((0, 0, 0), (0, 0, 0))) + (mb or motion()) + (bl or ball())

def seeds():
    out = {}
    box, octa, tet = structured("box"), structured("octahedron"), structured("tetrahedron")
    q = pose("quat", (5, 1, -2, 3))
    # Valid meshes, small balls on M's boundary.
    out["box_box_face"] = scene(box, bl=ball((2, 0, 0), ("unit", 0.5)))
    out["box_box_face_exact_identity"] = scene(box, pb=pose("identity"), bl=ball((2, 0, 0), ("unit", 0.25)))
    out["box_box_edge_quat"] = scene(box, pb=q, bl=ball((2, 2, 0), ("unit", 1)))
    out["box_octahedron_vertex"] = scene(box, B_OCT, bl=ball((2, 2, 1), ("unit", 0.5)))
    out["tetrahedron_box"] = scene(tet, bl=ball((-1, -1, -1), ("unit", 0.5)))
    out["octahedron_self_perm"] = scene(octa, B_SAME, pb=pose("perm", 13), bl=ball((1, 1, 0), ("unit", 0.5)))
    out["torus_box_inner_ring"] = scene(structured("torus", torus=(4, 3)), bl=ball((2, 0, 0), ("unit", 0.5)))
    out["lattice_torus_octahedron"] = scene(structured("lattice torus", e=-2, torus=(5, 4)), B_OCT, pb=q,
                                             bl=ball((2, 1, 0), ("unit", 0.5)))
    out["two_components_box"] = scene(structured("two"), bl=ball((2, 1, 0), ("unit", 0.5)))
    out["torus_torus"] = scene(structured("torus", torus=(3, 3)), B_DECODED + structured("torus", e=-1, torus=(3, 3)),
                                pb=pose("quat", (7, 2, 0, 1)), bl=ball((2, 2, 0), ("unit", 0.5)))
    out["box_tiny_denormal_scale"] = scene(structured("box", e=-1024), bl=ball((2, 0, 0), ("unit", 0.5)))
    out["box_scale_2^200"] = scene(structured("box", e=200), bl=ball((2, 0, 0), ("unit", 0.5)))
    out["box_nudged_vertex"] = scene(structured("box", edits=[edit(7, "nudge", 0, 5)]), pb=pose("identity"),
                                     bl=ball((2, 2, 2), ("unit", 0.25)))
    out["box_benign_mutations"] = scene(structured("box", mutations=[mutation("rotate", 3), mutation("swap", 1, 2)]),
                                         bl=ball((-2, 0, 0), ("unit", 0.5)))
    out["box_pose_nudged"] = scene(box, pa=pose("nudged", ((5, 1, -2, 3), 4, 21)), bl=ball((2, 0, 0), ("unit", 0.5)))
    # Hostile meshes.
    out["box_open"] = scene(structured("box", mutations=[mutation("drop", 5)]))
    out["box_non_manifold_duplicate"] = scene(structured("box", mutations=[mutation("duplicate", 2)]))
    out["box_inverted"] = scene(structured("box", mutations=[mutation("flip_all")]))
    out["box_one_flipped"] = scene(structured("box", mutations=[mutation("flip", 4)]))
    out["octahedron_folded_extra"] = scene(structured("octahedron", mutations=[mutation("fold", 1)]))
    out["box_index_out_of_range"] = scene(structured("box", mutations=[mutation("bad_index", 0, 1, ("high", 0))]))
    out["box_negative_index"] = scene(structured("box", mutations=[mutation("bad_index", 6, 2, ("negative", 0))]))
    out["box_corner_moved"] = scene(structured("box", mutations=[mutation("corner", 0, 1)]))
    out["box_unused_vertex"] = scene(structured("box", mutations=[mutation("unused_vertex")]))
    out["box_nan_vertex"] = scene(structured("box", edits=[edit(3, "special", 1, "nan")]))
    out["box_inf_vertex"] = scene(structured("box", edits=[edit(5, "special", 2, "-inf")]))
    out["box_1e300_vertex"] = scene(structured("box", edits=[edit(0, "special", 0, 1e300)]))
    out["box_denormal_vertex"] = scene(structured("box", edits=[edit(1, "special", 0, "denorm")]))
    out["box_collapsed_vertex"] = scene(structured("box", edits=[edit(1, "snap", 0)]))
    out["tetrahedron_flat"] = scene(structured("tetrahedron", edits=[edit(3, "half", 0), edit(3, "reflect", 1)]))
    out["octahedron_raw_coordinate"] = scene(structured("octahedron", edits=[edit(4, "raw", 2, 1e-310)]))
    out["torus_inverted"] = scene(structured("torus", mutations=[mutation("flip_all")]))
    out["random_lattice_soup"] = scene(random_mesh(0, [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), ("dup", 0), (1, 1, 1)],
                                                    [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3), (4, 5, 1), (0, ("bad", 0), 2)]))
    out["random_tetrahedron"] = scene(random_mesh(1, [(0, 0, 0), (8, 0, 0), (0, 8, 0), (0, 0, 8)],
                                                   [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]),
                                       bl=ball((2, 0, 0), ("unit", 0.5)))
    out["random_specials"] = scene(random_mesh(4, [(0, 0, 0), ("nan", 1, 0), (0, "inf", 1), ("denorm", 0, 1e300)],
                                                [(0, 1, 2), (0, 2, 3), (0, 3, 1), (1, 3, 2)]))
    # Hostile queries on valid meshes.
    for name, r in [("zero", ("special", 0.0)), ("negative", ("minus",)), ("nan", ("special", "nan")),
                    ("inf", ("special", "inf")), ("huge", ("raw", 1e300)), ("denormal", ("special", "denorm"))]:
        out["radius_" + name] = scene(box, bl=ball((2, 0, 0), r))
    out["centre_nan"] = scene(box, bl=ball(("nan", 0, 0), ("unit", 0.5), kind="special"))
    out["centre_huge"] = scene(box, bl=ball((1e300, 0, 0), ("unit", 0.5), kind="raw"))
    out["pose_reflection"] = scene(box, pb=pose("perm", 6 * 1), bl=ball((2, 0, 0), ("unit", 0.5)))
    out["pose_not_orthonormal"] = scene(box, pa=pose("rawquat", (5, 1, -2, 3)), bl=ball((2, 0, 0), ("unit", 0.5)))
    out["pose_specials"] = scene(box, pb=pose("specials", [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, "1+eps"]))
    out["pose_nan"] = scene(box, pa=pose("nan", 4))
    return out

def main():
    os.makedirs(OUT, exist_ok=True)
    for old in os.listdir(OUT): os.remove(os.path.join(OUT, old))
    for name, data in sorted(seeds().items()):
        with open(os.path.join(OUT, name), "wb") as f: f.write(data)
    print(f"wrote {len(seeds())} seeds to {OUT}")

if __name__ == "__main__":
    main()
