// mink_mesh_overlap_bench — cost of the mesh layer's overlap query (mesh/mesh_overlap.hpp)
// in the way CPD uses it: one relative pose, many translations y, "does A meet B + y?".
//
// Inputs: pairs of closed meshes (procedural: tests/support/mesh_shapes.hpp; shipped:
// tests/data/*.obj, Bullet's zlib-licensed meshes); for each pair, random poses of B in
// A's frame (fixed seed: a Haar-uniform rotation, B's root sphere centre at a distance of
// 0.05 .. 1.15 times the sum of the two root radii from A's) and, per pose, random y of
// up to 0.3 times that sum. Scalar: double.
// Figures, per pair, each a median over poses with its quartiles (a pose's figure is its
// batch of y divided by the batch size):
//   place:  MeshOverlap::setPlacement (B's vertices and tree centres mapped once per pose);
//   mink:   MeshOverlap::overlaps(y);
//   fcl:    fcl::collide on fcl::BVHModel<OBBRSSd> for the same configurations (the anchor;
//           it tests boundaries only, no containment), B's transform and box set per query;
// and the share of queries that overlap, and mink's node pairs and triangle pairs per query.
//
// Usage: mink_mesh_overlap_bench [out.csv] [--quick]
//   out.csv  default benchmarks/results/mesh_overlap.csv (directory must exist)
//   --quick  fewer poses (smoke test, numbers not for publication)
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "mink/io/triangle_mesh_io.hpp"
#include "mink/mesh/mesh_overlap.hpp"
#include "support/fcl_mesh.hpp"
#include "support/mesh_shapes.hpp"
#include "support/paper_shapes.hpp"

namespace {

using Mesh = mink::TriangleMesh<double>;
using V = Eigen::Vector3d;
using M3 = Eigen::Matrix3d;
using Clock = std::chrono::steady_clock;

volatile long gSink = 0;

struct Pair {
  std::string name;
  Mesh A, B;
};

Mesh fromShape(const mink_test::MeshShape& s) { return Mesh::fromMesh(s.verticesAs<double>(), s.triangles); }
Mesh shipped(const char* f) { return mink::io::readTriangleMesh<double>(std::string(MINK_BENCH_DATA_DIR) + "/" + f); }

using mink_test::randomRotation;

double micros(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::micro>(b - a).count(); }

struct Row {
  std::string pair, figure;
  int trianglesA = 0, trianglesB = 0;
  double q1 = 0, median = 0, q3 = 0;
};

}  // namespace

/// The usage, as in the comment at the top of this file.
constexpr const char* kUsage =
    "Usage: mink_mesh_overlap_bench [out.csv] [--quick]\n"
    "  out.csv  default benchmarks/results/mesh_overlap.csv (directory must exist)\n"
    "  --quick  fewer poses (smoke test, numbers not for publication)\n";

