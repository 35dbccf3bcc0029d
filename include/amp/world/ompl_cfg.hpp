#pragma once
#include <filesystem>

#include "amp/world/problem.hpp"

namespace amp::world {

// Loads an OMPL.app problem file (INI-style `.cfg`) so that its public benchmark problems run
// unchanged. Section [problem]: `robot`, `world` (mesh paths relative to the .cfg), `name`;
// start.x/y/z + start.axis.x/y/z + start.theta (axis-angle) for 3-D, start.x/y/theta for 2-D
// (2-D when start.z is absent, as OMPL.app decides); the same for goal.*; volume.min.x/y/z and
// volume.max.x/y/z (absent: the bounds of the world mesh). Other keys of [problem] are ignored.
// Planner defaults from [solver] `planner` and `time_limit` (else [benchmark] `time_limit`).
//
// As OMPL.app does, the robot mesh is re-centred on its vertex mean and only the robot's reference
// point must stay inside the volume. 3-D problems become an FCL SpatialEnvironment in SE3 (rotation
// weight = robot radius). 2-D problems (thin extruded prisms placed by the scene's nodes) are
// projected onto the plane: the triangles of non-zero projected area become polygons of a
// PlanarWorld and of a rigid PlanarRobot in SE2, so they run on the fast planar checker.
// Throws FileError naming the .cfg (and key) for malformed lines, missing keys or bad meshes.
Problem load_ompl_cfg(const std::filesystem::path& file);

}  // namespace amp::world
