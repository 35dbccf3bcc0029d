#!/usr/bin/env python3
"""Writes AMP's bundled problem files (problems/*.yaml) from a few geometric recipes.

The files are committed; this script documents how they were made and remakes them exactly
(`python3 scripts/make_problems.py`). Every maze is drawn from a fixed seed.
"""
import math
import random
from pathlib import Path

OUT = Path(__file__).resolve().parent.parent / "problems"


def fmt(x):
    s = f"{x:.4f}".rstrip("0").rstrip(".")
    return "0" if s == "-0" else s


def rect(x0, y0, x1, y1):
    return {"rectangle": {"center": [(x0 + x1) / 2, (y0 + y1) / 2], "size": [x1 - x0, y1 - y0]}}


def box(x0, y0, z0, x1, y1, z1):
    return {"box": {"center": [(x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2], "size": [x1 - x0, y1 - y0, z1 - z0]}}


def emit(value, indent=0):
    """A small YAML emitter: flow style for lists of numbers and shape items, block style elsewhere."""
    pad = "  " * indent
    if isinstance(value, dict):
        lines = []
        for k, v in value.items():
            if isinstance(v, (dict,)) or (isinstance(v, list) and v and isinstance(v[0], dict)):
                lines.append(f"{pad}{k}:")
                lines.append(emit(v, indent + 1))
            else:
                lines.append(f"{pad}{k}: {flow(v)}")
        return "\n".join(lines)
    if isinstance(value, list):
        return "\n".join(f"{pad}- {flow(v)}" for v in value)
    return pad + flow(value)


def flow(v):
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k}: {flow(x)}" for k, x in v.items()) + "}"
    if isinstance(v, list):
        return "[" + ", ".join(flow(x) for x in v) + "]"
    if isinstance(v, float):
        return fmt(v)
    return str(v)


def write(name, header, doc):
    path = OUT / f"{name}.yaml"
    path.write_text(f"# {header}\n# Made by scripts/make_problems.py; see docs/problem-format.md for the fields.\n"
                    + emit(doc) + "\n")
    print("wrote", path)


def maze_walls(cols, rows, cell, x0, y0, wall, rng, narrow_gaps, door=None):
    """A perfect maze (randomised depth-first search) of cols x rows cells as thin wall rectangles.
    `narrow_gaps` extra walls get a gap narrower than the robot: tempting shortcuts that cannot be used.
    With `door`, the maze's open connections are doors of that width instead of whole open walls."""
    visited = [[False] * rows for _ in range(cols)]
    open_e = set()  # (c, r, 'E'|'N') walls removed
    stack = [(0, rng.randrange(rows))]
    visited[stack[0][0]][stack[0][1]] = True
    while stack:
        c, r = stack[-1]
        nbrs = [(c + dc, r + dr) for dc, dr in ((1, 0), (-1, 0), (0, 1), (0, -1))
                if 0 <= c + dc < cols and 0 <= r + dr < rows and not visited[c + dc][r + dr]]
        if not nbrs:
            stack.pop()
            continue
        nc, nr = rng.choice(nbrs)
        if nc != c:
            open_e.add((min(c, nc), r, "E"))
        else:
            open_e.add((c, min(r, nr), "N"))
        visited[nc][nr] = True
        stack.append((nc, nr))
    closed = [(c, r, "E") for c in range(cols - 1) for r in range(rows) if (c, r, "E") not in open_e]
    closed += [(c, r, "N") for c in range(cols) for r in range(rows - 1) if (c, r, "N") not in open_e]
    narrow = set(rng.sample(closed, narrow_gaps))
    h = wall / 2
    obstacles = []
    # Wall posts at every grid corner keep the corners solid.
    for c in range(cols + 1):
        for r in range(rows + 1):
            x, y = x0 + c * cell, y0 + r * cell
            obstacles.append(rect(x - h, y - h, x + h, y + h))
    for c in range(cols):
        for r in range(rows):
            x, y = x0 + c * cell, y0 + r * cell
            # East wall of (c, r) and north wall of (c, r); the outer boundary is built below.
            if c < cols - 1 and (c, r, "E") in open_e and door:
                xe, mid = x + cell, y + cell / 2
                obstacles.append(rect(xe - h, y + h, xe + h, mid - door / 2))
                obstacles.append(rect(xe - h, mid + door / 2, xe + h, y + cell - h))
            if r < rows - 1 and (c, r, "N") in open_e and door:
                yn, mid = y + cell, x + cell / 2
                obstacles.append(rect(x + h, yn - h, mid - door / 2, yn + h))
                obstacles.append(rect(mid + door / 2, yn - h, x + cell - h, yn + h))
            if c < cols - 1 and (c, r, "E") not in open_e:
                xe = x + cell
                if (c, r, "E") in narrow:
                    mid = y + cell / 2
                    obstacles.append(rect(xe - h, y + h, xe + h, mid - narrow_gap / 2))
                    obstacles.append(rect(xe - h, mid + narrow_gap / 2, xe + h, y + cell - h))
                else:
                    obstacles.append(rect(xe - h, y + h, xe + h, y + cell - h))
            if r < rows - 1 and (c, r, "N") not in open_e:
                yn = y + cell
                if (c, r, "N") in narrow:
                    mid = x + cell / 2
                    obstacles.append(rect(x + h, yn - h, mid - narrow_gap / 2, yn + h))
                    obstacles.append(rect(mid + narrow_gap / 2, yn - h, x + cell - h, yn + h))
                else:
                    obstacles.append(rect(x + h, yn - h, x + cell - h, yn + h))
    return obstacles


