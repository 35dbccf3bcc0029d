#include "amp/bench/merge.hpp"

#include <fstream>
#include <memory>

#include <nlohmann/json.hpp>

#include "amp/bench/experiment.hpp"
#include "amp/bench/outputs.hpp"
#include "amp/bench/runs_csv.hpp"
#include "amp/bench/shard.hpp"
#include "amp/core/error.hpp"

namespace amp::bench {

namespace {

nlohmann::json read_manifest(const std::filesystem::path& dir) {
  const auto file = dir / "manifest.json";
  std::ifstream in(file);
  if (!in) throw Error("merge: '" + dir.string() + "' holds no results of amp bench (no manifest.json)");
  try {
    return nlohmann::json::parse(in);
  } catch (const std::exception&) {
    throw Error("merge: " + file.string() + " is not valid JSON");
  }
}

}  // namespace

std::size_t merge_results(const std::vector<std::filesystem::path>& dirs, const std::filesystem::path& out, bool force,
                          bool ompl_log) {
  if (dirs.empty()) throw Error("merge: no shard directories given");
  std::vector<nlohmann::json> manifests;
  for (const auto& d : dirs) manifests.push_back(read_manifest(d));
  const std::string fingerprint = manifests[0].value("fingerprint", "");
  for (std::size_t i = 1; i < dirs.size(); ++i) {
    if (manifests[i].value("fingerprint", "") != fingerprint) {
      throw Error("merge: '" + dirs[i].string() + "' holds results of another experiment than '" + dirs[0].string() +
                  "' (" + manifests[i].value("experiment", "?") + " vs " + manifests[0].value("experiment", "?") +
                  ", or the same experiment with other settings or problem files)");
    }
  }
  Experiment e = load_experiment(manifests[0].value("experiment_file", ""));
  // The shards may have run with --runs / --time-limit overrides: they are in the manifest.
  e.runs = manifests[0].value("runs", e.runs);
  e.time_limit_s = manifests[0].value("time_limit_s", e.time_limit_s);
  e.fingerprint = experiment_fingerprint(e);
  if (e.fingerprint != fingerprint) {
    throw Error("merge: the experiment file " + e.file.string() + " or its problems changed since the shards ran");
  }
  // Shard i of N sits at position i, so that trial t is the next row of shard t mod N.
  std::vector<std::filesystem::path> by_index;
  std::size_t count = 0;
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    const Shard s = parse_shard(manifests[i].value("shard", ""));
    if (i == 0) {
      count = s.count;
      by_index.resize(count);
    }
    if (s.count != count) throw Error("merge: '" + dirs[i].string() + "' is a shard of " + s.to_string() + ", others of /" + std::to_string(count));
    if (!by_index[s.index].empty()) throw Error("merge: shard " + s.to_string() + " is given twice");
    by_index[s.index] = dirs[i];
  }
  for (std::size_t i = 0; i < count; ++i) {
    if (by_index[i].empty()) throw Error("merge: shard " + Shard{i, count}.to_string() + " is missing");
  }

  std::error_code ec;
  if (std::filesystem::exists(out, ec) && !std::filesystem::is_directory(out, ec)) {
    throw Error("--out: '" + out.string() + "' is a file, expected a directory");
  }
  if (std::filesystem::is_directory(out, ec) && !std::filesystem::is_empty(out, ec) && !force) {
    throw Error("--out: directory '" + out.string() + "' is not empty (use --force to overwrite)");
  }
  std::filesystem::create_directories(out, ec);
  std::vector<std::unique_ptr<RunsCsvReader>> readers;
  for (const auto& d : by_index) readers.push_back(std::make_unique<RunsCsvReader>(d / "runs.csv", e));
  std::size_t written = 0;
  {
    RunsCsvWriter writer(out / "runs.csv", e, false);
    Trial t;
    for (std::size_t i = 0; i < e.trial_count(); ++i) {
      const std::size_t s = i % count;
      if (!readers[s]->next(t) || t.id.index != i) {
        throw Error("merge: shard " + Shard{s, count}.to_string() + " (" + by_index[s].string() +
                    ") is incomplete or out of order at trial " + std::to_string(i) + "; finish it with --resume");
      }
      writer.add(t);
      ++written;
    }
    writer.finish();
  }
  nlohmann::json manifest = manifests[0];
  manifest["shard"] = Shard{}.to_string();
  manifest["merged_from"] = count;
  std::ofstream(out / "manifest.json") << manifest.dump(2) << '\n';
  write_outputs(e, out, current_run_info(1), ompl_log);
  return written;
}

}  // namespace amp::bench
