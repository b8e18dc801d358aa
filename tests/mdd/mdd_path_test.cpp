// tests/mdd/mdd_path_test.cpp — MddResult::path (mdd/mdd_types.hpp): which step of mdd()
// answered. Checked against the result's own independent flags on the degenerate contacts
// and their generic twins (tests/support/degenerate_contacts.hpp): usedFallback iff the
// exhaustive scan or the chord answered, a Grazing face iff the grazing step did, fromCache
// iff the cache did, None only without an answer; a repeated query with a cache is answered
// by it, a caller's visit cap of 0 by nothing. A one-off penetrating query that stops at
// the nearer exit answers as the paper's search of both exits does. MddResult::featureOfP / featureOfQ: with Q
// moved by parameter * s, the typed features meet (a vertex on a face's plane, two edges).
// An EE exit whose edges the converged exit portal's corners name is certified alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "mink/mink.hpp"
#include "support/degenerate_contacts.hpp"
#include "support/paper_shapes.hpp"

namespace {

using mink::MddPath;
using mink::MddStatus;

struct Pair {
  mink::ConvexPolyhedron<double> P, Q;
  mink::Pose<double> poseP, poseQ;
};

Pair build(const mink_test::ContactScene& sc) {
  Pair p{mink::ConvexPolyhedron<double>::fromPoints(sc.P), mink::ConvexPolyhedron<double>::fromPoints(sc.Q), {}, {}};
  p.poseQ.rotation = sc.rotQ;
  p.poseQ.translation = sc.tQ;
  return p;
}

// mdd() on every direction of the degenerate contacts at n = 12 and their generic twins:
// check(pair, direction, result, label).
template <class Check>
void forEveryContact(Check&& check) {
  for (const std::string& family : mink_test::degenerateFamilies()) {
    for (bool generic : {false, true}) {
      const mink_test::ContactScene sc = mink_test::degenerateScene(family, 12, generic);
      const Pair p = build(sc);
      for (std::size_t d = 0; d < sc.dirs.size(); ++d) {
        const std::string label = family + (generic ? " generic" : " degenerate") + " direction " + std::to_string(d);
        check(p, sc.dirs[d], mink::mdd(p.P, p.poseP, p.Q, p.poseQ, sc.dirs[d]), label);
      }
    }
  }
}

TEST(MddPath, AgreesWithFallbackGrazingAndCacheFlags) {
  int searched = 0;
  forEveryContact([&](const Pair&, const Eigen::Vector3d&, const mink::MddResult<double>& r, const std::string& label) {
    const bool fallback = r.path == MddPath::Exhaustive || r.path == MddPath::Chord;
    EXPECT_EQ(r.usedFallback, fallback) << label;
    EXPECT_EQ(r.faceType == mink::MddFaceType::Grazing, r.path == MddPath::Grazing) << label;
    EXPECT_FALSE(r.fromCache) << label;
    EXPECT_NE(r.path, MddPath::Cache) << label;
    if (r.status != MddStatus::NoContact && r.status != MddStatus::IterationLimit) {
      EXPECT_NE(r.path, MddPath::None) << label;
    }
    searched += r.path == MddPath::Search || r.path == MddPath::Certificate;
  });
  EXPECT_GT(searched, 0);
}

// How far P's feature fp (at poseP) and Q's feature fq (at poseQ moved by `move`) are from
// touching, world frame: a vertex from the other's face plane (FV, VF), or the distance
// between the two edges' lines (EE; 0 when parallel).
double featureGap(const mink::ConvexPolyhedron<double>& P, const mink::Pose<double>& poseP, mink::Feature fp,
                  const mink::ConvexPolyhedron<double>& Q, const mink::Pose<double>& poseQ, mink::Feature fq,
                  const Eigen::Vector3d& move) {
  using K = mink::FeatureKind;
  auto valid = [](const mink::ConvexPolyhedron<double>& S, mink::Feature f) {
    const int n = f.kind == K::Vertex ? S.numVertices() : f.kind == K::Edge ? S.numEdges() : S.numFaces();
    return f.kind != K::None && f.index >= 0 && f.index < n;
  };
  if (!valid(P, fp) || !valid(Q, fq)) return 1e300;
  auto inP = [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return poseP.rotation * x + poseP.translation; };
  auto inQ = [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return poseQ.rotation * x + poseQ.translation + move; };
  auto vertexToFace = [](const Eigen::Vector3d& v, const Eigen::Vector3d& n, const Eigen::Vector3d& onFace) {
    return std::abs(n.dot(v - onFace));
  };
  if (fp.kind == K::Face && fq.kind == K::Vertex)
    return vertexToFace(inQ(Q.vertex(fq.index)), poseP.rotation * P.faceNormal(fp.index),
                        inP(P.vertex(P.faceVertices(fp.index)[0])));
  if (fp.kind == K::Vertex && fq.kind == K::Face)
    return vertexToFace(inP(P.vertex(fp.index)), poseQ.rotation * Q.faceNormal(fq.index),
                        inQ(Q.vertex(Q.faceVertices(fq.index)[0])));
  if (fp.kind == K::Edge && fq.kind == K::Edge) {
    const auto [a0, a1] = P.edgeVertices(fp.index);
    const auto [b0, b1] = Q.edgeVertices(fq.index);
    const Eigen::Vector3d pa = inP(P.vertex(a0)), da = inP(P.vertex(a1)) - pa;
    const Eigen::Vector3d qb = inQ(Q.vertex(b0)), db = inQ(Q.vertex(b1)) - qb;
    const Eigen::Vector3d c = da.cross(db);
    if (c.norm() <= 1e-12 * da.norm() * db.norm()) return 0.0;
    return std::abs((qb - pa).dot(c)) / c.norm();
  }
  return 1e300;
}

// The witnesses' distance to the face of P or vertex / edge they must lie on.
double witnessOnP(const mink::ConvexPolyhedron<double>& P, mink::Feature f, const Eigen::Vector3d& x) {
  if (f.kind == mink::FeatureKind::Face) return std::abs(P.faceNormal(f.index).dot(x) - P.faceOffset(f.index));
  return 0.0;  // (a vertex or edge of P: the gap above decides)
}

TEST(MddPath, TypedFeaturesMeetWhenQIsMoved) {
  int checked[3] = {0, 0, 0};
  forEveryContact([&](const Pair& p, const Eigen::Vector3d& s, const mink::MddResult<double>& r, const std::string& label) {
    const mink::Feature fp = r.featureOfP(), fq = r.featureOfQ();
    EXPECT_EQ(fp.index, r.featureP) << label;
    EXPECT_EQ(fq.index, r.featureQ) << label;
    using K = mink::FeatureKind;
    switch (r.faceType) {
      case mink::MddFaceType::FV:
        EXPECT_EQ(fp.kind, K::Face) << label;
        EXPECT_EQ(fq.kind, K::Vertex) << label;
        ++checked[0];
        break;
      case mink::MddFaceType::VF:
        EXPECT_EQ(fp.kind, K::Vertex) << label;
        EXPECT_EQ(fq.kind, K::Face) << label;
        ++checked[1];
        break;
      case mink::MddFaceType::EE:
        EXPECT_EQ(fp.kind, K::Edge) << label;
        EXPECT_EQ(fq.kind, K::Edge) << label;
        ++checked[2];
        break;
      default:
        EXPECT_EQ(fp.kind, r.featureP >= 0 ? K::Vertex : K::None) << label;
        return;
    }
    // Q moved by parameter * s touches P: the named features meet (a vertex on the
    // other's face plane, two edge lines crossing), and an FV witness lies on P's face.
    const double scale = 1.0 + r.witnessP.cwiseAbs().maxCoeff() + std::abs(r.translation);
    EXPECT_LT(featureGap(p.P, p.poseP, fp, p.Q, p.poseQ, fq, r.parameter * s), 1e-9 * scale)
        << label << " " << mink::toString(r.faceType);
    EXPECT_LT(witnessOnP(p.P, fp, r.witnessP), 1e-9 * scale) << label;  // poseP is the identity
  });
  EXPECT_GT(checked[0] + checked[1] + checked[2], 50) << checked[0] << " " << checked[1] << " " << checked[2];
}

TEST(MddPath, RepeatedQueryIsAnsweredByTheCache) {
  // Boxes turned by the generic twin's rotation, Q overlapping P slightly: penetrating
  // along s, each exit face a proper face of M. The pair's first query keeps only the
  // nearer end of the chord (the other lies beyond the centre of duality), the second
  // both ends, and the third is answered by the cache.
  const mink_test::ContactScene sc = mink_test::degenerateScene("boxes-aligned", 4, true);
  const Pair p = build(sc);
  mink::MddCache<double> cache;
  const Eigen::Vector3d s(0.1, 0.2, -1.0);
  const auto first = mink::mdd(p.P, p.poseP, p.Q, p.poseQ, s, cache);
  ASSERT_NE(first.path, MddPath::None);
  EXPECT_NE(first.path, MddPath::Cache);
  const auto second = mink::mdd(p.P, p.poseP, p.Q, p.poseQ, s, cache);
  EXPECT_EQ(second.parameter, first.parameter);
  const auto again = mink::mdd(p.P, p.poseP, p.Q, p.poseQ, s, cache);
  EXPECT_TRUE(again.fromCache);
  EXPECT_EQ(again.path, MddPath::Cache);
  EXPECT_EQ(again.parameter, first.parameter);
}

TEST(MddPath, CallersVisitCapLeavesNoPath) {
  const mink_test::ContactScene sc = mink_test::degenerateScene("cones-apex", 12, false);
  const Pair p = build(sc);
  mink::MddOptions<double> opt;
  opt.maxVisits = 0;
  const auto r = mink::mdd(p.P, p.poseP, p.Q, p.poseQ, sc.dirs[0], opt);
  ASSERT_EQ(r.status, MddStatus::IterationLimit);
  EXPECT_EQ(r.path, MddPath::None);
}

}  // namespace

