#!/usr/bin/env python3
"""Writes problems/scara-wicket.yaml: a Hwang & Ahuja-like SCARA task (run-cost variance paper, figure 1).

A 5-DOF SCARA arm carries a J-shaped hook. At the first seed the hook is threaded through a wicket
(an inverted-U gate of three bars standing on the floor, like a croquet hoop): the hook's foot passes
under the crossbar and its barb rises CATCH above the crossbar's underside behind it. To get free
the arm must lower the hook until the barb clears the crossbar, turn clockwise about the column so
that the foot slides out through the hoop (the crossbar lies along the radius, so this is a pure
shoulder motion), and lift; then it swings round a large cylinder, folding the elbow, to the last
seed on the cylinder's far side. The joint limits close the other way round.

HOOP_W, CATCH, START_FOOT and SHANK_GAP set the difficulty; they were calibrated so that plain PRM
(`amp plan problems/scara-wicket.yaml --planner prm --seed 1..10`) needs a median of about 165,000
CD calls.

The file is committed; this script documents how it was made and remakes it exactly
(`python3 scripts/make_scara_wicket.py`). Nothing is random.
"""
import math
from pathlib import Path

OUT = Path(__file__).resolve().parent.parent / "problems" / "scara-wicket.yaml"

# --- the robot ------------------------------------------------------------------------------------
L1, L2 = 0.5, 0.4            # upper arm, forearm
R = 0.04                     # link radius
WRIST = 0.08                 # wrist cylinder length
SLIDE = (0.55, 0.95)
# Base yaw, shoulder, elbow, wrist. The upper arm's heading (base yaw + shoulder) stays in
# [-3.1, 1.9], so the arm cannot reach the goal the other way round.
LIMITS = [(-0.3, 0.3), (-2.8, 1.6), (-2.6, 2.6), (-1.4, 1.4)]

# The hook in the flange frame (z up, origin at the wrist's lower end): a shank straight down, a foot
# along +x at its bottom, a barb rising at the foot's end.
HT = 0.03                    # bar thickness of the hook
SHANK = 0.28                 # shank length (flange to the foot's underside)
REACH = 0.22                 # foot length from the shank axis to the barb's outer face
BARB = 0.11                  # barb height above the foot's underside
TOOL = [
    ((0.0, 0.0, -SHANK / 2), (HT, HT, SHANK)),                                   # shank
    (((REACH - HT / 2) / 2, 0.0, -SHANK + HT / 2), (REACH + HT / 2, HT, HT)),  # foot
    ((REACH - HT / 2, 0.0, -SHANK + BARB / 2), (HT, HT, BARB)),                  # barb
]
TIP = (REACH - HT / 2, 0.0, -SHANK + BARB)  # top of the barb: the reference point
HOOK_DROP = WRIST + SHANK     # from the arm's height down to the foot's underside

# --- the world ------------------------------------------------------------------------------------
# The wicket stands on the floor with its crossbar along the x axis (radial, seen from the robot), so
# the hook, hanging at radius RHO with its foot pointing along +y (counter-clockwise), comes out of
# the hoop by turning the arm clockwise about the column.
RHO = 0.65                   # radius of the hook's shank axis, and of the hoop's centre
BAR = 0.03                   # wicket bar thickness
HOOP_W = 0.26                # inner width of the hoop (between the legs, along x)
START_FOOT = 0.14            # at the start, the arm is this far above its lowest position
CATCH = 0.012                # and the barb's top this high above the crossbar's underside
SHANK_GAP = 0.075            # and the shank this far in front of the crossbar
BIG = ((0.74 * math.cos(math.radians(-62)), 0.74 * math.sin(math.radians(-62))), 0.18)
# the large cylinder: centre (x, y), radius; full height
GOAL = (math.radians(-118.0), 0.74, math.radians(-118.0) + math.pi / 2, 1.0, 0.0, 0.62)
# the goal: wrist angle and distance, tool yaw, elbow sign, base yaw, slide


def ik(px, py, tool_yaw, elbow_sign=1.0, base_yaw=0.0):
    """Joint values putting the wrist axis at (px, py) with the tool turned to tool_yaw."""
    d2 = px * px + py * py
    c2 = (d2 - L1 * L1 - L2 * L2) / (2 * L1 * L2)
    t2 = elbow_sign * math.acos(max(-1.0, min(1.0, c2)))
    a1 = math.atan2(py, px) - math.atan2(L2 * math.sin(t2), L1 + L2 * math.cos(t2))
    shoulder = a1 - base_yaw
    wrist = tool_yaw - a1 - t2
    return base_yaw, shoulder, t2, wrist


