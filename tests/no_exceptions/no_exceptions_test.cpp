// tests/no_exceptions/no_exceptions_test.cpp — mink built the way engines that disable
// exceptions build it (-fno-exceptions; no gtest, which needs them): bad input must come
// back as a status or an Error, never as a throw (which cannot compile here) or a silent
// answer; good input must be answered as usual. The mesh, io and CPD layers' checks are
// in mesh_io_cpd_checks.cpp.
//
//   mink_no_exceptions_tests           every check; exit status = number of failures
//   mink_no_exceptions_tests --abort   a throwing entry point (fromPoints) on bad input:
//                                      must print its message and abort
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "mink/hierarchy/dk_hierarchy.hpp"
#include "mink/hierarchy/prepare.hpp"
#include "mink/mdd/first_contact.hpp"
#include "mink/mdd/intersects.hpp"
#include "mink/mdd/mdd.hpp"

static_assert(!MINK_EXCEPTIONS, "this test must be compiled with -fno-exceptions");

namespace mink_no_exceptions {
int checkMeshIoCpd();  // mesh_io_cpd_checks.cpp
}

namespace {

using mink::ConvexPolyhedron;
using mink::MddStatus;
using mink::Pose;

int failures = 0;

void check(bool ok, const std::string& what) {
  if (!ok) {
    ++failures;
    std::fprintf(stderr, "FAIL: %s\n", what.c_str());
  }
}

bool contains(const std::string& text, const char* words) { return text.find(words) != std::string::npos; }

template <class T>
std::vector<mink::Vec3<T>> box(T a) {
  std::vector<mink::Vec3<T>> p;
  for (int i = 0; i < 8; ++i) p.push_back(mink::Vec3<T>(i & 1 ? a : -a, i & 2 ? a : -a, i & 4 ? a : -a));
  return p;
}

template <class T>
void checkShapes(const char* type) {
  using V = mink::Vec3<T>;
  const std::string in = std::string(" (") + type + ")";
  const T nan = std::numeric_limits<T>::quiet_NaN();
  struct Case {
    std::vector<V> points;
    const char* words;
  };
  std::vector<V> withNaN = box<T>(1);
  withNaN[3][2] = nan;
  const std::vector<Case> bad = {{{}, "fromPoints: no points given"},
                                 {{V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)}, "need at least 4 points"},
                                 {withNaN, "point 3 has a non-finite coordinate"},
                                 {{V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(1, 1, 0)}, "coplanar"},
                                 {{V(0, 0, 0), V(1, 1, 1), V(2, 2, 2), V(3, 3, 3)}, "collinear"}};
  for (const Case& c : bad) {
    const auto r = ConvexPolyhedron<T>::tryFromPoints(c.points);
    check(!r.ok(), std::string("tryFromPoints accepted bad input: ") + c.words + in);
    check(contains(r.error().message(), c.words) && contains(r.error().message(), "mink: "),
          "tryFromPoints message '" + r.error().message() + "' lacks '" + c.words + "'" + in);
  }
  const auto good = ConvexPolyhedron<T>::tryFromPoints(box<T>(1));
  check(good.ok() && good.value().numVertices() == 8 && good.value().numFaces() == 6,
        "tryFromPoints on a box" + in);
  // fromMesh's twin: the box's own faces, then with one face missing.
  std::vector<std::vector<int>> faces;
  for (int f = 0; f < good.value().numFaces(); ++f) {
    std::vector<int> L;
    for (int v : good.value().faceVertices(f)) L.push_back(v);
    faces.push_back(L);
  }
  check(ConvexPolyhedron<T>::tryFromMesh(good.value().vertices(), faces).ok(), "tryFromMesh on a box" + in);
  faces.pop_back();
  const auto open = ConvexPolyhedron<T>::tryFromMesh(good.value().vertices(), faces);
  check(!open.ok() && contains(open.error().message(), "not closed"), "tryFromMesh on an open box" + in);
}