namespace {

// Two random convex hulls overlapping by about a tenth of their size (shallow: the origin
// is often nearer one end of the line's chord in M than the centre of duality is), and
// random directions: penetrating queries.
struct Overlap {
  mink::ConvexPolyhedron<double> P, Q;
  mink::Pose<double> poseP, poseQ;
  std::vector<Eigen::Vector3d> dirs;
};

Overlap overlapping(unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  auto cloud = [&](double r, int n) {
    std::vector<Eigen::Vector3d> v;
    for (int i = 0; i < n; ++i) v.push_back(r * Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized());
    return v;
  };
  Overlap o{mink::ConvexPolyhedron<double>::fromPoints(cloud(1.0, 40)),
            mink::ConvexPolyhedron<double>::fromPoints(cloud(0.7, 30)), {}, {}, {}};
  o.poseQ.rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  o.poseQ.translation = Eigen::Vector3d(1.45, 0.1, -0.05);
  for (int i = 0; i < 40; ++i) o.dirs.push_back(Eigen::Vector3d(g(rng), g(rng), g(rng)));
  return o;
}

// A degenerate contact (or its twin) with its directions.
Overlap overlapOf(const mink_test::ContactScene& sc) {
  Overlap o{mink::ConvexPolyhedron<double>::fromPoints(sc.P), mink::ConvexPolyhedron<double>::fromPoints(sc.Q),
            {}, {}, sc.dirs};
  o.poseQ.rotation = sc.rotQ;
  o.poseQ.translation = sc.tQ;
  return o;
}


TEST(MddPath, OneOffPenetratingQueryMatchesBothExits) {
  // A pair's first query stops at the exit towards the origin when it is nearer than the
  // centre of duality (the other exit lies beyond it); the paper's d_min over both exits
  // (what mddExact runs) must give the same status, parameter and face: on shallow
  // overlaps of random hulls, and on the degenerate contacts and their twins.
  std::vector<Overlap> scenes;
  for (unsigned seed = 1; seed <= 5; ++seed) scenes.push_back(overlapping(seed));
  for (const std::string& family : mink_test::degenerateFamilies()) {
    for (bool generic : {false, true}) {
      scenes.push_back(overlapOf(mink_test::degenerateScene(family, 12, generic)));
    }
  }
  int penetrating = 0, skipped = 0;
  for (std::size_t seed = 0; seed < scenes.size(); ++seed) {
    const Overlap& o = scenes[seed];
    for (const Eigen::Vector3d& s : o.dirs) {
      mink::MddCache<double> c1, c2;
      const auto one = mink::mdd(o.P, o.poseP, o.Q, o.poseQ, s, c1);
      const auto both = mink::detail::mddQuery(o.P, o.poseP, o.Q, o.poseQ, s, c2, mink::MddOptions<double>(), true);
      ASSERT_EQ(one.status, both.status) << seed;
      EXPECT_EQ(one.parameter, both.parameter) << seed;
      EXPECT_EQ(one.faceType, both.faceType) << seed;
      EXPECT_EQ(one.featureP, both.featureP) << seed;
      EXPECT_EQ(one.featureQ, both.featureQ) << seed;
      if (one.status != MddStatus::Penetrating) continue;
      EXPECT_LT((one.witnessP - one.witnessQ - one.parameter * s).norm(), 1e-9) << seed;
      ++penetrating;
      // Both exits were kept by the full query; one side only where the second was skipped.
      const int kept1 = (c1.exitFaces[0].type != mink::MddFaceType::None) +
                        (c1.exitFaces[1].type != mink::MddFaceType::None);
      const int kept2 = (c2.exitFaces[0].type != mink::MddFaceType::None) +
                        (c2.exitFaces[1].type != mink::MddFaceType::None);
      EXPECT_EQ(kept2, 2) << seed;
      if (kept1 == 1) {
        ++skipped;
        EXPECT_LT(one.visitedFV + one.visitedVF + one.visitedEE, both.visitedFV + both.visitedVF + both.visitedEE);
      }
      // Kept by side: [0] the exit along +s, [1] along −s; the answer is on its side.
      const int side = one.parameter > 0 ? 0 : 1;
      EXPECT_EQ(c1.exitFaces[side].type, one.faceType) << seed;
      EXPECT_EQ(c1.exitFaces[side].a, one.featureP) << seed;
      EXPECT_EQ(c1.exitFaces[side].b, one.featureQ) << seed;
    }
  }
  std::printf("[mdd one-off] %d penetrating queries, %d stopped at the nearer exit\n", penetrating, skipped);
  EXPECT_GT(penetrating, 50);
  EXPECT_GT(skipped, 10);
  EXPECT_LT(skipped, penetrating);
}

TEST(MddPath, RepeatedPenetratingQueryIsAnsweredByTheCache) {
  // The first query of a pair may keep one end of the chord; the second then searches
  // and keeps both, and from then on a resting contact is answered by the cache.
  const Overlap o = overlapping(7);
  int cachedAnswers = 0, oneEndFirst = 0;
  auto kept = [](const mink::MddCache<double>& c) {
    return (c.exitFaces[0].type != mink::MddFaceType::None) + (c.exitFaces[1].type != mink::MddFaceType::None);
  };
  for (const Eigen::Vector3d& s : o.dirs) {
    mink::MddCache<double> cache;
    const auto first = mink::mdd(o.P, o.poseP, o.Q, o.poseQ, s, cache);
    if (first.status != MddStatus::Penetrating) continue;
    EXPECT_FALSE(first.fromCache);
    const int keptFirst = kept(cache);
    const auto second = mink::mdd(o.P, o.poseP, o.Q, o.poseQ, s, cache);
    if (keptFirst == 1) {
      ++oneEndFirst;
      EXPECT_FALSE(second.fromCache);
    }
    EXPECT_EQ(kept(cache), 2);
    EXPECT_EQ(second.parameter, first.parameter);
    const auto third = mink::mdd(o.P, o.poseP, o.Q, o.poseQ, s, cache);
    EXPECT_TRUE(third.fromCache);
    EXPECT_EQ(third.status, MddStatus::Penetrating);
    EXPECT_EQ(third.parameter, first.parameter);
    cachedAnswers += third.fromCache;
  }
  EXPECT_GT(cachedAnswers, 10);
  EXPECT_GT(oneEndFirst, 0);
}

TEST(MddPath, CallsWithoutACacheAnswerAsAFreshCache) {
  // The overloads without a cache reuse one scratch cache per thread: every answer must be
  // a fresh cache's, field for field, whatever the scratch served before (other shapes,
  // the same query just before: never answered from kept faces).
  std::vector<Overlap> scenes;
  for (unsigned seed = 1; seed <= 3; ++seed) scenes.push_back(overlapping(seed));
  for (const std::string& family : mink_test::degenerateFamilies()) {
    scenes.push_back(overlapOf(mink_test::degenerateScene(family, 12, false)));
  }
  int queries = 0;
  std::size_t longest = 0;
  for (const Overlap& o : scenes) longest = std::max(longest, o.dirs.size());
  // Interleaved: consecutive calls are on different pairs, then each query twice in a row.
  for (std::size_t d = 0; d < longest; ++d) {
    for (std::size_t k = 0; k < scenes.size(); ++k) {
      const Overlap& o = scenes[k];
      if (d >= o.dirs.size()) continue;
      const Eigen::Vector3d& s = o.dirs[d];
      const std::string label = "scene " + std::to_string(k) + " direction " + std::to_string(d);
      for (int again = 0; again < 2; ++again) {
        mink::MddCache<double> fresh;
        const auto a = mink::mdd(o.P, o.poseP, o.Q, o.poseQ, s);
        const auto b = mink::mdd(o.P, o.poseP, o.Q, o.poseQ, s, fresh);
        ASSERT_EQ(a.status, b.status) << label;
        EXPECT_EQ(a.path, b.path) << label;
        EXPECT_FALSE(a.fromCache) << label;
        EXPECT_EQ(a.faceType, b.faceType) << label;
        EXPECT_EQ(a.featureP, b.featureP) << label;
        EXPECT_EQ(a.featureQ, b.featureQ) << label;
        if (a.status == MddStatus::Separated || a.status == MddStatus::Penetrating) {
          EXPECT_EQ(a.parameter, b.parameter) << label;
          EXPECT_EQ(a.witnessP, b.witnessP) << label;
          EXPECT_EQ(a.witnessQ, b.witnessQ) << label;
          EXPECT_EQ(a.normal, b.normal) << label;
        }
        EXPECT_EQ(a.visitedFV + a.visitedVF + a.visitedEE, b.visitedFV + b.visitedVF + b.visitedEE) << label;
        mink::MddCache<double> fresh2, fresh3;
        EXPECT_EQ(mink::intersects(o.P, o.poseP, o.Q, o.poseQ), mink::intersects(o.P, o.poseP, o.Q, o.poseQ, fresh2))
            << label;
        const auto fa = mink::firstContact(o.P, o.poseP, o.Q, o.poseQ, s);
        const auto fb = mink::firstContact(o.P, o.poseP, o.Q, o.poseQ, s, fresh3);
        EXPECT_EQ(fa.hit, fb.hit) << label;
        EXPECT_EQ(fa.fraction, fb.fraction) << label;
        ++queries;
      }
    }
  }
  EXPECT_GT(queries, 200);
}

TEST(MddPath, AnEdgePairExitIsNamedByThePortalsCorners) {
  // A converged exit portal's corners are points of the exit facet: where they are two
  // adjacent vertices of P and two of Q, tryAround (mdd/detail/exit_face.hpp) certifies
  // that EE face alone, before the FV / VF faces and the edge pairs around the portal's
  // support vertices. On separated one-off queries of the paper's two ellipsoids (P3 and
  // P4; lines towards Q's centre, turned by up to ~30 degrees): most EE answers of the
  // certificate path visit that one face and no other, and every answer's face is a
  // supporting plane of M at the contact, checked from the vertices themselves: with Q
  // moved by parameter * s, P's support along the normal equals Q's along its opposite.
  std::mt19937 rng(7u);
  const auto P = mink::ConvexPolyhedron<double>::fromPoints(mink_test::paperShape(mink_test::PaperShape::P3, rng));
  const auto Q = mink::ConvexPolyhedron<double>::fromPoints(mink_test::paperShape(mink_test::PaperShape::P4, rng));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int separated = 0, edgeCertified = 0, alone = 0;
  for (int k = 0; k < 400; ++k) {
    Eigen::Quaterniond q(u(rng), u(rng), u(rng), u(rng));
    q.normalize();
    mink::Pose<double> poseQ;
    poseQ.rotation = q.toRotationMatrix();
    Eigen::Vector3d dir(u(rng), u(rng), u(rng));
    dir.normalize();
    poseQ.translation = (12.0 + 4.0 * u(rng)) * dir;
    const Eigen::Vector3d s = (-dir + 0.5 * Eigen::Vector3d(u(rng), u(rng), u(rng))).normalized();
    mink::MddCache<double> fresh;
    const auto r = mink::mdd(P, mink::Pose<double>(), Q, poseQ, s, fresh);
    if (r.status != MddStatus::Separated) continue;
    ++separated;
    double hP = -1e300, hQ = 1e300;
    for (int v = 0; v < P.numVertices(); ++v) hP = std::max(hP, r.normal.dot(P.vertex(v)));
    for (int v = 0; v < Q.numVertices(); ++v)
      hQ = std::min(hQ, r.normal.dot(poseQ.rotation * Q.vertex(v) + poseQ.translation + r.parameter * s));
    EXPECT_NEAR(hP, hQ, 1e-9) << "query " << k;
    if (r.path != MddPath::Certificate || r.faceType != mink::MddFaceType::EE) continue;
    ++edgeCertified;
    alone += r.visitedFV + r.visitedVF == 0 && r.visitedEE == 1;
  }
  std::printf("[mdd corners] %d separated queries, %d EE answers by certificate, %d of them alone\n", separated,
              edgeCertified, alone);
  EXPECT_GT(separated, 200);
  EXPECT_GT(edgeCertified, 50);
  EXPECT_GE(4 * alone, 3 * edgeCertified);
}

}  // namespace
