// tests/mdd/mdd_exact_test.cpp — mink::mddExact against the exact CGAL reference (hull of
// all vertex differences placed exactly, exact clipping of the line;
// tests/support/mdd_reference.hpp) and against mdd<Gmpq> on exact copies of the shapes:
// the paper's pairs, the degenerate contacts, small integer hulls under exact quarter
// turns (ties everywhere), and the paths that must fall back.
#include "mink/mdd/mdd_exact.hpp"

#include <gtest/gtest.h>

#include <CGAL/Gmpq.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "support/degenerate_contacts.hpp"
#include "support/exact_placement.hpp"
#include "support/mdd_reference.hpp"
#include "support/mdd_status.hpp"
#include "support/paper_shapes.hpp"

namespace {

using mink::ConvexPolyhedron;
using mink::MddStatus;
using mink::Pose;
using mink_test::Rational;
using mink_test::Vec3r;
using Vec3d = Eigen::Vector3d;
using Mat3d = Eigen::Matrix3d;

mink_test::Mat3r toExact(const Mat3d& m) {
  mink_test::Mat3r r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = Rational(m(i, j));
  return r;
}

// The exact answer for the shapes' vertices placed exactly by the double poses.
mink_test::MddRefResult reference(const ConvexPolyhedron<double>& P, const Pose<double>& poseP,
                                  const ConvexPolyhedron<double>& Q, const Pose<double>& poseQ, const Vec3d& s) {
  const mink_test::MinkowskiDifferenceReference ref(
      mink_test::placeExact(P.vertices(), toExact(poseP.rotation), mink_test::toExact(poseP.translation)),
      mink_test::placeExact(Q.vertices(), toExact(poseQ.rotation), mink_test::toExact(poseQ.translation)));
  return ref.query(mink_test::toExact(s));
}

// mddExact equals the exact reference (on a penetrating tie, either end is minimal).
void expectExact(const mink::ExactMdd<Rational>& x, const mink_test::MddRefResult& e, const std::string& what) {
  ASSERT_EQ(x.status, mink_test::toMinkStatus(e.status)) << what << " (certified " << x.certified << ")";
  if (e.status == mink_test::MddRefStatus::NoContact) {
    EXPECT_EQ(x.parameter, Rational(0)) << what;
  } else if (e.tie) {
    EXPECT_TRUE(x.parameter == e.t || x.parameter == -e.t) << what;
  } else {
    EXPECT_EQ(x.parameter, e.t) << what << ": " << CGAL::to_double(x.parameter) << " vs " << CGAL::to_double(e.t)
                                << " (certified " << x.certified << ")";
  }
}

struct Tally {
  int queries = 0, certified = 0, contact = 0, contactCertified = 0;
  void add(const mink::ExactMdd<Rational>& x, const mink_test::MddRefResult& e) {
    ++queries;
    certified += x.certified;
    if (e.status != mink_test::MddRefStatus::NoContact) {
      ++contact;
      contactCertified += x.certified;
    }
  }
  void print(const char* name) const {
    std::printf("[mddExact/%s] %d queries, %d certified (%d of the %d whose line meets M, %d of the %d that "
                "miss)\n",
                name, queries, certified, contactCertified, contact, certified - contactCertified, queries - contact);
  }
};

// The paper's experiment (pairs, orientations, centre distances from deep overlap to
// clear separation, random directions), also against mdd<Gmpq> on exact copies.
TEST(MddExact, PaperPairs) {
  const unsigned seed = 20261203;
  std::mt19937 rng(seed);
  Tally tally;
  for (const auto& pair : mink_test::kPaperPairs) {
    const auto ptsP = mink_test::paperShape(pair.first, rng);
    const auto ptsQ = mink_test::paperShape(pair.second, rng);
    const auto P = ConvexPolyhedron<double>::fromPoints(ptsP);
    const auto Q = ConvexPolyhedron<double>::fromPoints(ptsQ);
    const auto rot = mink_test::randomRationalRotation(rng);
    // mdd<Gmpq>'s own copies: exact rotations only, so Q is turned by the rounded
    // rotation exactly first.
    const auto PE = ConvexPolyhedron<Rational>::fromPoints(P.vertices());
    const auto QE = ConvexPolyhedron<Rational>::fromPoints(
        mink_test::placeExact(Q.vertices(), toExact(rot.rounded), Vec3r::Zero()));
    const Vec3d axis = mink_test::randomUnitVector(rng);
    const mink_test::MinkowskiDifferenceReference ref(
        mink_test::toExact(P.vertices()), mink_test::placeExact(Q.vertices(), toExact(rot.rounded), Vec3r::Zero()));
    for (int step = 0; step <= 20; step += 5) {
      Pose<double> poseQ;
      poseQ.rotation = rot.rounded;
      poseQ.translation = (1.0 + 9.0 * step / 20.0) * axis;
      Pose<Rational> poseQE;
      poseQE.translation = mink_test::toExact(poseQ.translation);
      for (int k = 0; k < 4; ++k) {
        const Vec3d s = mink_test::randomUnitVector(rng) * (0.5 + mink_test::uniform01(rng));
        std::ostringstream what;
        what << "seed " << seed << " pair " << mink_test::paperShapeName(pair.first) << "-"
             << mink_test::paperShapeName(pair.second) << " step " << step << " k " << k;
        const auto x = mink::mddExact<Rational>(P, Pose<double>(), Q, poseQ, s);
        const auto e = ref.query(mink_test::toExact(s), mink_test::toExact(poseQ.translation));
        expectExact(x, e, what.str());
        const auto m = mink::mdd(PE, Pose<Rational>(), QE, poseQE, mink_test::toExact(s));
        EXPECT_EQ(x.status, m.status) << what.str();
        if (m.status != MddStatus::NoContact && !e.tie) {
          EXPECT_EQ(x.parameter, m.parameter) << what.str();
        }
        tally.add(x, e);
      }
    }
  }
  tally.print("paper");
  // Generic placements: every answer has a face or a separating direction to certify.
  EXPECT_EQ(tally.certified, tally.queries);
}

// The degenerate contacts of a physics scene (resting caps, overlapping caps, cylinders
// along a line, cones apex to apex, aligned boxes) and their generic twins: features with
// ties on both sides, facets that are spans of several faces.
TEST(MddExact, DegenerateContacts) {
  Tally tally;
  for (const std::string& family : mink_test::degenerateFamilies()) {
    for (int n : {5, 12}) {
      for (bool generic : {false, true}) {
        const mink_test::ContactScene sc = mink_test::degenerateScene(family, n, generic);
        const auto P = ConvexPolyhedron<double>::fromPoints(sc.P);
        const auto Q = ConvexPolyhedron<double>::fromPoints(sc.Q);
        Pose<double> poseQ;
        poseQ.rotation = sc.rotQ;
        poseQ.translation = sc.tQ;
        for (std::size_t k = 0; k < sc.dirs.size(); ++k) {
          const std::string what = family + " n " + std::to_string(n) + (generic ? " generic" : " degenerate") +
                                   " dir " + std::to_string(k);
          const auto x = mink::mddExact<Rational>(P, Pose<double>(), Q, poseQ, sc.dirs[k]);
          const auto e = reference(P, Pose<double>(), Q, poseQ, sc.dirs[k]);
          expectExact(x, e, what);
          tally.add(x, e);
        }
      }
    }
  }
  tally.print("degenerate contacts");
}

// The same families at n = 512 (1,024-vertex prisms: the shapes have hierarchies, whose
// support vertices among ties differ from a hill-climb's): mdd<double> against mddExact
// (the exact reference's hull of M would have a million points). A tied support vertex
// rounded the value of a grazing line's supporting plane below 0 (cylinders-side, s =
// (1, 1, 0): NoContact for Touching).
TEST(MddExact, DegenerateContactsWithHierarchies) {
  for (const std::string& family : mink_test::degenerateFamilies()) {
    for (bool generic : {false, true}) {
      const mink_test::ContactScene sc = mink_test::degenerateScene(family, 512, generic);
      const auto P = ConvexPolyhedron<double>::fromPoints(sc.P);
      const auto Q = ConvexPolyhedron<double>::fromPoints(sc.Q);
      if (family == "cylinders-side") {
        ASSERT_NE(mink::hierarchyOf(P), nullptr);
      }
      Pose<double> poseQ;
      poseQ.rotation = sc.rotQ;
      poseQ.translation = sc.tQ;
      for (std::size_t k = 0; k < sc.dirs.size(); ++k) {
        const std::string what = family + (generic ? " generic" : " degenerate") + " dir " + std::to_string(k);
        const auto r = mink::mdd(P, Pose<double>(), Q, poseQ, sc.dirs[k]);
        const auto x = mink::mddExact<Rational>(P, Pose<double>(), Q, poseQ, sc.dirs[k]);
        ASSERT_EQ(r.status, x.status) << what << " (certified " << x.certified << ")";
        if (x.status != MddStatus::NoContact) {
          EXPECT_NEAR(r.parameter, CGAL::to_double(x.parameter), 1e-12) << what;
        }
      }
    }
  }
}

// Small integer hulls under exact quarter turns: every number exact in double, ties
// everywhere (lines through vertices and along faces, touching, single-point contacts).
// Includes issue 17's case, where mdd<double> answers NoContact and the exact answer is
// Separated at parameter 1.
TEST(MddExact, IntegerHullsUnderQuarterTurns) {
  {
    const std::vector<Vec3d> p = {{1, 0, 2}, {-1, -1, -2}, {0, -2, -1}, {1, 1, -1}, {1, 1, 2}, {-2, 2, -1}};
    const std::vector<Vec3d> q = {{1, 0, -1}, {-2, 1, 0}, {0, 0, 1}, {2, 0, -2}, {2, 1, 1}};
    const auto P = ConvexPolyhedron<double>::fromPoints(p);
    const auto Q = ConvexPolyhedron<double>::fromPoints(q);
    Pose<double> poseQ;
    poseQ.rotation << 0, -1, 0, 1, 0, 0, 0, 0, 1;
    poseQ.translation = Vec3d(2, -2, -3);
    const Vec3d s(-1, -2, 1);
    const auto x = mink::mddExact<Rational>(P, Pose<double>(), Q, poseQ, s);
    EXPECT_EQ(x.status, MddStatus::Separated);
    EXPECT_EQ(x.parameter, Rational(1));
    expectExact(x, reference(P, Pose<double>(), Q, poseQ, s), "issue 17's single-point contact");
  }
  const unsigned seed = 17;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(-2, 2), turn(0, 3), dir(-2, 2);
  Tally tally;
  int tried = 0;
  while (tried < 300) {
    std::vector<Vec3d> p, q;
    for (int i = 0; i < 6; ++i) p.emplace_back(coord(rng), coord(rng), coord(rng));
    for (int i = 0; i < 5; ++i) q.emplace_back(coord(rng), coord(rng), coord(rng));
    ConvexPolyhedron<double> P = ConvexPolyhedron<double>::fromPoints(std::vector<Vec3d>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    ConvexPolyhedron<double> Q = P;
    try {
      P = ConvexPolyhedron<double>::fromPoints(p);
      Q = ConvexPolyhedron<double>::fromPoints(q);
    } catch (const mink::InvalidInput&) {
      continue;  // flat sets: not a polyhedron
    }
    Pose<double> poseQ;
    const int quarter = turn(rng);
    const double c[4] = {1, 0, -1, 0}, sn[4] = {0, 1, 0, -1};
    poseQ.rotation << c[quarter], -sn[quarter], 0, sn[quarter], c[quarter], 0, 0, 0, 1;
    poseQ.translation = Vec3d(coord(rng), coord(rng), coord(rng));
    Vec3d s(dir(rng), dir(rng), dir(rng));
    if (s == Vec3d::Zero()) s = Vec3d(0, 0, 1);
    ++tried;
    std::ostringstream what;
    what << "seed " << seed << " case " << tried;
    const auto x = mink::mddExact<Rational>(P, Pose<double>(), Q, poseQ, s);
    const auto e = reference(P, Pose<double>(), Q, poseQ, s);
    expectExact(x, e, what.str());
    tally.add(x, e);
  }
  tally.print("integer quarter turns");
  EXPECT_GT(tally.certified, 0);
}

// The 24 rotations that map the axes onto the axes (signed permutation matrices of
// determinant 1): every product with them is exact in double.
std::vector<Mat3d> axisRotations() {
  std::vector<Mat3d> out;
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& pm : perms)
    for (int signs = 0; signs < 8; ++signs) {
      Mat3d m = Mat3d::Zero();
      for (int r = 0; r < 3; ++r) m(r, pm[r]) = (signs >> r) & 1 ? -1.0 : 1.0;
      if (m.determinant() > 0) out.push_back(m);
    }
  return out;
}

// mdd<double> where every number is exact in double (issue 17): random small-integer
// hulls, Q turned by one of the 24 axis rotations and moved by an integer translation,
// integer directions. The status must be the exact one, grazing lines and single-point
// contacts included (no "or NoContact" leniency), and the parameter the exact one to
// rounding.
TEST(MddExact, DoubleAnswersExactlyOnExactInputs) {
  const std::vector<Mat3d> turns = axisRotations();
  ASSERT_EQ(turns.size(), 24u);
  // MINK_EXACT_SWEEP=<seed>,<cases> runs a longer sweep by hand (fuzz/README.md).
  unsigned seed = 2017;
#ifdef MINK_SANITIZE_BUILD
  int cases = 300;
#else
  int cases = 2000;
#endif
  if (const char* sweep = std::getenv("MINK_EXACT_SWEEP")) {
    seed = static_cast<unsigned>(std::strtoul(sweep, nullptr, 10));
    if (const char* comma = std::strchr(sweep, ',')) cases = std::atoi(comma + 1);
  }
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(-2, 2), pick(0, 23), dir(-2, 2), count(4, 8);
  int tried = 0, contacts = 0, wrong = 0;
  while (tried < cases) {
    std::vector<Vec3d> p, q;
    const int np = count(rng), nq = count(rng);
    for (int i = 0; i < np; ++i) p.emplace_back(coord(rng), coord(rng), coord(rng));
    for (int i = 0; i < nq; ++i) q.emplace_back(coord(rng), coord(rng), coord(rng));
    std::vector<ConvexPolyhedron<double>> shapes;
    try {
      shapes.push_back(ConvexPolyhedron<double>::fromPoints(p));
      shapes.push_back(ConvexPolyhedron<double>::fromPoints(q));
    } catch (const mink::InvalidInput&) {
      continue;  // flat sets: not a polyhedron
    }
    const ConvexPolyhedron<double>& P = shapes[0];
    const ConvexPolyhedron<double>& Q = shapes[1];
    Pose<double> poseP, poseQ;
    poseP.rotation = turns[pick(rng)];
    poseQ.rotation = turns[pick(rng)];
    poseP.translation = Vec3d(coord(rng), coord(rng), coord(rng));
    poseQ.translation = Vec3d(coord(rng), coord(rng), coord(rng));
    Vec3d s(dir(rng), dir(rng), dir(rng));
    if (s == Vec3d::Zero()) s = Vec3d(0, 0, 1);
    ++tried;
    const auto e = reference(P, poseP, Q, poseQ, s);
    const auto r = mink::mdd(P, poseP, Q, poseQ, s);
    const MddStatus want = mink_test::toMinkStatus(e.status);
    contacts += want != MddStatus::NoContact;
    bool ok = r.status == want;
    if (ok && want != MddStatus::NoContact) {
      const double t = CGAL::to_double(e.t);
      const double tol = 1e-12 * (1 + std::abs(t));
      ok = std::abs(r.parameter - t) <= tol || (e.tie && std::abs(r.parameter + t) <= tol);
    }
    if (!ok) {
      ++wrong;
      ADD_FAILURE() << "seed " << seed << " case " << tried << ": mdd<double> " << mink::toString(r.status)
                    << " at " << r.parameter << " (path " << static_cast<int>(r.path) << "), exact "
                    << mink::toString(want) << " at " << CGAL::to_double(e.t);
    }
  }
  std::printf("[mdd<double>/integer axis turns] %d queries (%d with contact), %d answered differently from the "
              "exact reference\n",
              tried, contacts, wrong);
}

// The filter's and the expansions' ranges: the same queries at scales 2^k (shapes and
// translations scaled, s kept) answer with the same status and the parameter scaled by
// 2^k exactly. Far below 2^-100 or above 2^100 the parameter is evaluated in E rather
// than as an expansion, and at 2^-300 the intervals cannot tell most signs (their
// products underflow), so the tests run in E too. Float shapes of the same numbers answer
// as double ones do (CGAL::Gmpq has no constructor from long double, the other type the
// filter is made for).
TEST(MddExact, ScalesAndScalarTypes) {
  std::mt19937 rng(20261204);
  int queries = 0, contacts = 0;
  for (const auto& pair : {std::make_pair(mink_test::PaperShape::P1, mink_test::PaperShape::P5),
                           std::make_pair(mink_test::PaperShape::P2, mink_test::PaperShape::P1)}) {
    // Numbers rounded to float, so that both scalar types hold them exactly. Through a
    // volatile float: GCC 12 at -O2 -frounding-math was seen to drop the double-float-
    // double round trip of an Eigen expression's result.
    auto toFloatGrid = [](const auto& m) {
      auto r = m.eval();
      for (int i = 0; i < r.size(); ++i) {
        volatile float f = static_cast<float>(r.data()[i]);
        r.data()[i] = f;
      }
      return r;
    };
    std::vector<Vec3d> ptsP, ptsQ;
    for (const Vec3d& x : mink_test::paperShape(pair.first, rng)) ptsP.push_back(toFloatGrid(x));
    for (const Vec3d& x : mink_test::paperShape(pair.second, rng)) ptsQ.push_back(toFloatGrid(x));
    const Vec3d axis = mink_test::randomUnitVector(rng);
    for (int step = 0; step <= 20; step += 4) {
      const auto rot = mink_test::randomRationalRotation(rng);
      Pose<double> poseQ;
      poseQ.rotation = toFloatGrid(rot.rounded);
      poseQ.translation = toFloatGrid((1.0 + 9.0 * step / 20.0) * axis);
      const Vec3d s = toFloatGrid(mink_test::randomUnitVector(rng));
      std::ostringstream what;
      what << "pair " << mink_test::paperShapeName(pair.first) << "-" << mink_test::paperShapeName(pair.second)
           << " step " << step;
      const auto P = ConvexPolyhedron<double>::fromPoints(ptsP);
      const auto Q = ConvexPolyhedron<double>::fromPoints(ptsQ);
      const auto x = mink::mddExact<Rational>(P, Pose<double>(), Q, poseQ, s);
      expectExact(x, reference(P, Pose<double>(), Q, poseQ, s), what.str());
      ++queries;
      contacts += x.status != MddStatus::NoContact;
      for (int k : {-300, -120, 120, 280}) {
        std::vector<Vec3d> sp, sq;
        for (const Vec3d& v : ptsP) sp.push_back(std::ldexp(1.0, k) * v);
        for (const Vec3d& v : ptsQ) sq.push_back(std::ldexp(1.0, k) * v);
        Pose<double> scaled = poseQ;
        scaled.translation *= std::ldexp(1.0, k);
        const auto y = mink::mddExact<Rational>(ConvexPolyhedron<double>::fromPoints(sp), Pose<double>(),
                                                ConvexPolyhedron<double>::fromPoints(sq), scaled, s);
        EXPECT_EQ(y.status, x.status) << what.str() << " at 2^" << k;
        EXPECT_EQ(y.parameter, x.parameter * (k > 0 ? Rational(std::ldexp(1.0, k)) : 1 / Rational(std::ldexp(1.0, -k))))
            << what.str() << " at 2^" << k;
      }
      // The same numbers in float.
      auto converted = [](const std::vector<Vec3d>& pts, auto zero) {
        using U = decltype(zero);
        std::vector<mink::Vec3<U>> out;
        for (const Vec3d& v : pts) out.push_back(v.cast<U>());
        return mink::ConvexPolyhedron<U>::fromPoints(out);
      };
      Pose<float> poseF;
      poseF.rotation = poseQ.rotation.cast<float>();
      poseF.translation = poseQ.translation.cast<float>();
      const auto f = mink::mddExact<Rational>(converted(ptsP, 0.0f), Pose<float>(), converted(ptsQ, 0.0f), poseF,
                                              mink::Vec3<float>(s.cast<float>()));
      EXPECT_EQ(f.status, x.status) << what.str() << " in float";
      EXPECT_EQ(f.parameter, x.parameter) << what.str() << " in float";
    }
  }
  EXPECT_GT(contacts, queries / 3);
}

// The paths that cannot be certified answer through mdd<Gmpq>, exactly: a line that
// misses M, a line in a facet plane of M (grazing), and a fromMesh shape in double (convex
// only within its tolerance, so a local maximum is not proven global).
TEST(MddExact, FallbackAnswersExactly) {
  std::vector<Vec3d> cube;
  for (int i = 0; i < 8; ++i) cube.emplace_back((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
  const auto P = ConvexPolyhedron<double>::fromPoints(cube);
  Pose<double> poseQ;
  poseQ.translation = Vec3d(3, 0.5, 0.25);
  // Misses: Q beside P, s along z; certified by the separating direction. Beside P's
  // face exactly (touching the face's plane x = 1 from outside along the whole line) it
  // is a grazing line instead.
  {
    Pose<double> far = poseQ;
    far.translation = Vec3d(5, 0, 0);
    const auto x = mink::mddExact<Rational>(P, Pose<double>(), P, far, Vec3d(0, 0, 1));
    EXPECT_TRUE(x.certified);
    expectExact(x, reference(P, Pose<double>(), P, far, Vec3d(0, 0, 1)), "misses");
    far.translation = Vec3d(2, 3, 0);
    const auto y = mink::mddExact<Rational>(P, Pose<double>(), P, far, Vec3d(0, 0, 1));
    expectExact(y, reference(P, Pose<double>(), P, far, Vec3d(0, 0, 1)), "misses along an edge line");
  }
  // Grazing: Q resting on P's top face, sliding along it.
  {
    Pose<double> rest;
    rest.translation = Vec3d(0.5, 0.25, 2);
    const Vec3d s(1, 0, 0);
    const auto x = mink::mddExact<Rational>(P, Pose<double>(), P, rest, s);
    EXPECT_FALSE(x.certified);
    const auto e = reference(P, Pose<double>(), P, rest, s);
    EXPECT_EQ(x.status, MddStatus::Touching);
    expectExact(x, e, "grazing");
  }
  // A fromMesh shape in double is not an exact hull: never certified, still exact.
  {
    const std::vector<std::vector<int>> quads = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                                 {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    const auto M = ConvexPolyhedron<double>::fromMesh(cube, quads);
    ASSERT_FALSE(M.isExactHull());
    ASSERT_TRUE(P.isExactHull());
    const Vec3d s(-1, 0.1, 0.05);
    const auto x = mink::mddExact<Rational>(M, Pose<double>(), P, poseQ, s);
    EXPECT_FALSE(x.certified);
    expectExact(x, reference(M, Pose<double>(), P, poseQ, s), "fromMesh");
    // The same shape from points is certified.
    const auto y = mink::mddExact<Rational>(P, Pose<double>(), P, poseQ, s);
    EXPECT_TRUE(y.certified);
    EXPECT_EQ(y.parameter, x.parameter);
    EXPECT_EQ(y.status, MddStatus::Separated);
  }
  // Bad input is rejected as by mdd().
  EXPECT_THROW((void)mink::mddExact<Rational>(P, Pose<double>(), P, poseQ, Vec3d(0, 0, 0)), mink::InvalidInput);
}

}  // namespace