def box(center, size):
    return {"box": {"center": list(center), "size": list(size)}}


def fmt(x):
    s = f"{x:.6f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def flow(v):
    if isinstance(v, dict):
        return "{" + ", ".join(f"{k}: {flow(x)}" for k, x in v.items()) + "}"
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(flow(x) for x in v) + "]"
    if isinstance(v, float):
        return fmt(v)
    return str(v)


def main():
    foot_z = SLIDE[0] - HOOK_DROP + START_FOOT   # the foot's underside at the start
    top = foot_z + BARB - CATCH                 # crossbar underside
    legs_x = HOOP_W / 2 + BAR / 2
    obstacles = [
        ("wicket: inner leg", box((RHO - legs_x, 0.0, top / 2), (BAR, BAR, top))),
        ("wicket: outer leg", box((RHO + legs_x, 0.0, top / 2), (BAR, BAR, top))),
        ("wicket: crossbar", box((RHO, 0.0, top + BAR / 2), (HOOP_W + 2 * BAR, BAR, BAR))),
        ("the large obstacle (full height)",
         {"cylinder": {"center": [BIG[0][0], BIG[0][1], 0.6], "radius": BIG[1], "length": 1.2}}),
    ]
    # Start: the shank just before the crossbar (clockwise of it), the foot under it, the barb up behind it.
    ang = -(BAR / 2 + SHANK_GAP + HT / 2) / RHO
    start = list(ik(RHO * math.cos(ang), RHO * math.sin(ang), ang + math.pi / 2))
    start.insert(1, SLIDE[0] + START_FOOT)
    # Goal: beyond the cylinder, seen from the wicket.
    gang, gdist, gtool, gsign, gyaw, gslide = GOAL
    goal = list(ik(gdist * math.cos(gang), gdist * math.sin(gang), gtool, elbow_sign=gsign, base_yaw=gyaw))
    goal.insert(1, gslide)

    lines = [
        "# SCARA wicket (5-DOF SCARA arm, Hwang & Ahuja-like): unhook a J-hook from a wicket, then swing",
        "# round a large cylinder to the far side. Made by scripts/make_scara_wicket.py; see docs/problem-format.md.",
        "name: SCARA wicket",
        "description: >-",
        f"  A J-hook threaded through a wicket (hoop {fmt(HOOP_W)} wide, crossbar {fmt(top)} high); lower it until",
        "  the barb clears the crossbar, draw it out, lift, and fold past the large cylinder to the goal.",
        "bounds: {min: [-1.1, -1.1, -0.05], max: [1.1, 1.1, 1.05]}",
        "resolution: 0.001            # edge-check step = 0.1 % of the space's extent",
        "world:",
        "  obstacles:",
    ]
    for note, item in obstacles:
        lines.append(f"    - {flow(item)}   # {note}")
    lines += [
        "robot:",
        "  type: scara",
        "  base: [0, 0, 0]",
        "  column_height: 1.0",
        f"  upper_arm: {fmt(L1)}",
        f"  forearm: {fmt(L2)}",
        f"  link_radius: {fmt(R)}",
        f"  wrist_length: {fmt(WRIST)}",
        f"  slide: {flow(list(SLIDE))}",
        f"  limits: {flow([list(l) for l in LIMITS])}   # base yaw, shoulder, elbow, wrist",
        "  tool:                        # the J-hook, in the flange frame: shank, foot, barb",
    ]
    for c, s in TOOL:
        lines.append(f"    - {flow(box(c, s))}")
    lines += [
        f"  tip: {flow(list(TIP))}        # top of the barb",
        "seeds:                         # (base yaw, slide, shoulder, elbow, wrist)",
        f"  - {flow(start)}   # hook threaded through the wicket",
        f"  - {flow(goal)}   # behind the large cylinder",
        "defaults:",
        "  planner: prm",
        "  time_limit: 60",
        "  node_limit: 50000",
    ]
    OUT.write_text("\n".join(lines) + "\n")
    print("wrote", OUT)


if __name__ == "__main__":
    main()
