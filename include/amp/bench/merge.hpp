#pragma once
#include <filesystem>
#include <vector>

namespace amp::bench {

// Combines the result directories of the shards i/N (i = 0..N-1) of one experiment into `out`, with
// the same outputs as one process would have written. Refuses, with the reason, shards of different
// experiments (or of an experiment changed since), a missing or duplicated shard, an incomplete
// shard, and a non-empty `out` without `force`. Returns the number of trials merged.
std::size_t merge_results(const std::vector<std::filesystem::path>& shard_dirs, const std::filesystem::path& out,
                          bool force, bool ompl_log);

}  // namespace amp::bench