narrow_gap = 1.1  # narrower than the Maze robot (width 1.4)


def make_maze():
    rng = random.Random(20261125)
    cols, rows, cell, wall = 6, 5, 8.0, 1.0
    x0, y0 = 24.0, 4.0  # maze block spans x 24..72, y 4..44
    obstacles = maze_walls(cols, rows, cell, x0, y0, wall, rng, narrow_gaps=6, door=2.6)
    h = wall / 2
    x1, y1 = x0 + cols * cell, y0 + rows * cell
    # West and east boundary walls of the maze block, each with one entrance cell open.
    w_in, e_in = 2, 1
    for r in range(rows):
        y = y0 + r * cell
        if r != w_in:
            obstacles.append(rect(x0 - h, y + h, x0 + h, y + cell - h))
        if r != e_in:
            obstacles.append(rect(x1 - h, y + h, x1 + h, y + cell - h))
    # Solid blocks above and below the maze block so the open areas join only through the maze.
    obstacles.append(rect(x0 - h, 0.0, x1 + h, y0 - h))
    obstacles.append(rect(x0 - h, y1 + h, x1 + h, 48.0))
    write("maze", "Maze (SE2): two open areas joined by a maze of tunnels, some narrower than the robot.", {
        "name": "Maze",
        "bounds": {"min": [0, 0], "max": [96, 48]},
        "resolution": 0.002,
        "world": {"obstacles": obstacles},
        "robot": {"type": "rigid2d", "shapes": [rect(-2.0, -0.7, 2.0, 0.7)]},
        "start": [8.0, 24.0, 0.0],
        "goal": [88.0, 24.0, 1.5708],
        "defaults": {"planner": "prm", "time_limit": 60, "node_limit": 50000},
    })


def make_l_tunnel():
    obstacles = [
        rect(0, 22, 40, 100),    # west block
        rect(48.6, 0, 86, 61.4),     # south-east block
        rect(40, 70, 86, 100),   # north block
    ]
    l_robot = [rect(-1.0, -1.0, 7.0, 1.0), rect(-1.0, 1.0, 1.0, 7.0)]
    write("l-tunnel", "L-Tunnel (SE2): an L-shaped robot through an L-shaped passage between three large obstacles.", {
        "name": "L-Tunnel",
        "bounds": {"min": [0, 0], "max": [100, 100]},
        "resolution": 0.002,
        "world": {"obstacles": obstacles},
        "robot": {"type": "rigid2d", "shapes": l_robot},
        "start": [12.0, 10.0, 0.0],
        "goal": [94.0, 78.0, 1.5708],
        "defaults": {"planner": "prm", "time_limit": 60, "node_limit": 50000},
    })


def make_hook():
    wall = 4.0
    slit = 7.6
    obstacles = []
    for y, cx in ((32.0, 30.0), (66.0, 70.0)):
        obstacles.append(rect(0, y, cx - slit / 2, y + wall))
        obstacles.append(rect(cx + slit / 2, y, 100, y + wall))
    hook = [rect(-1.0, 0.0, 1.0, 14.0), rect(-1.0, -2.0, 5.5, 0.0), rect(3.5, 0.0, 5.5, 4.0)]
    write("hook", "Hook (SE2): a hook-shaped robot through slits in two walls.", {
        "name": "Hook",
        "bounds": {"min": [0, 0], "max": [100, 100]},
        "resolution": 0.002,
        "world": {"obstacles": obstacles},
        "robot": {"type": "rigid2d", "shapes": hook},
        "start": [70.0, 10.0, 0.0],
        "goal": [30.0, 82.0, 0.0],
        "defaults": {"planner": "prm", "time_limit": 60, "node_limit": 50000},
    })


