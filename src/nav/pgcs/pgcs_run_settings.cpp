#include "amp/nav/pgcs/pgcs_run_settings.hpp"

namespace amp::nav {

const core::SettingsSchema<PgcsRunSettings>& PgcsRunSettings::schema() {
  using S = PgcsRunSettings;
  static const core::SettingsSchema<S> schema(
      "pgcs",
      {core::integer_field<S>("steps", &S::steps, 1, 1e10, "exploration steps"),
       core::integer_field<S>("queries", &S::queries, 0, 1e6, "random query pairs after exploring"),
       core::integer_field<S>("curve_points", &S::curve_points, 1, 1e5, "samples of the exploration curves"),
       core::choice_field<S>("exploration", &S::exploration, {"random-walk", "novelty"},
                             "random-walk (the paper) or novelty (heads for the least visited clear direction)"),
       core::real_field<S>("speed", &S::speed, 1e-3, 1, "robot radii per time step"),
       core::real_field<S>("turn_every", &S::turn_every, 1, 1e9, "random walk: mean steps between turns"),
       core::real_field<S>("avoid_distance", &S::avoid_distance, 0, 100, "radii: a closer reading ahead turns the walk"),
       core::real_field<S>("sensor_range", &S::sensor_range, 1e-3, 100, "radii beyond the rim"),
       core::real_field<S>("sensor_noise", &S::sensor_noise, 0, 10, "radii, standard deviation of a reading"),
       core::real_field<S>("turn_weight", &S::turn_weight, 0, 1e6, "route cost per radian turned, in radii"),
       core::real_field<S>("prior_weight", &S::prior_weight, 0, 1e6, "route cost per log(mean prior / prior), radii"),
       core::integer_field<S>("attach", &S::attach, 1, 64, "start and target join this many nearest centres"),
       core::integer_field<S>("max_replans", &S::max_replans, 0, 1e6, "a query gives up after this many replans"),
       core::real_field<S>("block_distance", &S::block_distance, 0, 100, "radii: a closer reading ahead is a block"),
       core::real_field<S>("reference_cell", &S::reference_cell, 0, 1e9,
                           "m, cell of the reference grid (0: longer side / 256)"),
       core::real_field<S>("detour", &S::detour, 0, 1e6,
                           "radii a leg may slide off its line past what blocks it (0: stop at the first block)"),
       core::integer_field<S>("strikes", &S::strikes, 1, 1000,
                              "blocks before an edge is illegal (1: the paper; more: a suspect edge is a last resort first)"),
       core::real_field<S>("suspect_weight", &S::suspect_weight, 0, 1e9,
                           "extra route cost per length of an edge blocked fewer than `strikes` times"),
       core::bool_field<S>("retreat", &S::retreat, "after a block, drive back the way the leg came before replanning"),
       core::bool_field<S>("portals", &S::portals,
                           "drive an edge through where the explorer crossed between its clusters"),
       core::real_field<S>("unverified_weight", &S::unverified_weight, 0, 1e6,
                           "extra route cost per length of an edge the explorer never crossed (needs portals)"),
       core::bool_field<S>("exemplars", &S::exemplars,
                           "drive to the visited position nearest each centre instead of the centre"),
       core::bool_field<S>("shortcuts", &S::shortcuts,
                           "between two portals, cut across the cell instead of through its point"),
       core::bool_field<S>("trace_legs", &S::trace_legs,
                           "drive a route along where the robot has stood in its clusters' cells")});
  return schema;
}

}  // namespace amp::nav
