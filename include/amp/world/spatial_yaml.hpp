#pragma once
#include "amp/world/problem.hpp"
#include "amp/world/yaml_fields.hpp"

namespace amp::world {

// Builds a 3-D world, robot and space from a problem file's root (start/goal are read by the
// caller). Fields (lengths in world units, rotations as quaternions [qx, qy, qz, qw]):
//
//   bounds: {min: [x, y, z], max: [x, y, z]}
//   resolution: 0.01                 # optional: edge-check step as a fraction of the space extent
//   world:
//     obstacles:                     # each item has exactly one key:
//       - box: {center: [x, y, z], size: [sx, sy, sz], rotation: [qx, qy, qz, qw]}  # rotation optional
//       - sphere: {center: [x, y, z], radius: r}
//       - cylinder: {center: [x, y, z], radius: r, length: l, rotation: [...]}        # axis = local z
//       - mesh: {file: meshes/a.stl, position: [x, y, z], rotation: [...], scale: 1.0, up: z}
//                                    # scale: a number or [sx, sy, sz]; up: y | z (default: the file's)
//   robot:
//     type: rigid3d | sphere | scara
//     shapes: [same items]           # rigid3d: solids in the body frame; state x y z qx qy qz qw
//     radius: r                      # sphere; state x y z
//     # scara (state: base yaw, slide z, shoulder, elbow, wrist yaw; see ScaraParams):
//     base: [x, y, z]                # foot of the column
//     column_height: h
//     upper_arm: l1
//     forearm: l2
//     link_radius: r                 # half-thickness of the links, radius of column and wrist
//     wrist_length: w                # optional [2 * link_radius]
//     slide: [zlo, zhi]              # arm height above the base, within [0, column_height]
//     limits: [[lo, hi] x 4]         # base yaw, shoulder, elbow, wrist yaw (radians)
//     tool: [box items]              # in the flange frame (x along the wrist yaw, z up)
//     tip: [x, y, z]                 # optional tool tip in the flange frame [lowest tool point on the axis]
//
// Spaces: rigid3d -> Se3Space(bounds, rotation weight = robot radius); sphere -> Rn (x, y, z);
// scara -> JointSpace "linkage" (revolute joints weighted by the reach they swing, slide 1).
// Throws FileError naming the file and field.
LoadedWorld parse_spatial_world(const YamlFields& root);

}  // namespace amp::world
