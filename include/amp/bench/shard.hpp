#pragma once
#include <cstddef>
#include <string>

namespace amp::bench {

// A deterministic 1/N of an experiment's trials: trial i belongs to shard i mod N, so every shard
// gets a share of every problem and planner (balanced load for Slurm job arrays and MPI ranks).
struct Shard {
  std::size_t index = 0;
  std::size_t count = 1;

  bool owns(std::size_t trial) const { return trial % count == index; }
  std::string to_string() const { return std::to_string(index) + "/" + std::to_string(count); }
  friend bool operator==(const Shard&, const Shard&) = default;
};

// Parses "i/N" with 0 <= i < N; throws ParameterError otherwise ("3/2", "1/0", "x").
Shard parse_shard(const std::string& text);

}  // namespace amp::bench
