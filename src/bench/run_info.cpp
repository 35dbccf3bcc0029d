#include <unistd.h>

#include <array>
#include <chrono>
#include <ctime>
#include <fstream>
#include <string>
#include <thread>

#include "amp/core/version.hpp"
#include "amp/bench/trial_sink.hpp"

namespace amp::bench {

namespace {

constexpr std::size_t kHostNameMax = 256;

std::string host_name() {
  std::array<char, kHostNameMax + 1> buf{};
  if (gethostname(buf.data(), kHostNameMax) != 0) return "UNKNOWN";
  return std::string(buf.data());
}

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

// "<model name> (<n> logical cores)" from /proc/cpuinfo; other systems give the core count only.
std::string cpu_description() {
  std::string model;
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; model.empty() && std::getline(in, line);) {
    const auto colon = line.find(':');
    if (colon != std::string::npos && trim(line.substr(0, colon)) == "model name") model = trim(line.substr(colon + 1));
  }
  const unsigned cores = std::thread::hardware_concurrency();
  return (model.empty() ? std::string("unknown CPU") : model) + " (" + std::to_string(cores) + " logical cores)";
}

std::string utc_now_iso8601() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  std::array<char, 32> buf{};
  std::strftime(buf.data(), buf.size(), "%Y-%m-%dT%H:%M:%SZ", &tm);
  return std::string(buf.data());
}

}  // namespace

RunInfo current_run_info(int threads) {
  RunInfo info;
  info.hostname = host_name();
  info.cpu_info = cpu_description();
  info.date = utc_now_iso8601();
  info.version = std::string("AMP ") + core::kVersion;
  info.threads = threads;
  return info;
}

}  // namespace amp::bench
