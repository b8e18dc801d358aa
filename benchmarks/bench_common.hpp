// Helpers shared by the benchmark programs: quantiles of timing samples and a description
// of the machine for the header of each table and CSV. Linux only (/proc); elsewhere the
// machine reads "unknown".
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace mink_bench {

/// The q-quantile of v by linear interpolation between order statistics; NaN if v is empty.
inline double quantile(std::vector<double> v, double q) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const double pos = q * (v.size() - 1);
  const std::size_t i = static_cast<std::size_t>(pos);
  const double f = pos - i;
  return i + 1 < v.size() ? v[i] * (1 - f) + v[i + 1] * f : v[i];
}

/// The "model name" line of /proc/cpuinfo.
inline std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto c = line.find(':');
      if (c != std::string::npos) return line.substr(c + 2);
    }
  }
  return "unknown";
}

/// The 1, 5 and 15 minute load averages of /proc/loadavg.
inline std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return in ? a + " " + b + " " + c : std::string("unknown");
}

/// "<cpu model>, <n> hardware threads".
inline std::string machineLine() {
  std::ostringstream o;
  o << cpuModel() << ", " << std::thread::hardware_concurrency() << " hardware threads";
  return o.str();
}

}  // namespace mink_bench