template <class T>
void checkQueries(const char* type) {
  using V = mink::Vec3<T>;
  const std::string in = std::string(" (") + type + ")";
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const auto B = ConvexPolyhedron<T>::fromPoints(box<T>(1));
  Pose<T> q;
  q.translation = V(3, 0, 0);

  // Good input: answered as usual (boxes of half-size 1, Q at x = 3, s along -x).
  const mink::MddResult<T> ok = mink::mdd(B, Pose<T>(), B, q, V(-1, 0, 0));
  check(ok.status == MddStatus::Separated && std::abs(ok.translation - T(1)) < T(1e-5), "mdd on good input" + in);
  check(!mink::checkMddInput(B, Pose<T>(), B, q, V(-1, 0, 0)), "checkMddInput on good input" + in);

  // Bad input: the status InvalidInput, NaN values, and checkMddInput names the problem.
  Pose<T> skew = q;
  skew.rotation(0, 1) = T(0.5);
  Pose<T> moved = q;
  moved.translation[1] = nan;
  struct Case {
    Pose<T> poseQ;
    V s;
    const char* words;
  };
  mink::MddCache<T> cache;
  for (const Case& c : {Case{q, V(0, 0, 0), "direction s is zero"}, Case{q, V(nan, 0, 0), "direction s is not finite"},
                        Case{skew, V(-1, 0, 0), "poseQ.rotation is not orthonormal"},
                        Case{moved, V(-1, 0, 0), "poseQ.translation is not finite"}}) {
    const mink::MddResult<T> r = mink::mdd(B, Pose<T>(), B, c.poseQ, c.s, cache);
    check(r.status == MddStatus::InvalidInput, std::string("mdd status on bad input: ") + c.words + " gave " +
                                                   mink::toString(r.status) + in);
    check(std::isnan(r.distance) && std::isnan(r.translation) && std::isnan(r.parameter),
          std::string("mdd values on bad input are not NaN: ") + c.words + in);
    const mink::Error e = mink::checkMddInput(B, Pose<T>(), B, c.poseQ, c.s);
    check(e && contains(e.message(), c.words), "checkMddInput message '" + e.message() + "' lacks '" + c.words + "'" + in);
    const mink::FirstContact<T> fc = mink::firstContact(B, Pose<T>(), B, c.poseQ, c.s);
    check(fc.mdd.status == MddStatus::InvalidInput && fc.hit && fc.fraction == T(0),
          std::string("firstContact on bad input is not a contact at 0: ") + c.words + in);
  }
  // The cache still serves good queries after rejected ones.
  const mink::MddResult<T> again = mink::mdd(B, Pose<T>(), B, q, V(-1, 0, 0), cache);
  check(again.status == MddStatus::Separated && again.translation == ok.translation, "mdd after rejections" + in);

  mink::MddOptions<T> nanTol;
  nanTol.touchTolerance = nan;
  check(mink::mdd(B, Pose<T>(), B, q, V(-1, 0, 0), nanTol).status == MddStatus::InvalidInput,
        "mdd with a NaN touchTolerance" + in);
  const mink::Result<bool> ti = mink::tryIntersects(B, Pose<T>(), B, q, nanTol);
  check(!ti.ok() && contains(ti.error().message(), "intersects: options.touchTolerance is NaN"),
        "tryIntersects with a NaN touchTolerance" + in);
  const mink::Result<bool> tp = mink::tryIntersects(B, Pose<T>(), B, skew);
  check(!tp.ok() && contains(tp.error().message(), "poseQ.rotation is not orthonormal"),
        "tryIntersects with a skew pose" + in);
  for (T x : {T(1.5), T(2.5)}) {
    Pose<T> at;
    at.translation = V(x, T(0.25), 0);
    const mink::Result<bool> r = mink::tryIntersects(B, Pose<T>(), B, at);
    check(r.ok() && r.value() == (x < T(2)) && r.value() == mink::intersects(B, Pose<T>(), B, at),
          "tryIntersects on good input" + in);
  }
}

void checkHierarchy() {
  mink::DKHierarchyOptions bad;
  bad.maxRemovedDegree = 2;
  const mink::Error e = mink::DKHierarchy<double>::checkOptions(bad);
  check(e && contains(e.message(), "maxRemovedDegree must be >= 3, got 2"), "DKHierarchy::checkOptions");
  check(!mink::DKHierarchy<double>::checkOptions(mink::DKHierarchyOptions{}), "DKHierarchy::checkOptions default");
  // A shape large enough for a hierarchy: built and used without exceptions.
  std::vector<mink::Vec3<double>> pts;
  for (int i = 0; i < 2000; ++i) {
    const double z = 1 - 2 * (i + 0.5) / 2000, r = std::sqrt(1 - z * z), a = 2.399963229728653 * i;
    pts.push_back(mink::Vec3<double>(r * std::cos(a), r * std::sin(a), z));
  }
  const auto S = ConvexPolyhedron<double>::fromPoints(pts);
  const mink::DKHierarchy<double>* H = mink::prepare(S);
  check(H != nullptr, "prepare on a 2000-vertex shape");
  const mink::Vec3<double> d(0.3, -0.5, 0.8);
  check(H && S.vertex(H->support(d)).dot(d) == S.vertex(S.supportBruteForce(d)).dot(d), "hierarchy support");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--abort") == 0) {
    // A throwing entry point on bad input: prints "mink: fromPoints: no points given" and
    // aborts (ctest expects that message and a failing exit).
    const auto P = ConvexPolyhedron<double>::fromPoints({});
    std::printf("not aborted: %d vertices\n", P.numVertices());
    return 0;
  }
  checkShapes<double>("double");
  checkShapes<float>("float");
  checkQueries<double>("double");
  checkQueries<float>("float");
  checkHierarchy();
  failures += mink_no_exceptions::checkMeshIoCpd();
  std::printf("%s: %d failure(s)\n", failures ? "FAILED" : "passed", failures);
  return failures == 0 ? 0 : 1;
}