int main(int argc, char** argv) {
  std::string out = "benchmarks/results/mesh_overlap.csv";
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0)
      quick = true;
    else
      out = mink_bench::pathArgument(argv[i], kUsage);
  }
  const int poses = quick ? 20 : 300, ys = 64;
  std::vector<Pair> pairs = {
      {"torus 12x8 / L-block", fromShape(mink_test::torus(12, 8)), fromShape(mink_test::lBlock())},
      {"spoon / cup", fromShape(mink_test::spoon()), fromShape(mink_test::cup())},
      {"torus 48x24 / axes", fromShape(mink_test::torus(48, 24)), fromShape(mink_test::axes())},
      {"duck / torus.obj", shipped("duck.obj"), shipped("torus.obj")},
      {"bunny / concave_box", shipped("bunny.obj"), shipped("concave_box.obj")},
  };
  const std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M", std::localtime(&now));
  std::printf("mink_mesh_overlap_bench  %s  %s  load %s\n", date, mink_bench::machineLine().c_str(),
              mink_bench::loadAverage().c_str());
  std::printf("%d poses per pair, %d translations y per pose; times in microseconds, median [q1, q3] over poses\n\n",
              poses, ys);
  std::printf("%-22s %6s %6s | %-22s | %-22s | %-22s | %7s %9s %9s\n", "pair", "tri A", "tri B", "place (per pose)",
              "mink overlaps(y)", "fcl collide", "overlap", "nodes/q", "tris/q");
  std::vector<Row> rows;
  std::mt19937 rng(20240601u);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const Pair& p : pairs) {
    mink_test::FclPair fcl(p.A, p.B);
    const auto& ta = p.A.sphereTree();
    const auto& tb = p.B.sphereTree();
    const double reach = ta.radius(0) + tb.radius(0);
    std::vector<double> place, mink, fclT;
    long hits = 0, queries = 0, fclHits = 0;
    double nodes = 0, tris = 0;
    mink::MeshOverlap<double> o(p.A, p.B, M3::Identity(), V::Zero());
    std::vector<V> y(ys);
    for (int i = 0; i < poses; ++i) {
      const M3 R = randomRotation(rng);
      const V t = ta.centre(0) - R * tb.centre(0) + mink_test::randomUnitVector(rng) * reach * (0.05 + 1.1 * u(rng));
      for (V& v : y) v = mink_test::randomUnitVector(rng) * 0.3 * reach * u(rng);
      auto c0 = Clock::now();
      o.setPlacement(R, t);
      auto c1 = Clock::now();
      place.push_back(micros(c0, c1));
      long h = 0;
      c0 = Clock::now();
      for (const V& v : y) {
        h += o.overlaps(v);
        nodes += static_cast<double>(o.result().nodePairs);
        tris += static_cast<double>(o.result().trianglePairs);
      }
      c1 = Clock::now();
      mink.push_back(micros(c0, c1) / ys);
      hits += h;
      queries += ys;
      long fh = 0;
      c0 = Clock::now();
      for (const V& v : y) fh += fcl.collide(R, t + v);
      c1 = Clock::now();
      fclT.push_back(micros(c0, c1) / ys);
      fclHits += fh;
    }
    gSink += hits + fclHits;
    auto add = [&](const char* figure, const std::vector<double>& v) {
      rows.push_back({p.name, figure, p.A.numTriangles(), p.B.numTriangles(), mink_bench::quantile(v, 0.25),
                      mink_bench::quantile(v, 0.5), mink_bench::quantile(v, 0.75)});
      char buf[64];
      std::snprintf(buf, sizeof buf, "%8.2f [%6.2f, %6.2f]", rows.back().median, rows.back().q1, rows.back().q3);
      return std::string(buf);
    };
    const std::string a = add("place", place), b = add("mink", mink), c = add("fcl", fclT);
    std::printf("%-22s %6d %6d | %-22s | %-22s | %-22s | %6.1f%% %9.1f %9.1f\n", p.name.c_str(), p.A.numTriangles(),
                p.B.numTriangles(), a.c_str(), b.c_str(), c.c_str(), 100.0 * hits / queries, nodes / queries,
                tris / queries);
    if (hits < fclHits)  // FCL sees boundaries only: it can report fewer overlaps, never more
      std::printf("  note: fcl reported %ld overlaps, mink %ld\n", fclHits, hits);
  }
  std::ofstream csv(out);
  csv << "# mink_mesh_overlap_bench " << date << ", " << mink_bench::machineLine() << ", load "
      << mink_bench::loadAverage() << ", poses " << poses << ", y per pose " << ys << "\n";
  csv << "pair,triangles_a,triangles_b,figure,q1_us,median_us,q3_us\n";
  for (const Row& r : rows)
    csv << r.pair << "," << r.trianglesA << "," << r.trianglesB << "," << r.figure << "," << r.q1 << "," << r.median
        << "," << r.q3 << "\n";
  if (!csv) {
    std::fprintf(stderr, "could not write %s\n", out.c_str());
    return 1;
  }
  return 0;
}
