// mink_demo — convex polyhedra from real meshes, with every printed claim checked.
//
// For each of two meshes (a duck and a Duplo brick, from Bullet's data folder, zlib
// licence in data/LICENSE-zlib.txt) it reads the OBJ file, builds the convex hull of the
// vertices with ConvexPolyhedron<double>::fromPoints and prints:
//   counts V, E, F and Euler's V - E + F = 2; input vs hull vertex count; how many faces
//   came out of coplanar merging with more than three corners; the bounding box; support
//   vertices in the six axis directions by hill-climbing and by brute force, which must
//   agree; and how long the hull takes to build (median of several runs).
// Then it shows fromMesh: a box written to OBJ and read back, two broken boxes that are
// rejected with a message, and the duck's hull written out and validated back.
//
// Usage: mink_demo [--data DIR]   (DIR defaults to the source tree's examples/data)
// Exit status: 0 when every check holds, 1 otherwise.
#include <mink/mink.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <system_error>
#include <vector>

#ifndef MINK_EXAMPLES_DATA_DIR
#define MINK_EXAMPLES_DATA_DIR "data"
#endif

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using mink::ConvexPolyhedron;
using mink::Vec3;

int failures = 0;

void check(bool ok, const std::string& what) {
  std::printf("  [%s] %s\n", ok ? "ok" : "FAILED", what.c_str());
  if (!ok) ++failures;
}

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

template <class T>
std::vector<Vec3<T>> convert(const std::vector<Vec3<double>>& points) {
  std::vector<Vec3<T>> out;
  out.reserve(points.size());
  for (const auto& p : points) out.push_back(p.cast<T>());
  return out;
}

// Builds the hull `runs` times; returns the last hull and the median time in ms.
template <class T>
ConvexPolyhedron<T> timedHull(const std::vector<Vec3<T>>& points, int runs, double& medianMs) {
  std::vector<double> times;
  for (int r = 1; r < runs; ++r) {
    const auto start = Clock::now();
    const auto hull = ConvexPolyhedron<T>::fromPoints(points);
    times.push_back(millisecondsSince(start));
  }
  const auto start = Clock::now();
  auto hull = ConvexPolyhedron<T>::fromPoints(points);
  times.push_back(millisecondsSince(start));
  medianMs = median(times);
  return hull;
}

// Polygon loops of a polyhedron, as indices into its own vertex array.
template <class T>
std::vector<std::vector<int>> faceLoops(const ConvexPolyhedron<T>& poly) {
  std::vector<std::vector<int>> faces;
  for (int f = 0; f < poly.numFaces(); ++f) {
    const auto loop = poly.faceVertices(f);
    faces.emplace_back(loop.begin(), loop.end());
  }
  return faces;
}

void printCounts(const char* label, int v, int e, int f) {
  std::printf("  %s: V = %d, E = %d, F = %d, V - E + F = %d\n", label, v, e, f, v - e + f);
}

bool sameSupport(const ConvexPolyhedron<double>& hull, const Vec3<double>& d, int a, int b) {
  // Ties are legitimate: two vertices with the same d . x are both support vertices.
  return a == b || d.dot(hull.vertex(a)) == d.dot(hull.vertex(b));
}

