#!/usr/bin/env python3
"""Writes the meshes of our OMPL.app-style problems (run from this directory; outputs are committed).

gap_planar_env.dae  2-D world: unit-cube prisms placed and stretched by COLLADA node matrices
                    (Z_UP as SketchUp writes it: nodes pre-turned against assimp's Z_UP
                    rotation; thickness 0.2): a wall across x = 0 with a 1.6-wide gap, plus two blocks.
l_planar_robot.obj  2-D robot: an L of two extruded rectangles, deliberately off-centre (the loader
                    re-centres it on its vertex mean, as OMPL.app does).
cage_env.stl        3-D world: floor, ceiling and a dividing wall with a square window, in [0, 10]^3.
rod_robot.obj       3-D robot: a 1.2 x 0.3 x 0.3 rod centred at (5, 5, 5) in its file.
"""

CUBE = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)]  # index = x + 2y + 4z
# Outward-facing triangles of the unit cube.
CUBE_TRIS = [(0, 2, 3), (0, 3, 1), (4, 5, 7), (4, 7, 6), (0, 1, 5), (0, 5, 4),
             (1, 3, 7), (1, 7, 5), (3, 2, 6), (3, 6, 7), (2, 0, 4), (2, 4, 6)]


def box(lo, hi):
    pts = [tuple(lo[i] + c[i] * (hi[i] - lo[i]) for i in range(3)) for c in CUBE]
    return pts, CUBE_TRIS


def write_obj(name, boxes):
    with open(name, "w") as f:
        base = 1
        for lo, hi in boxes:
            pts, tris = box(lo, hi)
            for p in pts:
                f.write("v %g %g %g\n" % p)
            for t in tris:
                f.write("f %d %d %d\n" % tuple(base + i for i in t))
            base += len(pts)


def write_stl(name, boxes):
    with open(name, "w") as f:
        f.write("solid %s\n" % name)
        for lo, hi in boxes:
            pts, tris = box(lo, hi)
            for t in tris:
                f.write(" facet normal 0 0 0\n  outer loop\n")
                for i in t:
                    f.write("   vertex %g %g %g\n" % pts[i])
                f.write("  endloop\n endfacet\n")
        f.write("endsolid %s\n" % name)


def write_dae(name, boxes):
    pts, tris = box((0, 0, 0), (1, 1, 1))
    nodes = []
    for k, (lo, hi) in enumerate(boxes):
        s = [hi[i] - lo[i] for i in range(3)]
        # assimp (and so OMPL.app) turns a Z_UP scene by (x, y, z) -> (x, z, -y) at its root, as
        # SketchUp's exports expect: store each node pre-turned by the inverse, (x, y, z) ->
        # (x, -z, y), so that the prisms come out standing in z.
        m = "%g 0 0 %g 0 0 %g %g 0 %g 0 %g 0 0 0 1" % (s[0], lo[0], -s[2], -lo[2], s[1], lo[1])
        nodes.append('      <node id="b%d"><matrix>%s</matrix><instance_geometry url="#cube"/></node>' % (k, m))
    with open(name, "w") as f:
        f.write("""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_geometries>
    <geometry id="cube"><mesh>
      <source id="cube-pos"><float_array id="cube-pos-array" count="24">%s</float_array>
        <technique_common><accessor source="#cube-pos-array" count="8" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common></source>
      <vertices id="cube-vtx"><input semantic="POSITION" source="#cube-pos"/></vertices>
      <triangles count="12"><input semantic="VERTEX" source="#cube-vtx" offset="0"/><p>%s</p></triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes><visual_scene id="Scene">
%s
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#Scene"/></scene>
</COLLADA>
""" % (" ".join("%g %g %g" % p for p in pts), " ".join("%d %d %d" % t for t in tris), "\n".join(nodes)))


if __name__ == "__main__":
    t = 0.2  # prism thickness
    write_dae("gap_planar_env.dae", [((-0.5, -10, 0), (0.5, -0.8, t)), ((-0.5, 0.8, 0), (0.5, 10, t)),
                                      ((-6, 2, 0), (-3, 5, t)), ((3, -5, 0), (6, -2, t))])
    write_obj("l_planar_robot.obj", [((10, 10, 0), (11.2, 10.3, t)), ((10, 10.3, 0), (10.3, 11.0, t))])
    write_stl("cage_env.stl", [((0, 0, 0), (10, 10, 0.5)), ((0, 0, 9.5), (10, 10, 10)),
                               ((4.8, 0, 0.5), (5.2, 10, 4)), ((4.8, 0, 6), (5.2, 10, 9.5)),
                               ((4.8, 0, 4), (5.2, 4, 6)), ((4.8, 6, 4), (5.2, 10, 6))])
    write_obj("rod_robot.obj", [((4.4, 4.85, 4.85), (5.6, 5.15, 5.15))])
