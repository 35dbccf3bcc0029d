#pragma once

namespace amp::roadmap {

class PlannerRegistry;

// Adds the PRM variants that differ from `prm` only by their sampler, each reporting its node classes
// (cc_create, cc_merge, cc_expand, cc_oversample), its distance `sampler_d` where it has one and
// `sampler_distance_fallback` (1 when the robot has no diameter and 1% of the space extent stood in):
//   gaussian-prm  Gaussian sampling (Boor et al. 1999), d = d_scale * r unless d > 0 is given;
//   obprm         obstacle-based PRM (Amato et al. 1998);
//   bridge-prm    the bridge test (Hsu et al. 2003), bridge length d = d_scale * r, optional uniform mix.
void register_sampler_prms(PlannerRegistry& registry);

}  // namespace amp::roadmap
