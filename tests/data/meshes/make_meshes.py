#!/usr/bin/env python3
"""Writes the small test meshes of tests/data/meshes (known vertex counts and bounds).

Run from this directory: python3 make_meshes.py. The files are committed; the script documents them.
"""

BOX = [(0, 0, 0), (2, 0, 0), (2, 1, 0), (0, 1, 0), (0, 0, 0.5), (2, 0, 0.5), (2, 1, 0.5), (0, 1, 0.5)]
# Six quads, outward-facing (counter-clockwise seen from outside): the loader must triangulate them.
BOX_QUADS = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
TETRA = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TETRA_FACES = [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)]


def write_obj():
    with open("box.obj", "w") as f:
        f.write("# 2 x 1 x 0.5 box made of quads: 8 vertices, 12 triangles once triangulated\n")
        for v in BOX:
            f.write("v %g %g %g\n" % v)
        for q in BOX_QUADS:
            f.write("f %d %d %d %d\n" % tuple(i + 1 for i in q))


def write_stl():
    with open("tetra.stl", "w") as f:
        f.write("solid tetra\n")
        for face in TETRA_FACES:
            f.write(" facet normal 0 0 0\n  outer loop\n")
            for i in face:
                f.write("   vertex %g %g %g\n" % TETRA[i])
            f.write("  endloop\n endfacet\n")
        f.write("endsolid tetra\n")


def write_ply():
    with open("tetra.ply", "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n")
        for v in TETRA:
            f.write("%g %g %g\n" % tuple(3 * c for c in v))  # scaled by 3: bounds [0, 3]^3
        for face in TETRA_FACES:
            f.write("3 %d %d %d\n" % face)


def write_dae():
    # The box (x 2, up 3, depth 1) in a Y-up file, under a node translated by (10, 0, 0) inside a
    # parent node translated by (0, 5, 0) (Y up: 5 upwards). Z-up result: x [10, 12], y [-1, 0], z [5, 8].
    pts = [(x * 2, y * 3, z * 1) for (x, y, z) in [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
                                                    (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]]
    tris = []
    for q in [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]:
        tris += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
    positions = " ".join("%g %g %g" % p for p in pts)
    indices = " ".join("%d %d %d" % t for t in tris)
    with open("box_yup.dae", "w") as f:
        f.write(f"""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
  <library_geometries>
    <geometry id="box-mesh" name="box">
      <mesh>
        <source id="box-positions">
          <float_array id="box-positions-array" count="24">{positions}</float_array>
          <technique_common>
            <accessor source="#box-positions-array" count="8" stride="3">
              <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
            </accessor>
          </technique_common>
        </source>
        <vertices id="box-vertices"><input semantic="POSITION" source="#box-positions"/></vertices>
        <triangles count="12"><input semantic="VERTEX" source="#box-vertices" offset="0"/><p>{indices}</p></triangles>
      </mesh>
    </geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="Scene" name="Scene">
      <node id="parent" name="parent">
        <matrix>1 0 0 0 0 1 0 5 0 0 1 0 0 0 0 1</matrix>
        <node id="box" name="box">
          <matrix>1 0 0 10 0 1 0 0 0 0 1 0 0 0 0 1</matrix>
          <instance_geometry url="#box-mesh"/>
        </node>
      </node>
    </visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#Scene"/></scene>
</COLLADA>
""")


if __name__ == "__main__":
    write_obj()
    write_stl()
    write_ply()
    write_dae()
    with open("not_a_mesh.stl", "w") as f:  # for the loader's error test
        f.write("garbage\n")
