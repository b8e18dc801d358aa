// The package test's second consumer program: mddExact with an exact rational type that
// the consumer brings (CGAL::Gmpq; mink's installed headers know no CGAL). Two unit cubes
// (half-width 0.5), Q's centre 3 from P's along x, s = -x: Q must move by exactly 2 along
// s, so the exact parameter is the rational 2, certified from the double search; with
// s = (-2, 0, 0) it is exactly 1. Exit status 0 only if every check holds.
#include <CGAL/Gmpq.h>

#include <mink/mink.hpp>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Gmpq = CGAL::Gmpq;

std::string text(const Gmpq& x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

int check(const char* what, const mink::ExactMdd<Gmpq>& r, const Gmpq& expected) {
  const bool ok = r.status == mink::MddStatus::Separated && r.parameter == expected && r.certified;
  std::printf("consumer_exact: %s: parameter %s (expected %s), %s, %s\n", what, text(r.parameter).c_str(),
              text(expected).c_str(), r.status == mink::MddStatus::Separated ? "Separated" : "not Separated",
              r.certified ? "certified" : "not certified");
  return ok ? 0 : 1;
}

}  // namespace

int main() {
  std::vector<mink::Vec3<double>> corners;
  for (int i = 0; i < 8; ++i) corners.emplace_back(i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5);
  const auto P = mink::ConvexPolyhedron<double>::fromPoints(corners);
  const auto Q = mink::ConvexPolyhedron<double>::fromPoints(corners);
  mink::Pose<double> poseP, poseQ;
  poseQ.translation = mink::Vec3<double>(3.0, 0.0, 0.0);

  int failures = 0;
  failures += check("s = (-1, 0, 0)", mink::mddExact<Gmpq>(P, poseP, Q, poseQ, mink::Vec3<double>(-1.0, 0.0, 0.0)),
                    Gmpq(2));
  failures += check("s = (-2, 0, 0)", mink::mddExact<Gmpq>(P, poseP, Q, poseQ, mink::Vec3<double>(-2.0, 0.0, 0.0)),
                    Gmpq(1));
  // Q at the double nearest 3 + 1/3: the exact parameter is that double minus 1.
  poseQ.translation.x() = 3.0 + 1.0 / 3.0;
  failures += check("Q at 3 + 1/3 (rounded)",
                    mink::mddExact<Gmpq>(P, poseP, Q, poseQ, mink::Vec3<double>(-1.0, 0.0, 0.0)),
                    Gmpq(poseQ.translation.x()) - Gmpq(1));
  std::printf("consumer_exact: %s\n", failures == 0 ? "ok" : "FAILED");
  return failures == 0 ? 0 : 1;
}
