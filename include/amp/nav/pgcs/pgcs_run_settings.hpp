#pragma once
#include <string>

#include "amp/core/settings_schema.hpp"

namespace amp::nav {

// How a PGCS session explores and answers queries; lengths are in robot radii, so one setting
// suits a Khepera in a maze and a wheelchair in an office.
struct PgcsRunSettings {
  long steps = 200000;                       // exploration steps (simulator time steps)
  int queries = 100;                         // random query pairs after exploring
  int curve_points = 100;                    // samples of the curves over the exploration
  std::string exploration = "random-walk";   // random-walk | novelty
  double speed = 0.4;                        // radii per time step
  double turn_every = 50.0;                  // random walk: mean steps between heading changes
  double avoid_distance = 0.5;               // radii: a sensor reading below this turns the walk
  double sensor_range = 1.5;                 // radii beyond the rim
  double sensor_noise = 0.01;                // radii (standard deviation)
  double turn_weight = 1.0;                  // route cost per radian turned, in radii
  double prior_weight = 1.0;                 // route cost per unit of log(mean prior / prior), in radii
  int attach = 3;                            // start and target join this many nearest centres
  int max_replans = 100;                     // a query gives up after this many replans (a safety net)
  double block_distance = 0.5;               // radii: a sensor reading ahead below this is a block
  // Radii a leg may slide off its line past a block (StraightLegSettings::detour). 4: legs that
  // graze a door frame get through; queries solved with 0 against 4 (6 seeds): office 97.5% and
  // 99.2%, MovingAI rooms (novelty walk, l = 50,000, M = 300) 39% and 70%.
  double detour = 4.0;
  // Blocks before an edge is illegal (EdgeMemory); 2: a blocked edge stays a last resort once (a
  // leg that clipped a door frame cut whole rooms off the MovingAI rooms map with 1).
  int strikes = 2;
  double suspect_weight = 100.0;             // extra route cost per length of an edge blocked, not yet illegal
  bool retreat = true;                       // after a block, drive back the way the leg came, then replan
  double reference_cell = 0.0;               // m, the reference grid's cell; 0: longer side / 256
  bool portals = true;                       // drive an edge through where the explorer crossed it (EdgePortals)
  double unverified_weight = 1.0;            // extra route cost per length of an edge never seen crossed
  bool exemplars = true;                     // drive to each cluster's exemplar, not to its centre
  bool shortcuts = true;                     // between two portals, cut across the cell (not via its point)
  // Drive a route along the positions the robot has stood at in its clusters' cells (TraceCorridor),
  // falling back to the legs above when they do not join.
  bool trace_legs = true;
  static const core::SettingsSchema<PgcsRunSettings>& schema();
  void validate() const { schema().validate(*this); }
};

}  // namespace amp::nav