void demoMesh(const fs::path& path) {
  std::printf("\n== %s\n", path.filename().string().c_str());
  const auto mesh = mink::io::readObj<double>(path);
  std::printf("  input: %zu vertices, %zu faces (%s)\n", mesh.vertices.size(), mesh.faces.size(),
              path.string().c_str());

  double buildMs = 0;
  const auto hull = timedHull(mesh.vertices, 7, buildMs);
  std::printf("  fromPoints<double>: %.3f ms (median of 7 builds)\n", buildMs);
  printCounts("hull", hull.numVertices(), hull.numEdges(), hull.numFaces());
  check(hull.numVertices() - hull.numEdges() + hull.numFaces() == 2, "Euler characteristic is 2");
  std::printf("  hull keeps %d of %zu input vertices (tolerance %.3g, extent %.3g)\n",
              hull.numVertices(), mesh.vertices.size(), hull.tolerance(), hull.extent());

  bool verticesAreInputPoints = true;
  for (int v = 0; v < hull.numVertices(); ++v) {
    verticesAreInputPoints = verticesAreInputPoints &&
                             hull.vertex(v) == mesh.vertices[static_cast<std::size_t>(hull.inputIndex(v))];
  }
  check(verticesAreInputPoints, "every hull vertex is, bit for bit, the input point it names");

  int merged = 0;
  int largest = 0;
  for (int f = 0; f < hull.numFaces(); ++f) {
    merged += hull.faceSize(f) > 3 ? 1 : 0;
    largest = std::max(largest, hull.faceSize(f));
  }
  std::printf("  faces with more than 3 corners (merged coplanar triangles): %d of %d, largest has %d\n",
              merged, hull.numFaces(), largest);

  // Bounding boxes. Hull vertices are input points, so the hull's box lies inside the
  // input's; input points the hull left out lie within about its tolerance of it.
  Vec3<double> inLo = Vec3<double>::Constant(std::numeric_limits<double>::infinity());
  Vec3<double> inHi = -inLo;
  for (const auto& p : mesh.vertices) {
    inLo = inLo.cwiseMin(p);
    inHi = inHi.cwiseMax(p);
  }
  Vec3<double> lo = Vec3<double>::Constant(std::numeric_limits<double>::infinity());
  Vec3<double> hi = -lo;
  for (const auto& p : hull.vertices()) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Vec3<double> size = hi - lo;
  std::printf("  bounding box: [%.6f, %.6f] x [%.6f, %.6f] x [%.6f, %.6f]; extents %.6f x %.6f x %.6f\n",
              lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), hi.z(), size.x(), size.y(), size.z());
  const double boxGap = std::max((lo - inLo).cwiseAbs().maxCoeff(), (hi - inHi).cwiseAbs().maxCoeff());
  std::printf("  largest gap between hull box and input box: %.3g (%.2f x tolerance)\n", boxGap,
              boxGap / hull.tolerance());

  double maxHeight = -std::numeric_limits<double>::infinity();
  for (const auto& p : mesh.vertices) {
    for (int f = 0; f < hull.numFaces(); ++f) {
      maxHeight = std::max(maxHeight, hull.faceNormal(f).dot(p) - hull.faceOffset(f));
    }
  }
  std::printf("  highest input point above a hull face plane: %.3g (%.2f x tolerance)\n", maxHeight,
              maxHeight / hull.tolerance());

  std::printf("  support vertices (hill-climb from vertex 0 | brute force):\n");
  const char* names[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
  bool axesAgree = true;
  for (int a = 0; a < 6; ++a) {
    Vec3<double> d = Vec3<double>::Zero();
    d[a / 2] = a % 2 == 0 ? 1.0 : -1.0;
    const int climbed = hull.support(d, 0);
    const int scanned = hull.supportBruteForce(d);
    const Vec3<double>& p = hull.vertex(climbed);
    const bool agree = sameSupport(hull, d, climbed, scanned);
    axesAgree = axesAgree && agree;
    std::printf("    %s: vertex %4d (input #%4d) at (% .6f, % .6f, % .6f) | vertex %4d  %s\n", names[a],
                climbed, hull.inputIndex(climbed), p.x(), p.y(), p.z(), scanned,
                agree ? "agree" : "DISAGREE");
  }
  check(axesAgree, "hill-climbing and brute force agree in the six axis directions");

  // Many directions: cold starts from vertex 0, warm starts along a slowly turning
  // direction (frame coherence), and the brute-force reference.
  std::mt19937 rng(20260101u);
  std::normal_distribution<double> gauss;
  const int queries = 20000;
  std::vector<Vec3<double>> dirs(queries);
  for (auto& d : dirs) d = Vec3<double>(gauss(rng), gauss(rng), gauss(rng));
  std::vector<int> cold(queries), brute(queries);
  auto start = Clock::now();
  for (int i = 0; i < queries; ++i) cold[i] = hull.support(dirs[i], 0);
  const double coldNs = millisecondsSince(start) * 1e6 / queries;
  start = Clock::now();
  for (int i = 0; i < queries; ++i) brute[i] = hull.supportBruteForce(dirs[i]);
  const double bruteNs = millisecondsSince(start) * 1e6 / queries;
  int agreeing = 0;
  for (int i = 0; i < queries; ++i) agreeing += sameSupport(hull, dirs[i], cold[i], brute[i]) ? 1 : 0;
  std::vector<Vec3<double>> sweep(queries);
  for (int i = 0; i < queries; ++i) {
    const double t = 2.0 * 3.14159265358979323846 * i / queries;
    sweep[i] = Vec3<double>(std::cos(t), std::sin(t), 0.3 * std::sin(3.0 * t));
  }
  std::vector<int> warm(queries);
  int hint = 0;
  start = Clock::now();
  for (int i = 0; i < queries; ++i) hint = warm[i] = hull.support(sweep[i], hint);
  const double warmNs = millisecondsSince(start) * 1e6 / queries;
  int warmAgreeing = 0;
  for (int i = 0; i < queries; ++i) {
    warmAgreeing += sameSupport(hull, sweep[i], warm[i], hull.supportBruteForce(sweep[i])) ? 1 : 0;
  }
  std::printf("  %d random directions: hill-climb %.0f ns/query, brute force %.0f ns/query;"
              " warm-started along a path: %.0f ns/query\n",
              queries, coldNs, bruteNs, warmNs);
  check(agreeing == queries && warmAgreeing == queries,
        std::to_string(agreeing) + "/" + std::to_string(queries) + " random and " +
            std::to_string(warmAgreeing) + "/" + std::to_string(queries) +
            " warm-started support queries agree with brute force");
}