def make_walls():
    rng = random.Random(7)
    size, wall, hole = 90.0, 1.5, 3.4
    third = size / 3
    obstacles = []
    h = wall / 2
    # Two vertical and two horizontal walls make 3x3 chambers; each wall segment has one small hole.
    for i in (1, 2):
        x = i * third
        for j in range(3):
            ya, yb = j * third, (j + 1) * third
            c = rng.uniform(ya + 5, yb - 5)
            obstacles.append(rect(x - h, ya, x + h, c - hole / 2))
            obstacles.append(rect(x - h, c + hole / 2, x + h, yb))
    for j in (1, 2):
        y = j * third
        for i in range(3):
            xa, xb = i * third, (i + 1) * third
            c = rng.uniform(xa + 5, xb - 5)
            obstacles.append(rect(xa, y - h, c - hole / 2, y + h))
            obstacles.append(rect(c + hole / 2, y - h, xb, y + h))
    # Clutter in four chambers: circles and small squares kept away from the walls' holes.
    for (ci, cj) in ((1, 0), (0, 1), (1, 1), (2, 1)):
        for _ in range(7):
            x = rng.uniform(ci * third + 4, (ci + 1) * third - 4)
            y = rng.uniform(cj * third + 4, (cj + 1) * third - 4)
            if rng.random() < 0.5:
                obstacles.append({"circle": {"center": [round(x, 2), round(y, 2)], "radius": round(rng.uniform(0.8, 1.6), 2)}})
            else:
                s = rng.uniform(1.0, 2.4)
                obstacles.append({"rectangle": {"center": [round(x, 2), round(y, 2)], "size": [round(s, 2), round(s, 2)],
                                                "angle": round(rng.uniform(0, math.pi), 3)}})
    write("walls", "Walls (SE2): 3x3 chambers joined by small holes, four of them cluttered.", {
        "name": "Walls",
        "bounds": {"min": [0, 0], "max": [size, size]},
        "resolution": 0.002,
        "world": {"obstacles": obstacles},
        "robot": {"type": "rigid2d", "shapes": [rect(-1.4, -0.6, 1.4, 0.6)]},
        "start": [8.0, 8.0, 0.0],
        "goal": [82.0, 82.0, 0.0],
        "defaults": {"planner": "prm", "time_limit": 60, "node_limit": 50000},
    })


def make_linkage():
    obstacles = [
        rect(-2, 9, 3.0, 11),      # shelf above the base, left of the slot
        rect(6.0, 9, 14, 11),      # shelf right of the slot
        {"circle": {"center": [-7.5, 4.0], "radius": 1.5}},
        rect(8.0, 1.5, 10.0, 6.0),  # post in the lower right
    ]
    write("linkage", "Linkage: a 4-link planar arm on a fixed base reaching through a slot in a shelf.", {
        "name": "Arm-Slot",
        "bounds": {"min": [-14, -2], "max": [14, 20]},
        "resolution": 0.002,
        "world": {"obstacles": obstacles},
        "robot": {"type": "arm", "base": [0.0, 0.0, 0.0],
                  "links": [{"length": 4.0, "width": 0.8}, {"length": 3.5, "width": 0.7},
                            {"length": 3.0, "width": 0.6}, {"length": 2.5, "width": 0.5}],
                  "limits": [[-0.2, 3.34], [-2.6, 2.6], [-2.6, 2.6], [-2.6, 2.6]]},
        "start": [3.0, 0.0, 0.0, 0.0],
        "goal": [1.1, 0.1, 0.1, 0.1],
        "defaults": {"planner": "prm", "time_limit": 60, "node_limit": 50000},
    })


