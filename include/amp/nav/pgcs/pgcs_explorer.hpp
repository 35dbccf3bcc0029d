#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "amp/core/rng.hpp"
#include "amp/learn/pgcs.hpp"
#include "amp/nav/nav_task.hpp"
#include "amp/nav/pgcs/edge_portals.hpp"
#include "amp/nav/pgcs/pgcs_run_settings.hpp"
#include "amp/nav/random_walk.hpp"

namespace amp::nav {

class Simulator;
class TraceCorridor;

// The online growth of a PGCS session (Vlassis, Papakonstantinou & Tsanakas, section 3): a disc
// robot driven by an exploration strategy streams its positions into learn::Pgcs. Alongside, the
// explorer notes when each cluster was born, the position nearest each centre the robot has stood
// at (the cluster's exemplar), and where the robot crossed from one cluster's cell into another's
// (EdgePortals): what routes on the learned graph drive to and through.
class PgcsExplorer {
 public:
  // `rng`: the exploration's own stream. Throws ParameterError for bad PGCS settings.
  PgcsExplorer(const NavTask& task, const PgcsRunSettings& run, learn::PgcsSettings pgcs, core::Rng rng);
  // Not copied or moved: the novelty walk asks this explorer's clusters.
  PgcsExplorer(const PgcsExplorer&) = delete;
  PgcsExplorer& operator=(const PgcsExplorer&) = delete;

  // One step of the exploration strategy: the robot moves in `simulator`, the clusters learn where
  // it went, and `corridor` marks the move.
  void step(Simulator& simulator, TraceCorridor& corridor);
  // Exemplars from the kept positions, once per step of the clusters, when exemplars are on.
  void adopt_exemplars();
  // Drops the portal of the edge a-b (the way through it proved undrivable).
  void drop_portal(int a, int b);

  long steps() const { return steps_; }
  const learn::Pgcs& clusters() const { return pgcs_; }
  const EdgePortals& portals() const { return portals_; }
  // The portal of the edge a-b (null when none is known or portals are off).
  const Eigen::Vector2d* portal(int a, int b) const;
  // Where the robot drives to reach cluster k: its exemplar, or its centre when exemplars are off
  // (see PgcsSession::node_point). NaN for a cluster whose cell the robot has not entered since the
  // cluster was made.
  Eigen::Vector2d node_point(int k) const;
  // Exploration positions, one every few steps (for drawing and adopt_exemplars).
  const std::vector<Eigen::Vector2d>& positions() const { return positions_; }
  // Changes whenever node_point, portal or portals may answer differently.
  std::uint64_t revision() const { return revision_; }

 private:
  // Notes births of clusters (after PGCS's insertions and deletions) and the crossing to x.
  void track_clusters(const Eigen::Vector2d& x);
  void note_births();
  void note_exemplar(int k, const Eigen::Vector2d& p);

  bool portals_on_, exemplars_on_;
  long keep_every_;  // steps between kept positions
  learn::Pgcs pgcs_;
  EdgePortals portals_;
  RandomWalk walk_;
  core::Rng rng_;
  bool last_blocked_ = false;
  long steps_ = 0;
  std::uint64_t revision_ = 0;
  std::vector<long> born_;                 // by cluster id: the step it was (last) created
  std::vector<Eigen::Vector2d> exemplar_;  // by cluster id
  std::vector<long> exemplar_born_;        // by cluster id: born_ of the cluster the exemplar is of
  std::vector<std::uint8_t> alive_;        // by cluster id, as of the last check
  std::vector<std::uint8_t> was_alive_;
  int last_winner_ = -1;
  Eigen::Vector2d last_position_ = Eigen::Vector2d::Zero();
  long exemplars_step_ = -1;  // the clusters' step adopt_exemplars ran at
  std::vector<Eigen::Vector2d> positions_;
};

}  // namespace amp::nav