// The same hull in three floating-point types: what precision costs.
void demoScalars(const fs::path& path) {
  std::printf("\n== %s in three scalar types (fromPoints, median of 5 builds)\n",
              path.filename().string().c_str());
  const auto mesh = mink::io::readObj<double>(path);
  double ms = 0;
  const auto f = timedHull(convert<float>(mesh.vertices), 5, ms);
  std::printf("  float      : V = %4d, E = %4d, F = %4d, %.3f ms\n", f.numVertices(), f.numEdges(),
              f.numFaces(), ms);
  const auto d = timedHull(mesh.vertices, 5, ms);
  std::printf("  double     : V = %4d, E = %4d, F = %4d, %.3f ms\n", d.numVertices(), d.numEdges(),
              d.numFaces(), ms);
  const auto l = timedHull(convert<long double>(mesh.vertices), 5, ms);
  std::printf("  long double: V = %4d, E = %4d, F = %4d, %.3f ms\n", l.numVertices(), l.numEdges(),
              l.numFaces(), ms);
  check(f.numVertices() - f.numEdges() + f.numFaces() == 2 &&
            l.numVertices() - l.numEdges() + l.numFaces() == 2,
        "Euler characteristic is 2 for float and long double hulls too");
}

void demoFromMesh(const fs::path& scratch, const fs::path& duckPath) {
  std::printf("\n== fromMesh: validated meshes (scratch files in %s)\n", scratch.string().c_str());
  // A 2 x 1 x 0.5 box, faces counter-clockwise seen from outside.
  const std::vector<Vec3<double>> corners = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0},
                                             {0, 0, 0.5}, {2, 0, 0.5}, {2, 1, 0.5}, {0, 1, 0.5}};
  const std::vector<std::vector<int>> quads = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                               {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  const fs::path boxPath = scratch / "box.obj";
  mink::io::writeObj(boxPath, corners, quads);
  const auto box = mink::io::readObj<double>(boxPath);
  const auto boxPoly = ConvexPolyhedron<double>::fromMesh(box.vertices, box.faces);
  printCounts("box.obj", boxPoly.numVertices(), boxPoly.numEdges(), boxPoly.numFaces());
  check(boxPoly.numVertices() == 8 && boxPoly.numEdges() == 12 && boxPoly.numFaces() == 6,
        "box written to OBJ, read back and validated by fromMesh has V, E, F = 8, 12, 6");
  const int top = boxPoly.support(Vec3<double>(1, 1, 1));
  check(boxPoly.vertex(top) == Vec3<double>(2, 1, 0.5), "support of the box in (1, 1, 1) is corner (2, 1, 0.5)");

  auto open = quads;
  open.pop_back();
  try {
    ConvexPolyhedron<double>::fromMesh(corners, open);
    check(false, "a box with a missing face is rejected");
  } catch (const mink::InvalidInput& e) {
    check(true, std::string("a box with a missing face is rejected: \"") + e.what() + "\"");
  }
  auto flipped = quads;
  std::reverse(flipped[1].begin(), flipped[1].end());
  try {
    ConvexPolyhedron<double>::fromMesh(corners, flipped);
    check(false, "a box with one face turned inside out is rejected");
  } catch (const mink::InvalidInput& e) {
    check(true, std::string("a box with one face turned inside out is rejected: \"") + e.what() + "\"");
  }

  // The duck's hull as a polygon mesh on disk, read back and validated (not rebuilt).
  const auto duck = mink::io::readObj<double>(duckPath);
  const auto hull = ConvexPolyhedron<double>::fromPoints(duck.vertices);
  const fs::path hullPath = scratch / "duck_hull.obj";
  mink::io::writeObj(hullPath, hull.vertices(), faceLoops(hull));
  const auto back = mink::io::readObj<double>(hullPath);
  try {
    const auto start = Clock::now();
    const auto validated = ConvexPolyhedron<double>::fromMesh(back.vertices, back.faces);
    const double ms = millisecondsSince(start);
    printCounts("duck_hull.obj via fromMesh", validated.numVertices(), validated.numEdges(),
                validated.numFaces());
    std::printf("  fromMesh validation took %.3f ms\n", ms);
    check(validated.numVertices() == hull.numVertices() && validated.numEdges() == hull.numEdges() &&
              validated.numFaces() == hull.numFaces(),
          "the duck's hull, written and read back, validates with the same V, E, F");
  } catch (const mink::InvalidInput& e) {
    check(false, std::string("the duck's hull, written and read back, validates: \"") + e.what() + "\"");
  }
}

}  // namespace

