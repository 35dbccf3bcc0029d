#pragma once
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "amp/core/run_record.hpp"

namespace amp::bench {

// The run record as JSON (every field, extras under "extra").
nlohmann::json to_json(const core::RunRecord& r);
// The run record as an aligned two-column table for people.
std::string format_table(const core::RunRecord& r);

}  // namespace amp::bench
