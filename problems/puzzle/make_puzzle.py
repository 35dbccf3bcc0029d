#!/usr/bin/env python3
"""Writes the two meshes of problems/puzzle.yaml, a two-piece disassembly puzzle in the spirit of the
Alpha Puzzle (run-cost variance paper, figure 2). Run from anywhere; the outputs are committed:

    python3 problems/puzzle/make_puzzle.py

puzzle_fixed.obj   the fixed piece: a flat frame of square bars (BAR x BAR) in the xz plane,
                   OUTER_W wide and OUTER_H high, with a middle crossbar (like the letter 日), so it
                   has an upper and a lower window. The top and the bottom bar are each cut in the
                   middle by a slit SLIT wide, so the frame is one piece with four prongs: the two
                   halves of the top bar point at each other across the upper slit, the two halves of
                   the bottom bar across the lower slit. The outline is a simple polygon (20 corners),
                   ear-clipped into triangles and extruded BAR thick along y.
puzzle_moving.obj  the moving piece: a closed square ring RING wide, its strand STRAND x STRAND, lying
                   in its own xy plane, centred on the origin (the body frame of the state).

The ring, hung on one of the four prongs (the prong passes through its hole), can only come off
through that prong's slit: it must slide to the prong's end, stand square to the slit and pass its
strand through it (STRAND < SLIT). It cannot move from the top prongs to the bottom ones without
coming off, because the middle crossbar and the side bars close the frame.

Both meshes are closed and consistently oriented (outward normals, counter-clockwise seen from
outside). Standard library only; nothing is random.
"""
from pathlib import Path

HERE = Path(__file__).resolve().parent

BAR = 1.0          # the fixed frame's bar: square section BAR x BAR
OUTER_W = 12.0     # the frame's outer width (x)
OUTER_H = 14.0     # the frame's outer height (z)
SLIT = 1.6         # the slits in the top and bottom bars (twice the ring's strand)
RING = 7.0         # the moving ring's outer side (hole 5.4: it hangs loosely on a 1 x 1 bar)
STRAND = 0.8       # the moving ring's strand: square section STRAND x STRAND


def frame_outline():
    """The fixed piece's outline in the xz plane, counter-clockwise (x right, z up)."""
    w, h, b, s = OUTER_W / 2, OUTER_H / 2, BAR, SLIT / 2
    m = BAR / 2  # the middle crossbar spans z in [-m, m]
    return [
        # walk round the outside counter-clockwise, dipping into each slit and each window
        (s, h - b), (w - b, h - b), (w - b, m), (-w + b, m), (-w + b, h - b), (-s, h - b), (-s, h),
        (-w, h), (-w, -h), (-s, -h), (-s, -h + b), (-w + b, -h + b), (-w + b, -m), (w - b, -m),
        (w - b, -h + b), (s, -h + b), (s, -h), (w, -h), (w, h), (s, h),
    ]


def area2(poly):
    return sum(poly[i][0] * poly[(i + 1) % len(poly)][1] - poly[(i + 1) % len(poly)][0] * poly[i][1]
               for i in range(len(poly)))