int main(int argc, char** argv) {
  fs::path dataDir = MINK_EXAMPLES_DATA_DIR;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--data") == 0 && i + 1 < argc) {
      dataDir = argv[++i];
    } else {
      std::fprintf(stderr, "usage: %s [--data DIR]\n  DIR holds duck.obj and lego.obj (default %s)\n",
                   argv[0], MINK_EXAMPLES_DATA_DIR);
      return std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0 ? 0 : 2;
    }
  }
  std::printf("mink_demo: convex polyhedra from meshes in %s\n", dataDir.string().c_str());

  const fs::path scratch =
      fs::temp_directory_path() /
      ("mink_demo_" + std::to_string(Clock::now().time_since_epoch().count()));
  try {
    demoMesh(dataDir / "duck.obj");
    demoMesh(dataDir / "lego.obj");
    demoScalars(dataDir / "duck.obj");
    fs::create_directories(scratch);
    demoFromMesh(scratch, dataDir / "duck.obj");
  } catch (const mink::InvalidInput& e) {
    std::fprintf(stderr, "mink_demo: %s\n", e.what());
    ++failures;
  }
  std::error_code ignored;
  fs::remove_all(scratch, ignored);

  std::printf("\n%s\n", failures == 0 ? "mink_demo: all checks passed"
                                      : ("mink_demo: " + std::to_string(failures) + " check(s) FAILED").c_str());
  return failures == 0 ? 0 : 1;
}
