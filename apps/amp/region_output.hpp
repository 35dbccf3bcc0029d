#pragma once
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "amp/roadmap/uas/uas_regions.hpp"

namespace amp::world {
struct Problem;
}

namespace amp::cli {

// The paper's Tables 1-3 for one model: per cluster size %, visibility mean, std, min, max, and the box.
void print_region_table(const world::Problem& problem, const roadmap::RegionModel& model, std::uint64_t cd_calls);
nlohmann::json region_json(const roadmap::RegionModel& model, std::uint64_t cd_calls);
// The training roadmap coloured by cluster, with the region boxes, over the world (SVG).
void draw_regions(const world::Problem& problem, const roadmap::RegionModel& model, const std::string& file);

}  // namespace amp::cli