def cross(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def inside_triangle(p, a, b, c):
    return cross(a, b, p) >= 0 and cross(b, c, p) >= 0 and cross(c, a, p) >= 0


def ear_clip(poly):
    """Triangles (index triples, counter-clockwise) of a simple counter-clockwise polygon."""
    idx = list(range(len(poly)))
    tris = []
    while len(idx) > 3:
        n = len(idx)
        for k in range(n):
            i, j, l = idx[k - 1], idx[k], idx[(k + 1) % n]
            a, b, c = poly[i], poly[j], poly[l]
            if cross(a, b, c) <= 1e-12:
                continue  # reflex or degenerate corner
            if any(inside_triangle(poly[q], a, b, c) for q in idx if q not in (i, j, l)
                   and poly[q] not in (a, b, c)):
                continue
            tris.append((i, j, l))
            del idx[k]
            break
        else:
            raise RuntimeError("ear clipping failed: polygon not simple?")
    tris.append(tuple(idx))
    return tris


def extrude_xz(poly, y0, y1):
    """A closed prism: the xz polygon (counter-clockwise seen from -y... see below) from y0 to y1.

    The polygon is counter-clockwise in (x, z). Seen from +y looking towards -y, (x, z) appears
    mirrored, so the face at y1 (normal +y) takes the triangles reversed and the face at y0
    (normal -y) takes them as they are.
    """
    n = len(poly)
    verts = [(x, y0, z) for x, z in poly] + [(x, y1, z) for x, z in poly]
    faces = []
    for a, b, c in ear_clip(poly):
        faces.append((a, b, c))               # y0 face, normal -y
        faces.append((n + a, n + c, n + b))   # y1 face, normal +y
    for i in range(n):
        j = (i + 1) % n
        # side wall of edge i -> j; outward is to the right of the counter-clockwise edge
        faces.append((i, n + i, n + j))
        faces.append((i, n + j, j))
    return verts, faces


def square_ring(side, strand):
    """A closed square ring in the xy plane, centred on the origin, strand x strand section."""
    o, i, t = side / 2, side / 2 - strand, strand / 2
    sq = lambda r: [(-r, -r), (r, -r), (r, r), (-r, r)]  # counter-clockwise seen from +z
    verts = []
    for z in (-t, t):
        verts += [(x, y, z) for x, y in sq(o)] + [(x, y, z) for x, y in sq(i)]
    # indices: bottom outer 0-3, bottom inner 4-7, top outer 8-11, top inner 12-15
    faces = []
    for k in range(4):
        m = (k + 1) % 4
        faces += [(8 + k, 8 + m, 12 + m), (8 + k, 12 + m, 12 + k)]      # top (+z)
        faces += [(0 + k, 4 + m, 0 + m), (0 + k, 4 + k, 4 + m)]         # bottom (-z)
        faces += [(0 + k, 0 + m, 8 + m), (0 + k, 8 + m, 8 + k)]         # outer wall
        faces += [(4 + k, 12 + m, 4 + m), (4 + k, 12 + k, 12 + m)]      # inner wall (faces the hole)
    return verts, faces


def check_closed(verts, faces, name):
    """Every directed edge must appear once and its reverse once (closed, consistently oriented)."""
    edges = {}
    for f in faces:
        for a, b in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0])):
            edges[(a, b)] = edges.get((a, b), 0) + 1
    for (a, b), c in edges.items():
        if c != 1 or edges.get((b, a), 0) != 1:
            raise RuntimeError(f"{name}: edge {a}-{b} is not shared by exactly two opposite faces")
    # signed volume must be positive (outward normals)
    vol = 0.0
    for a, b, c in faces:
        (x1, y1, z1), (x2, y2, z2), (x3, y3, z3) = verts[a], verts[b], verts[c]
        vol += x1 * (y2 * z3 - z2 * y3) - y1 * (x2 * z3 - z2 * x3) + z1 * (x2 * y3 - y2 * x3)
    if vol <= 0:
        raise RuntimeError(f"{name}: faces point inwards (volume {vol / 6})")
    return vol / 6


def write_obj(path, verts, faces, comment):
    lines = [f"# {c}" for c in comment] + [f"# {len(verts)} vertices, {len(faces)} triangles", "o piece"]
    lines += ["v " + " ".join(f"{c:g}" for c in v) for v in verts]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in faces]
    path.write_text("\n".join(lines) + "\n")
    print("wrote", path)


def main():
    poly = frame_outline()
    if area2(poly) <= 0:
        poly = poly[::-1]
    verts, faces = extrude_xz(poly, -BAR / 2, BAR / 2)
    vol = check_closed(verts, faces, "fixed")
    write_obj(HERE / "puzzle_fixed.obj", verts, faces, [
        "Puzzle, fixed piece (made by make_puzzle.py): a frame of square bars with a middle crossbar,",
        f"{OUTER_W:g} x {OUTER_H:g} in the xz plane, bars {BAR:g} thick, a {SLIT:g}-wide slit in the top and bottom bars.",
        f"volume {vol:g}"])
    verts, faces = square_ring(RING, STRAND)
    vol = check_closed(verts, faces, "moving")
    write_obj(HERE / "puzzle_moving.obj", verts, faces, [
        "Puzzle, moving piece (made by make_puzzle.py): a closed square ring in the xy plane,",
        f"{RING:g} wide, strand {STRAND:g} x {STRAND:g}, centred on the origin.",
        f"volume {vol:g}"])


if __name__ == "__main__":
    main()