def make_maze3d():
    """A 3-D maze: a 4x4x2 grid of cells in a solid block, corridors carved by a random DFS."""
    rng = random.Random(31)
    nx, ny, nz, cell, wall = 4, 4, 2, 6.0, 1.0
    visited = set()
    opened = set()
    start = (0, 0, 0)
    stack = [start]
    visited.add(start)
    while stack:
        c = stack[-1]
        nbrs = []
        for d in ((1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)):
            n = (c[0] + d[0], c[1] + d[1], c[2] + d[2])
            if 0 <= n[0] < nx and 0 <= n[1] < ny and 0 <= n[2] < nz and n not in visited:
                nbrs.append(n)
        if not nbrs:
            stack.pop()
            continue
        n = rng.choice(nbrs)
        opened.add(frozenset((c, n)))
        visited.add(n)
        stack.append(n)
    obstacles = []
    X, Y, Z = nx * cell, ny * cell, nz * cell
    h = wall / 2
    # Interior walls between cells that stay closed, as slabs; doors are holes of 3.2 x 3.2.
    for i in range(nx):
        for j in range(ny):
            for k in range(nz):
                for d in ((1, 0, 0), (0, 1, 0), (0, 0, 1)):
                    n = (i + d[0], j + d[1], k + d[2])
                    if n[0] >= nx or n[1] >= ny or n[2] >= nz:
                        continue
                    x0, y0, z0 = i * cell, j * cell, k * cell
                    if frozenset(((i, j, k), n)) in opened:
                        continue
                    if d[0]:
                        obstacles.append(box(x0 + cell - h, y0, z0, x0 + cell + h, y0 + cell, z0 + cell))
                    elif d[1]:
                        obstacles.append(box(x0, y0 + cell - h, z0, x0 + cell, y0 + cell + h, z0 + cell))
                    else:
                        obstacles.append(box(x0, y0, z0 + cell - h, x0 + cell, y0 + cell, z0 + cell + h))
    # Opened walls keep a frame around a square door.
    door = 3.2
    for pair in opened:
        a, b = sorted(pair)
        axis = [b[t] - a[t] for t in range(3)].index(1)
        lo = [a[t] * cell for t in range(3)]
        plane = (a[axis] + 1) * cell
        others = [t for t in range(3) if t != axis]
        u, v = others
        cu, cv = lo[u] + cell / 2, lo[v] + cell / 2
        frame = [
            (lo[u], lo[v], cu - door / 2, lo[v] + cell),
            (cu + door / 2, lo[v], lo[u] + cell, lo[v] + cell),
            (cu - door / 2, lo[v], cu + door / 2, cv - door / 2),
            (cu - door / 2, cv + door / 2, cu + door / 2, lo[v] + cell),
        ]
        for (u0, v0, u1, v1) in frame:
            mn = [0, 0, 0]
            mx = [0, 0, 0]
            mn[axis], mx[axis] = plane - h, plane + h
            mn[u], mx[u] = u0, u1
            mn[v], mx[v] = v0, v1
            obstacles.append(box(*mn, *mx))
    robot = [box(-1.6, -0.5, -0.5, 1.6, 0.5, 0.5)]
    write("maze3d", "3-D Maze (SE3): a 4x4x2 maze of cells joined by square doors; a bar-shaped robot.", {
        "name": "Maze-3D",
        "bounds": {"min": [0, 0, 0], "max": [X, Y, Z]},
        "resolution": 0.002,
        "world": {"obstacles": obstacles},
        "robot": {"type": "rigid3d", "shapes": robot},
        "start": [3.0, 3.0, 3.0, 0, 0, 0, 1],
        "goal": [X - 3.0, Y - 3.0, Z - 3.0, 0, 0, 0, 1],
        "defaults": {"planner": "prm", "time_limit": 60, "node_limit": 50000},
    })


def make_walls3d():
    rng = random.Random(5)
    L, W, H = 40.0, 16.0, 16.0
    obstacles = []
    hole = 3.3
    for x in (10.0, 20.0, 30.0):
        cy, cz = rng.uniform(3, W - 3), rng.uniform(3, H - 3)
        t = 0.5
        obstacles.append(box(x - t, 0, 0, x + t, cy - hole / 2, H))
        obstacles.append(box(x - t, cy + hole / 2, 0, x + t, W, H))
        obstacles.append(box(x - t, cy - hole / 2, 0, x + t, cy + hole / 2, cz - hole / 2))
        obstacles.append(box(x - t, cy - hole / 2, cz + hole / 2, x + t, cy + hole / 2, H))
    # Clutter in the second chamber.
    for _ in range(5):
        c = [rng.uniform(12, 18), rng.uniform(2, W - 2), rng.uniform(2, H - 2)]
        obstacles.append({"sphere": {"center": [round(v, 2) for v in c], "radius": round(rng.uniform(0.8, 1.5), 2)}})
    robot = [box(-1.2, -0.4, -0.4, 1.2, 0.4, 0.4), box(-0.4, -1.2, -0.4, 0.4, 1.2, 0.4)]
    write("walls3d", "3-D Walls (SE3): chambers divided by three walls, each with a small square hole.", {
        "name": "Walls-3D",
        "bounds": {"min": [0, 0, 0], "max": [L, W, H]},
        "resolution": 0.002,
        "world": {"obstacles": obstacles},
        "robot": {"type": "rigid3d", "shapes": robot},
        "start": [4.0, 8.0, 8.0, 0, 0, 0, 1],
        "goal": [36.0, 8.0, 8.0, 0, 0, 0, 1],
        "defaults": {"planner": "prm", "time_limit": 60, "node_limit": 50000},
    })


if __name__ == "__main__":
    make_maze()
    make_l_tunnel()
    make_hook()
    make_walls()
    make_linkage()
    make_maze3d()
    make_walls3d()
