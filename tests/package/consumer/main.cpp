// The package test's consumer: builds the hull of a cube's 8 corners plus its centre
// from the installed headers and checks the answer against the cube's known shape.
// Exit status 0 only if every check holds.
#include <mink/mink.hpp>

#include <cstdio>
#include <vector>

int main() {
  std::vector<mink::Vec3<double>> points;
  for (int i = 0; i < 8; ++i) {
    points.emplace_back(i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0);
  }
  points.emplace_back(0.0, 0.0, 0.0);  // the centre is inside: not a hull vertex

  const auto cube = mink::ConvexPolyhedron<double>::fromPoints(points);
  const int v = cube.numVertices();
  const int e = cube.numEdges();
  const int f = cube.numFaces();
  std::printf("consumer: cube hull V = %d, E = %d, F = %d\n", v, e, f);
  int failures = 0;
  if (v != 8 || e != 12 || f != 6) {
    std::printf("consumer: expected V = 8, E = 12, F = 6\n");
    ++failures;
  }
  for (int i = 0; i < v; ++i) {
    if (cube.inputIndex(i) == 8) {
      std::printf("consumer: the centre became a hull vertex\n");
      ++failures;
    }
  }
  const mink::Vec3<double> d(1.0, 2.0, 3.0);
  const int s = cube.support(d);
  if (cube.vertex(s) != mink::Vec3<double>(1.0, 1.0, 1.0)) {
    std::printf("consumer: support in (1, 2, 3) is not the corner (1, 1, 1)\n");
    ++failures;
  }
  // A query through the entry points compiled once in mink_instantiations.cpp: the second
  // cube, centred at x = 3, touches the first after moving 1 along -x.
  mink::Pose<double> at3;
  at3.translation = mink::Vec3<double>(3.0, 0.5, 0.0);
  const auto r = mink::mdd(cube, mink::Pose<double>(), cube, at3, mink::Vec3<double>(-1.0, 0.0, 0.0));
  if (r.status != mink::MddStatus::Separated || r.translation != 1.0 ||
      mink::intersects(cube, mink::Pose<double>(), cube, at3)) {
    std::printf("consumer: mdd of two cubes 1 apart gave status %d, translation %g\n", static_cast<int>(r.status),
                r.translation);
    ++failures;
  }
  try {
    mink::ConvexPolyhedron<double>::fromPoints({points[0], points[1], points[2]});
    std::printf("consumer: three points were accepted as a polyhedron\n");
    ++failures;
  } catch (const mink::InvalidInput&) {
  }
  std::printf("consumer: %s\n", failures == 0 ? "ok" : "FAILED");
  return failures == 0 ? 0 : 1;
}
