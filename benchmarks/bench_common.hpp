// Helpers shared by the benchmark programs: quantiles of timing samples, a description
// of the machine for the header of each table and CSV, the two clocks, and a runner that
// does work in a child process stopped after a wall-time limit. POSIX (fork, pipe,
// CLOCK_THREAD_CPUTIME_ID); the machine line reads /proc and is "unknown" elsewhere.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

namespace mink_bench {

/// An argument that no option of a benchmark's parser took: returned when it is a path;
/// "--help" / "-h" print the usage and end the program (status 0); any other argument
/// starting with '-' (an unknown option, or one missing its value) is an error that names
/// it, prints the usage and ends the program with status 2 (it used to be taken as the
/// output path).
inline const char* pathArgument(const char* arg, const char* usage) {
  if (arg[0] != '-') return arg;
  const bool help = std::strcmp(arg, "--help") == 0 || std::strcmp(arg, "-h") == 0;
  if (!help) std::fprintf(stderr, "unknown option or missing value: %s\n", arg);
  std::fprintf(help ? stdout : stderr, "%s\n", usage);
  std::exit(help ? 0 : 2);
}

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

/// CPU time of the calling thread, ms (CLOCK_THREAD_CPUTIME_ID: on a shared machine it
/// leaves out the time the thread waited for a core).
inline double threadCpuMs() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

/// Monotonic wall time, ms.
inline double wallMs() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// Runs work(emit) in a child process stopped after timeoutS seconds of wall time; returns
/// the records emitted before that, in order. `finished` tells whether the child ran to its
/// end. childCpuMs: the CPU time the child used in all (a lower bound on an unfinished
/// call's time when no record came back). Record is plain data of at most 512 bytes, so
/// each write to the pipe is atomic (PIPE_BUF >= 512 by POSIX).
template <class Record>
std::vector<Record> inChild(double timeoutS, const std::function<void(const std::function<void(const Record&)>&)>& work,
                            bool& finished, double* childCpuMs = nullptr) {
  static_assert(std::is_trivially_copyable<Record>::value, "a record crosses the pipe as bytes");
  static_assert(sizeof(Record) <= 512, "a record must be written atomically (PIPE_BUF)");
  std::vector<Record> out;
  finished = false;
  rusage ru{};
  int fd[2];
  if (pipe(fd) != 0) return out;
  const pid_t pid = fork();
  if (pid < 0) return out;
  if (pid == 0) {
    close(fd[0]);
    work([&](const Record& r) {
      if (write(fd[1], &r, sizeof r) != static_cast<ssize_t>(sizeof r)) _exit(1);
    });
    _exit(0);
  }
  close(fd[1]);
  const double w0 = wallMs();
  int status = 0;
  bool done = false;
  // Drain the pipe while waiting, so that a child with many records never blocks.
  fcntl(fd[0], F_SETFL, O_NONBLOCK);
  Record r;
  auto drain = [&] {
    while (read(fd[0], &r, sizeof r) == static_cast<ssize_t>(sizeof r)) out.push_back(r);
  };
  while (wallMs() - w0 < timeoutS * 1e3) {
    drain();
    if (wait4(pid, &status, WNOHANG, &ru) == pid) {
      done = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (!done) {
    kill(pid, SIGKILL);
    wait4(pid, &status, 0, &ru);
  }
  if (childCpuMs)
    *childCpuMs = (ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) * 1e3 + (ru.ru_utime.tv_usec + ru.ru_stime.tv_usec) * 1e-3;
  drain();
  close(fd[0]);
  finished = done && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  return out;
}

}  // namespace mink_bench
