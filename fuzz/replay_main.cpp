// fuzz/replay_main.cpp — a main() for the fuzz targets without libFuzzer: runs
// LLVMFuzzerTestOneInput once on each file named on the command line and prints the wall
// time it took. Linked into mink_mdd_replay and mink_mesh_replay (fuzz/CMakeLists.txt),
// built at -O2 without sanitizers, so that the time of a saved input (a slow one, before
// and after a fix) is measured as users' builds would run it; a failing check still
// aborts, as in the fuzzer.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s INPUT...\n", argv[0]);
    return 2;
  }
  for (int i = 1; i < argc; ++i) {
    std::ifstream in(argv[i], std::ios::binary);
    if (!in) {
      std::fprintf(stderr, "%s: cannot read\n", argv[i]);
      return 2;
    }
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto t0 = std::chrono::steady_clock::now();
    LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%s: %.1f ms\n", argv[i], ms);
  }
  return 0;
}
