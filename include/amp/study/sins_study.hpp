#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "amp/learn/case_library.hpp"
#include "amp/learn/splitting_cases.hpp"
#include "amp/nav/sins/clutter_world.hpp"
#include "amp/nav/sins/motor_schemas.hpp"
#include "amp/nav/sins/sins_run.hpp"

namespace amp::study {

// One `amp sins` run: the settings read from the command line.
struct SinsSetup {
  std::string system = "adaptive";  // the system whose result is printed
  nav::SinsSettings sins;
  learn::CaseSettings cases;
  learn::SplittingCaseSettings plus;  // sins-plus's (its max_cases is the cases' max_cases)
  nav::SchemaParameters initial = nav::SchemaParameters::middle();  // the static system's, where SINS starts
  std::uint64_t seed = 1;
  std::function<void(int done, int total)> progress;  // worlds driven, over every system run
};

// One system over the sequence.
struct SystemRun {
  std::string system;
  std::vector<nav::WorldOutcome> worlds;
  nav::Estimators estimators;
  int cases = 0;
  nav::WorldTrace last_trace;  // the last world's, as driven in the sequence
};

struct SinsResult {
  // The sequence every system meets: world i of ClutterWorldSequence(seed, settings.world), the
  // clutter switched at change_at (as nav::run_sequence draws it).
  std::vector<nav::ClutterWorld> worlds;
  int rejected_worlds = 0;
  std::vector<SystemRun> runs;    // the chosen system first, then (all_systems) the other two
  nlohmann::ordered_json record;  // the chosen system's flat record (what --json prints)
};

// The settings from parameters by their schema names (SinsSettings, SchemaParameters, CaseSettings,
// SplittingCaseSettings; `amp sins --param`, Python's params=) at `scale` (its step limit and radii
// unless given, its box), through core::route_params; the rest of `setup` is left as it is. Throws
// ParameterError (one line, no option named) for an unknown name or a bad value.
void read_sins_params(const core::ParamMap& params, const nav::SinsScale& scale, SinsSetup& setup);

// Draws the worlds once (nav::draw_sequence_worlds; a clutter no world can be drawn at is reported
// naming --clutter, or --param clutter_after after the change), then runs nav::run_sequence over
// them for the chosen system, and with `all_systems` for the paper's other two as well, keeping the
// last world's trace.
SinsResult run_sins(const SinsSetup& setup, bool all_systems);

// The files `-o DIR` gets, in the order they are written.
const std::vector<std::string>& sins_output_files();
// Refuses (before any work) a DIR that is a file, or one of its files that exists, unless `force`.
void check_sins_dir(const std::filesystem::path& dir, bool force, const std::string& option);
// record.json: the flat record, the settings, each system's estimators and every world's outcome.
nlohmann::ordered_json sins_record(const SinsSetup& setup, const SinsResult& result);
// Writes record.json, learning.svg (Figure 5) and run.svg (Figure 4) into `dir` (created if missing).
void write_sins_outputs(const SinsSetup& setup, const SinsResult& result, const std::filesystem::path& dir);

// The flat record as a two-column table (what `amp sins` prints without --json).
std::string format_sins_table(const nlohmann::ordered_json& record);
// The systems side by side (final estimators), what `amp sins -o DIR` prints after the record.
std::string format_sins_comparison(const SinsResult& result);

}  // namespace amp::study
