// mink_mdd_bench — the minimum directional distance (MDD) against its peers (issue 4):
//   1. paper   the MDD paper's experiment (Choi et al., section VII, Fig. 14): the ten pairs
//              of its six polyhedra; per pair mink's time per query (separated / penetrating),
//              the share of the faces of M = P ⊕ −Q it visits, its error against the exact
//              CGAL reference, and beside it on the same queries libccd GJK (yes/no), libccd
//              MPR read as a directional distance, FCL signed distance, Bullet's two convex
//              casts read as a directional distance, and the CGAL brute force.
//   2. scaling ellipsoid pairs of 100 .. 100k vertices: build times and time per query.
//   3. coherence a pair moving along a smooth path: cold against warm-cache queries.
//   4. precision mink in float, double, long double and exact rationals: time against error.
//   5. prepare   the first query on a fresh, unprepared large shape (it builds the shape's
//                Dobkin–Kirkpatrick hierarchy) against the first query after prepare(), and
//                prepare()'s own time (mink/hierarchy/prepare.hpp).
// The adapters for the peers, and what each one measures, are in benchmarks/peers.hpp.
//
// Placements follow the paper: for each orientation of Q and a random axis u, the offset
// λ0 along u at which P and Q touch is found by bisection on libccd's GJK overlap test, and
// Q is placed at λ0 + d along u for d = −1.5, −1.35, .., +1.5 (21 placements: 10 overlapping,
// 1 touching, 10 apart; the paper used the shortest distance, we use the directional
// distance along u). For each placement, random unit directions s.
//
// Timing: every query is timed on its own with std::chrono::steady_clock; the whole query
// list of a pair runs once per method untimed (warm-up), then `passes` times per method,
// methods interleaved pass by pass; a query's time is its minimum over the passes (the
// machine is shared: the minimum drops the passes in which the thread lost its core).
// Reported: median and mean over the queries. "mink cold" runs each query with an
// MddCache that just served another pair of shapes (so it holds no hints for this pair,
// but its buffers are allocated); "mink no cache" calls mdd() without a cache (it
// allocates its work buffers per call); "mink warm" keeps one cache along a coherent path.
//
// Usage: mink_mdd_bench [outdir] [--quick] [--orientations O] [--directions D]
//                       [--exact-orientations E] [--passes K] [--sections paper,scaling,...]
//   outdir default benchmarks/results; writes mdd_paper.csv, mdd_scaling.csv,
//   mdd_coherence.csv, mdd_precision.csv, mdd_prepare.csv and mdd_targets.csv (the printed tables go to
//   stdout). Defaults: 40 orientations x 21 placements x 10 directions per pair, the exact
//   reference on 4 orientations, 3 timed passes (about 3 minutes on 2 shared cores).
#include <CGAL/Gmpq.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "mink/mink.hpp"
#include "bench_common.hpp"
#include "peers.hpp"
#include "support/exact_placement.hpp"
#include "support/gjk_reference.hpp"
#include "support/mdd_reference.hpp"
#include "support/paper_shapes.hpp"

namespace {

using mink::ConvexPolyhedron;
using mink::MddStatus;
using mink::Pose;
using mink_bench::Mat3d;
using mink_bench::Vec3d;
using mink_test::Rational;
using Clock = std::chrono::steady_clock;
using mink_bench::loadAverage;
using mink_bench::machineLine;
using mink_bench::quantile;

volatile double gSink = 0;

double microsSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
}

// ---------------------------------------------------------------------------------------
// Small statistics and output helpers.

struct Summary {
  std::size_t n = 0;
  double median = std::nan(""), mean = std::nan(""), q1 = std::nan(""), q3 = std::nan(""), max = std::nan("");
};

Summary summarize(const std::vector<double>& v) {
  Summary s;
  s.n = v.size();
  if (v.empty()) return s;
  s.median = quantile(v, 0.5);
  s.q1 = quantile(v, 0.25);
  s.q3 = quantile(v, 0.75);
  double sum = 0;
  for (double x : v) sum += x;
  s.mean = sum / v.size();
  s.max = *std::max_element(v.begin(), v.end());
  return s;
}

/// One CSV per section, all with the same columns; '#' lines carry the machine and setup.
struct Csv {
  std::ofstream out;
  Csv(const std::string& path, const std::string& setup) : out(path) {
    out << "# machine: " << machineLine() << "\n# compiler: " << __VERSION__ << "\n# load average at start: "
        << loadAverage() << "\n# setup: " << setup << "\n";
    out << "section,case,method,subset,count,median_us,mean_us,q1_us,q3_us,max_err,median_err,value,note\n";
  }
  void row(const std::string& section, const std::string& cs, const std::string& method, const std::string& subset,
           const Summary& t, double maxErr = std::nan(""), double medErr = std::nan(""), double value = std::nan(""),
           const std::string& note = "") {
    out << section << ',' << cs << ',' << method << ',' << subset << ',' << t.n << ',' << t.median << ',' << t.mean
        << ',' << t.q1 << ',' << t.q3 << ',' << maxErr << ',' << medErr << ',' << value << ',' << note << '\n';
  }
  void value(const std::string& section, const std::string& cs, const std::string& method, double v,
             const std::string& note = "") {
    row(section, cs, method, "value", Summary(), std::nan(""), std::nan(""), v, note);
  }
};

// ---------------------------------------------------------------------------------------
// Shapes, placements and queries.

std::vector<Vec3d> ellipsoidPoints(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<Vec3d> pts;
  pts.reserve(n);
  while (static_cast<int>(pts.size()) < n) {
    Vec3d p(mink_test::standardNormal(rng), mink_test::standardNormal(rng), mink_test::standardNormal(rng));
    const double r = p.norm();
    if (r == 0) continue;
    pts.push_back(Vec3d(2 * p.x() / r, 2 * p.y() / r, 5 * p.z() / r));
  }
  return pts;
}

struct Query {
  int orient = 0, step = 0;
  Mat3d R = Mat3d::Identity();  // Q's rotation (P is at the identity)
  Vec3d t = Vec3d::Zero();      // Q's translation
  Vec3d s = Vec3d::UnitX();     // unit direction
  // Exact answer (orientations < exactOrientations only).
  bool hasExact = false;
  mink_test::MddRefStatus exactStatus = mink_test::MddRefStatus::NoContact;
  mink_test::OriginLocation exactOrigin = mink_test::OriginLocation::Outside;  // do P and Q overlap?
  double exactTranslation = 0;
  Rational exactT;
  bool exactTie = false;
};

struct Orientation {
  mink_test::RationalRotation rot;
  Vec3d base = Vec3d::Zero();  // translation that puts Q's centroid on P's
  Vec3d axis = Vec3d::UnitX();
  double touch = 0;            // λ0: Q at base + λ0 axis touches P (GJK bisection)
  double facetsM = 0, facetsEE = 0;  // face counts of M (exact reference), when built
};

/// λ0 along `axis` at which Q (rotation R) just touches P, by bisection on ccdGJKIntersect
/// between the coinciding centroids (overlap) and a surely separated offset.
double touchingOffset(mink_bench::CcdPair& ccd, const Mat3d& R, const Vec3d& base, const Vec3d& axis,
                      double far) {
  double lo = 0, hi = far;
  for (int i = 0; i < 60 && hi - lo > 1e-13 * far; ++i) {
    const double mid = 0.5 * (lo + hi);
    ccd.place(Mat3d::Identity(), Vec3d::Zero(), R, base + mid * axis);
    (ccd.gjkIntersect() ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

/// The paper-style query list: `orientations` × 21 placements × `directions`.
std::vector<Query> makeQueries(const ConvexPolyhedron<double>& P, const ConvexPolyhedron<double>& Q,
                               std::vector<Orientation>& orients, int orientations, int directions, double step,
                               std::mt19937& rng) {
  mink_bench::CcdPair ccd(P, Q);
  const double far = mink_bench::radiusAboutCentroid(P) + mink_bench::radiusAboutCentroid(Q) + 1.0;
  std::vector<Query> qs;
  for (int o = 0; o < orientations; ++o) {
    Orientation ori;
    ori.rot = mink_test::randomRationalRotation(rng);
    ori.axis = mink_test::randomUnitVector(rng);
    ori.base = P.interiorPoint() - ori.rot.rounded * Q.interiorPoint();
    ori.touch = touchingOffset(ccd, ori.rot.rounded, ori.base, ori.axis, far);
    for (int k = 0; k <= 20; ++k) {
      const double d = step * (k - 10);
      for (int j = 0; j < directions; ++j) {
        Query q;
        q.orient = o;
        q.step = k;
        q.R = ori.rot.rounded;
        q.t = ori.base + (ori.touch + d) * ori.axis;
        q.s = mink_test::randomUnitVector(rng);
        qs.push_back(q);
      }
    }
    orients.push_back(ori);
  }
  return qs;
}

/// mink queries in scalar T; "cold" clears the cache's hints by serving a dummy pair first.
template <class T>
struct MinkRunner {
  ConvexPolyhedron<T> boxA, boxB;
  mink::MddCache<T> cache;
  Pose<T> dummyPose;
  mink::Vec3<T> dummyS;
  MinkRunner() : boxA(box(T(1))), boxB(box(T(1))) {
    dummyPose.translation = mink::Vec3<T>(T(3), T(0), T(0));
    dummyS = mink::Vec3<T>(T(-1), T(0), T(0));
  }
  static ConvexPolyhedron<T> box(T h) {
    std::vector<mink::Vec3<T>> v;
    for (int i = 0; i < 8; ++i) v.emplace_back((i & 1) ? h : T(-h), (i & 2) ? h : T(-h), (i & 4) ? h : T(-h));
    return ConvexPolyhedron<T>::fromPoints(v);
  }
  void clearHints() { mink::mdd(boxA, Pose<T>(), boxB, dummyPose, dummyS, cache); }
};

// ---------------------------------------------------------------------------------------
// Options.

struct Options {
  std::string outdir = "benchmarks/results";
  bool quick = false;
  int orientations = 40, directions = 10, exactOrientations = 4, passes = 3;
  int gmpqDirections = 2;      // precision: directions per placement for the exact rationals
  int scalingOrientations = 4, scalingDirections = 5, coherenceFrames = 1000;
  std::vector<int> sizes = {100, 1000, 10000, 100000};
  std::string sections = "paper,scaling,coherence,precision,prepare";
  bool has(const std::string& s) const { return sections.find(s) != std::string::npos; }
};

std::string setupLine(const Options& o) {
  std::ostringstream s;
  s << "orientations=" << o.orientations << " directions=" << o.directions
    << " exact_orientations=" << o.exactOrientations << " passes=" << o.passes
    << " gmpq_directions=" << o.gmpqDirections << " scaling=" << o.scalingOrientations << "x21x"
    << o.scalingDirections << " coherence_frames=" << o.coherenceFrames << (o.quick ? " (--quick)" : "");
  return s.str();
}

// ---------------------------------------------------------------------------------------
// Timing helper: per-query minimum over passes, methods interleaved.

struct Method {
  std::string name;
  // Runs query i; returns its time in microseconds (most methods time the whole call, MPR
  // reports the time of its libccd calls only).
  std::function<double(std::size_t)> run;
  std::vector<double> best;
};

void timeMethods(std::vector<Method>& methods, std::size_t count, int passes) {
  for (Method& m : methods) m.best.assign(count, std::numeric_limits<double>::infinity());
  for (int pass = 0; pass <= passes; ++pass) {
    for (Method& m : methods) {
      for (std::size_t i = 0; i < count; ++i) {
        const double us = m.run(i);
        if (pass > 0) m.best[i] = std::min(m.best[i], us);
      }
    }
  }
}

std::vector<double> subset(const std::vector<double>& v, const std::vector<int>& idx) {
  std::vector<double> out;
  out.reserve(idx.size());
  for (int i : idx) out.push_back(v[i]);
  return out;
}

double errWithTie(double got, const Query& q) {
  double e = std::abs(got - q.exactTranslation);
  if (q.exactTie) e = std::min(e, std::abs(got + q.exactTranslation));
  return e;
}

// ---------------------------------------------------------------------------------------
// Shapes of the paper, built once.

struct PaperShapes {
  std::vector<std::vector<Vec3d>> pts;  // by PaperShape index
  std::vector<std::unique_ptr<ConvexPolyhedron<double>>> poly;
  std::vector<std::unique_ptr<mink_test::GjkShape>> fcl;
  PaperShapes() {
    std::mt19937 rng(20260404u);
    for (auto id : mink_test::kPaperShapes) {
      pts.push_back(mink_test::paperShape(id, rng));
      poly.push_back(std::make_unique<ConvexPolyhedron<double>>(ConvexPolyhedron<double>::fromPoints(pts.back())));
      fcl.push_back(std::make_unique<mink_test::GjkShape>(pts.back()));
    }
  }
};

int idx(mink_test::PaperShape s) { return static_cast<int>(s); }

struct PairData {
  std::string name;
  int iP = 0, iQ = 0;
  std::vector<Orientation> orients;
  std::vector<Query> queries;
};

Eigen::Isometry3d iso(const Mat3d& R, const Vec3d& t) {
  Eigen::Isometry3d x = Eigen::Isometry3d::Identity();
  x.linear() = R;
  x.translation() = t;
  return x;
}

// Aggregates for the target lines.
struct Targets {
  std::vector<double> gjkRatio, mprRatio, mprRatio1, bulletRatio, intersectsRatio;  // per pair
  double maxErr = 0, shareM = 0, shareEE = 0;
  long long shareCount = 0;
  double scalingCold1k = 0, scalingCold100k = 0, coherenceRatio = 0, exactOverDouble = 0;
};

// ---------------------------------------------------------------------------------------
// 1. The paper's experiment.

void paperSection(const Options& opt, const PaperShapes& shapes, std::vector<PairData>& pairs, Targets& tg) {
  Csv csv(opt.outdir + "/mdd_paper.csv", setupLine(opt));
  std::printf("\n== 1. The paper's experiment (section VII): 10 pairs, %d orientations x 21 placements x %d "
              "directions per pair (timing); exact CGAL reference on the first %d orientations ==\n",
              opt.orientations, opt.directions, opt.exactOrientations);
  std::printf("   times: us per query, median [mean]; sep / pen: queries mink reports Separated / Penetrating\n");
  std::printf("%-7s %5s %5s %5s | %-17s %-17s %-17s %-17s | %-17s %-17s %-17s %-17s %-17s %-17s %-17s %-9s | %-16s\n",
              "pair", "sep", "pen", "miss", "mink cold sep", "mink cold pen", "mink no-cache all", "mink intersects",
              "ccd GJK (y/n)", "ccd MPR pen (2x)", "MPR tol1e-4 (2x)", "FCL signed dist", "Bullet GJK cast",
              "Bullet subsimplex", "Bt subsimplex pen", "mink/GJK", "CGAL build+query");
  std::mt19937 rng(4u);
  std::vector<double> allMink, allGjk;
  for (const auto& pr : mink_test::kPaperPairs) {
    PairData pd;
    pd.iP = idx(pr.first);
    pd.iQ = idx(pr.second);
    pd.name = std::string(mink_test::paperShapeName(pr.first)) + "-" + mink_test::paperShapeName(pr.second);
    const ConvexPolyhedron<double>& P = *shapes.poly[pd.iP];
    const ConvexPolyhedron<double>& Q = *shapes.poly[pd.iQ];
    pd.queries = makeQueries(P, Q, pd.orients, opt.orientations, opt.directions, 0.15, rng);
    std::vector<Query>& qs = pd.queries;
    const std::size_t n = qs.size();

    // Exact reference (CGAL) on the first orientations: its build is the brute force's
    // per-placement cost, its query the per-direction cost.
    std::vector<double> cgalBuild, cgalQuery;
    for (int o = 0; o < std::min(opt.exactOrientations, opt.orientations); ++o) {
      Orientation& ori = pd.orients[o];
      auto t0 = Clock::now();
      const mink_test::MinkowskiDifferenceReference ref(
          mink_test::toExact(shapes.pts[pd.iP]), mink_test::placeExact(shapes.pts[pd.iQ], ori.rot.exact,
                                                                       mink_test::Vec3r::Zero()));
      cgalBuild.push_back(microsSince(t0));
      ori.facetsM = static_cast<double>(ref.facets().size());
      ori.facetsEE = std::max(1.0, ori.facetsM - P.numFaces() - Q.numFaces());
      for (Query& q : qs) {
        if (q.orient != o) continue;
        t0 = Clock::now();
        const auto e = ref.query(mink_test::toExact(q.s), mink_test::toExact(q.t));
        cgalQuery.push_back(microsSince(t0));
        q.hasExact = true;
        q.exactStatus = e.status;
        q.exactOrigin = e.origin;
        q.exactTranslation = e.translation;
        q.exactT = e.t;
        q.exactTie = e.tie;
      }
    }

    // Methods.
    MinkRunner<double> cold;
    mink::MddCache<double> icache;
    mink_bench::CcdPair ccd(P, Q), ccdDefault(P, Q, 1e-4);
    mink_bench::BulletCast<btGjkConvexCast> bgjk(P, Q);
    mink_bench::BulletCast<btSubsimplexConvexCast> bsub(P, Q);
    const fcl::Convexd& fP = shapes.fcl[pd.iP]->fclConvex();
    const fcl::Convexd& fQ = shapes.fcl[pd.iQ]->fclConvex();
    std::vector<mink::MddResult<double>> rCold(n);
    std::vector<mink_bench::MprAnswer> rMpr(n), rMprD(n);
    std::vector<mink_bench::CastAnswer> rBg(n), rBs(n);
    std::vector<char> rGjk(n), rInt(n);
    std::vector<double> rFcl(n);
    const Pose<double> I;
    auto poseOf = [&](const Query& q) {
      Pose<double> p;
      p.rotation = q.R;
      p.translation = q.t;
      return p;
    };
    std::vector<Method> methods;
    methods.push_back({"mink_cold", [&](std::size_t i) {
                         const Query& q = qs[i];
                         const Pose<double> pq = poseOf(q);
                         cold.clearHints();
                         const auto t0 = Clock::now();
                         rCold[i] = mink::mdd(P, I, Q, pq, q.s, cold.cache);
                         return microsSince(t0);
                       }, {}});
    methods.push_back({"mink_nocache", [&](std::size_t i) {
                         const Query& q = qs[i];
                         const Pose<double> pq = poseOf(q);
                         const auto t0 = Clock::now();
                         gSink = gSink + mink::mdd(P, I, Q, pq, q.s).translation;
                         return microsSince(t0);
                       }, {}});
    methods.push_back({"mink_intersects", [&](std::size_t i) {
                         const Query& q = qs[i];
                         const Pose<double> pq = poseOf(q);
                         const auto t0 = Clock::now();
                         rInt[i] = mink::intersects(P, I, Q, pq, icache);
                         return microsSince(t0);
                       }, {}});
    methods.push_back({"ccd_gjk", [&](std::size_t i) {
                         const Query& q = qs[i];
                         const auto t0 = Clock::now();
                         ccd.place(Mat3d::Identity(), Vec3d::Zero(), q.R, q.t);
                         rGjk[i] = ccd.gjkIntersect();
                         return microsSince(t0);
                       }, {}});
    methods.push_back({"ccd_mpr", [&](std::size_t i) {
                         const Query& q = qs[i];
                         ccd.place(Mat3d::Identity(), Vec3d::Zero(), q.R, q.t);
                         rMpr[i] = ccd.mprDirectional(q.s);
                         return rMpr[i].micros;
                       }, {}});
    methods.push_back({"ccd_mpr_tol1e-4", [&](std::size_t i) {
                         const Query& q = qs[i];
                         ccdDefault.place(Mat3d::Identity(), Vec3d::Zero(), q.R, q.t);
                         rMprD[i] = ccdDefault.mprDirectional(q.s);
                         return rMprD[i].micros;
                       }, {}});
    methods.push_back({"fcl_signed", [&](std::size_t i) {
                         const Query& q = qs[i];
                         const auto t0 = Clock::now();
                         rFcl[i] = mink_bench::fclSignedDistance(fP, Eigen::Isometry3d::Identity(), fQ, iso(q.R, q.t));
                         return microsSince(t0);
                       }, {}});
    methods.push_back({"bullet_gjk_cast", [&](std::size_t i) {
                         const Query& q = qs[i];
                         const auto t0 = Clock::now();
                         rBg[i] = bgjk.directional(Mat3d::Identity(), Vec3d::Zero(), q.R, q.t, q.s);
                         return microsSince(t0);
                       }, {}});
    methods.push_back({"bullet_subsimplex_cast", [&](std::size_t i) {
                         const Query& q = qs[i];
                         const auto t0 = Clock::now();
                         rBs[i] = bsub.directional(Mat3d::Identity(), Vec3d::Zero(), q.R, q.t, q.s);
                         return microsSince(t0);
                       }, {}});
    timeMethods(methods, n, opt.passes);
    auto byName = [&](const std::string& s) -> const std::vector<double>& {
      for (const Method& m : methods)
        if (m.name == s) return m.best;
      throw std::logic_error(s);
    };

    // Groups by mink's status (checked against the exact status on the subsample below).
    std::vector<int> all, sep, pen, miss, contact;
    for (std::size_t i = 0; i < n; ++i) {
      all.push_back(static_cast<int>(i));
      const MddStatus st = rCold[i].status;
      if (st == MddStatus::Penetrating) pen.push_back(static_cast<int>(i));
      else if (st == MddStatus::NoContact) miss.push_back(static_cast<int>(i));
      else sep.push_back(static_cast<int>(i));
      if (st != MddStatus::NoContact) contact.push_back(static_cast<int>(i));
    }
    // MPR's time on penetrating queries (two calls); one call: its first call only is not
    // separable from the outside, so the split is by the number of calls made.
    for (const Method& m : methods) {
      csv.row("paper", pd.name, m.name, "all", summarize(m.best));
      csv.row("paper", pd.name, m.name, "separated", summarize(subset(m.best, sep)));
      csv.row("paper", pd.name, m.name, "penetrating", summarize(subset(m.best, pen)));
      csv.row("paper", pd.name, m.name, "nocontact", summarize(subset(m.best, miss)));
    }

    // Accuracy and visits on the exact subsample.
    std::vector<double> eMink, eMpr, eMprD, eMprPerp, eBg, eBs, shareM, shareEE, visits, visitsEE;
    int statusMink = 0, statusBg = 0, statusBs = 0, mprMissed = 0, mprFalse = 0, mprFallback = 0, gjkWrong = 0,
        intWrong = 0, fallbacks = 0, exactCount = 0, exactPen = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const Query& q = qs[i];
      const auto& r = rCold[i];
      fallbacks += r.usedFallback;
      if (!q.hasExact) continue;
      ++exactCount;
      const Orientation& ori = pd.orients[q.orient];
      const bool exactContact = q.exactStatus != mink_test::MddRefStatus::NoContact;
      const bool clear = std::abs(q.exactTranslation) > 1e-9;
      if (r.status != MddStatus::NoContact) {
        visits.push_back(r.visitedFV + r.visitedVF + r.visitedEE);
        visitsEE.push_back(r.visitedEE);
        shareM.push_back((r.visitedFV + r.visitedVF + r.visitedEE) / ori.facetsM);
        shareEE.push_back(r.visitedEE / ori.facetsEE);
      }
      if (exactContact != (r.status != MddStatus::NoContact)) ++statusMink;
      if (exactContact && r.status != MddStatus::NoContact) {
        eMink.push_back(errWithTie(r.translation, q));
        const bool pe = r.status == MddStatus::Penetrating;
        if (clear && pe != (q.exactStatus == mink_test::MddRefStatus::Penetrating)) ++statusMink;
      }
      const bool exactInside = q.exactStatus == mink_test::MddRefStatus::Penetrating;
      // Yes/no answers are judged away from the touching placement (step 10: P and Q within
      // the GJK bisection's 1e-13 of contact, where a tolerance decides either way).
      const bool overlap = q.exactOrigin != mink_test::OriginLocation::Outside;
      const bool decidable = q.step != 10;
      if (decidable) {
        if (static_cast<bool>(rGjk[i]) != overlap) ++gjkWrong;
        if (static_cast<bool>(rInt[i]) != overlap) ++intWrong;
      }
      // MPR: directional value on penetrating queries only.
      if (exactInside && clear && decidable) {
        ++exactPen;
        if (!rMpr[i].overlap) {
          ++mprMissed;
        } else {
          eMpr.push_back(errWithTie(rMpr[i].translation, q));
          eMprPerp.push_back(std::abs(rMpr[i].perpendicular - std::abs(q.exactTranslation)));
          mprFallback += rMpr[i].portalFallbacks > 0;
        }
        if (rMprD[i].overlap) eMprD.push_back(errWithTie(rMprD[i].translation, q));
      } else if (!overlap && decidable && rMpr[i].overlap) {
        ++mprFalse;
      }
      for (int b = 0; b < 2; ++b) {
        const mink_bench::CastAnswer& c = b == 0 ? rBg[i] : rBs[i];
        int& st = b == 0 ? statusBg : statusBs;
        if (c.contact != exactContact) {
          ++st;
          continue;
        }
        if (!exactContact) continue;
        (b == 0 ? eBg : eBs).push_back(errWithTie(c.translation, q));
        if (clear && c.penetrating != exactInside) ++st;
      }
    }
    for (double e : eMink) tg.maxErr = std::max(tg.maxErr, e);
    for (double x : shareM) tg.shareM += x;
    for (double x : shareEE) tg.shareEE += x;
    tg.shareCount += static_cast<long long>(shareM.size());

    const Summary sc = summarize(subset(byName("mink_cold"), sep)), pc = summarize(subset(byName("mink_cold"), pen));
    const Summary nc = summarize(byName("mink_nocache"));
    const Summary it = summarize(byName("mink_intersects"));
    const Summary gj = summarize(byName("ccd_gjk"));
    // MPR on the queries where it made its two calls (it reported overlap).
    std::vector<int> mpr2, mpr1;
    for (int i : all) (rMpr[i].overlap ? mpr2 : mpr1).push_back(i);
    const Summary mp = summarize(subset(byName("ccd_mpr"), mpr2));
    std::vector<int> mprD2;
    for (int i : all)
      if (rMprD[i].overlap) mprD2.push_back(i);
    const Summary mpd = summarize(subset(byName("ccd_mpr_tol1e-4"), mprD2));
    const Summary mp1 = summarize(subset(byName("ccd_mpr"), mpr1));
    const Summary fc = summarize(byName("fcl_signed"));
    const Summary bg = summarize(byName("bullet_gjk_cast")), bs = summarize(byName("bullet_subsimplex_cast"));
    const Summary mc = summarize(byName("mink_cold"));
    const Summary mcPen = pc;
    const Summary cb = summarize(cgalBuild), cq = summarize(cgalQuery);
    csv.row("paper", pd.name, "ccd_mpr", "two_calls", mp);
    csv.row("paper", pd.name, "ccd_mpr", "one_call", mp1);
    csv.row("paper", pd.name, "ccd_mpr_tol1e-4", "two_calls", mpd);
    csv.row("paper", pd.name, "cgal_build", "per_orientation", cb);
    csv.row("paper", pd.name, "cgal_query", "per_query", cq);
    const Summary em = summarize(eMink), emp = summarize(eMpr), empp = summarize(eMprPerp), ebg = summarize(eBg),
                  ebs = summarize(eBs), sm = summarize(shareM), se = summarize(shareEE), vi = summarize(visits),
                  ve = summarize(visitsEE), empd = summarize(eMprD);
    csv.row("paper", pd.name, "mink_cold", "error", Summary{em.n}, em.max, em.median, statusMink,
            "value=status mismatches");
    csv.row("paper", pd.name, "ccd_mpr", "error", Summary{emp.n}, emp.max, emp.median, mprMissed,
            "value=penetrating queries MPR called apart; false overlaps=" + std::to_string(mprFalse) +
                "; portal fallbacks=" + std::to_string(mprFallback) + "; of " + std::to_string(exactPen));
    csv.row("paper", pd.name, "ccd_mpr_perpendicular", "error", Summary{empp.n}, empp.max, empp.median);
    csv.row("paper", pd.name, "ccd_mpr_tol1e-4", "error", Summary{empd.n}, empd.max, empd.median);
    csv.row("paper", pd.name, "bullet_gjk_cast", "error", Summary{ebg.n}, ebg.max, ebg.median, statusBg,
            "value=status mismatches");
    csv.row("paper", pd.name, "bullet_subsimplex_cast", "error", Summary{ebs.n}, ebs.max, ebs.median, statusBs,
            "value=status mismatches");
    csv.row("paper", pd.name, "ccd_gjk", "wrong", Summary{static_cast<std::size_t>(exactCount)}, std::nan(""),
            std::nan(""), gjkWrong);
    csv.row("paper", pd.name, "mink_intersects", "wrong", Summary{static_cast<std::size_t>(exactCount)},
            std::nan(""), std::nan(""), intWrong);
    csv.value("paper", pd.name, "share_faces_M", sm.mean, "mean over contact queries of the exact subsample");
    csv.value("paper", pd.name, "share_faces_EE", se.mean);
    csv.value("paper", pd.name, "faces_visited", vi.mean);
    csv.value("paper", pd.name, "faces_visited_EE", ve.mean);
    csv.value("paper", pd.name, "faces_M", pd.orients[0].facetsM);
    csv.value("paper", pd.name, "fallbacks", fallbacks);

    const double rG = mc.median / gj.median, rM = mcPen.median / mp.median, rB = mc.median / bs.median;
    tg.gjkRatio.push_back(rG);
    tg.mprRatio.push_back(rM);
    tg.mprRatio1.push_back(mcPen.median / mp1.median);
    tg.bulletRatio.push_back(rB);
    tg.intersectsRatio.push_back(it.median / gj.median);
    for (double x : byName("mink_cold")) allMink.push_back(x);
    for (double x : byName("ccd_gjk")) allGjk.push_back(x);
    csv.value("paper", pd.name, "ratio_mink_over_gjk", rG);
    csv.value("paper", pd.name, "ratio_mink_pen_over_mpr2", rM);
    csv.value("paper", pd.name, "ratio_bullet_subsimplex_over_mink", 1.0 / rB);
    csv.value("paper", pd.name, "ratio_intersects_over_gjk", it.median / gj.median);

    auto cell = [](const Summary& s) {
      char b[64];
      std::snprintf(b, sizeof b, "%7.2f [%7.2f]", s.median, s.mean);
      return std::string(b);
    };
    const Summary bsPen = summarize(subset(byName("bullet_subsimplex_cast"), pen));
    std::printf("%-7s %5zu %5zu %5zu | %-17s %-17s %-17s %-17s | %-17s %-17s %-17s %-17s %-17s %-17s %-17s %8.2fx | %6.0fms+%5.0fus\n",
                pd.name.c_str(), sep.size(), pen.size(), miss.size(), cell(sc).c_str(), cell(pc).c_str(),
                cell(nc).c_str(), cell(it).c_str(), cell(gj).c_str(), cell(mp).c_str(), cell(mpd).c_str(),
                cell(fc).c_str(), cell(bg).c_str(), cell(bs).c_str(), cell(bsPen).c_str(), rG, cb.median * 1e-3,
                cq.median);
    std::fflush(stdout);
    pairs.push_back(std::move(pd));
    // Accuracy line for the pair (printed into a second table after the loop).
    std::ostringstream acc;
    char line[512];
    std::snprintf(line, sizeof line,
                  "%-7s %5d | %9.2e %9.2e %3d %3d | %5.1f%% %5.1f%% %6.1f %5.1f %5.0f | %9.2e %9.2e %9.2e %3d/%3d %3d %3d "
                  "| %9.2e %9.2e | %9.2e %9.2e %3d | %9.2e %9.2e %3d | %3d %3d",
                  pairs.back().name.c_str(), exactCount, em.max, em.median, statusMink, fallbacks, 100 * sm.mean,
                  100 * se.mean, vi.mean, ve.mean, pairs.back().orients[0].facetsM, emp.max, emp.median, empp.median,
                  mprMissed, exactPen, mprFalse, mprFallback, empd.max, empd.median, ebg.max, ebg.median, statusBg,
                  ebs.max, ebs.median,
                  statusBs, gjkWrong, intWrong);
    static std::vector<std::string> accLines;
    accLines.push_back(line);
    if (pairs.size() == mink_test::kPaperPairs.size()) {
      std::printf("\n   accuracy on the exact subsample (errors: |translation - exact|, length units; shapes of "
                  "radius 5)\n");
      std::printf("%-7s %5s | %-9s %-9s %3s %3s | %-6s %-6s %-6s %-5s %-5s | %-9s %-9s %-9s %-7s %3s %3s | %-9s "
                  "%-9s | %-9s %-9s %3s | %-9s %-9s %3s | %3s %3s\n",
                  "pair", "exact", "mink max", "mink med", "st", "fb", "M%", "EE%", "faces", "EE", "|M|", "MPR max",
                  "MPR med", "perp med", "missed", "fls", "fbk", "MPR4 max", "MPR4 med", "BtGJK max", "BtGJK med",
                  "st", "BtSub max", "BtSub med", "st", "GJK", "int");
      for (const auto& l : accLines) std::printf("%s\n", l.c_str());
      std::printf("   st: status mismatches (contact or not; separated vs penetrating where |exact| > 1e-9); fb: "
                  "mink fallbacks (all queries);\n   M%%, EE%%: mean share of the faces of M and of its EE faces that "
                  "mink visits (queries where the line meets M; both searches of a penetrating query);\n   faces, "
                  "EE: mean faces visited; |M|: faces of M (first orientation); MPR: penetrating queries only, "
                  "missed = MPR said apart, fls = MPR said overlap on a separated query,\n   fbk = portal plane not "
                  "found; perp med: median |MPR's own perpendicular depth - |exact directional||; MPR4: MPR at "
                  "libccd's default mpr_tolerance 1e-4;\n   Bt: Bullet casts (st: wrong contact/status, e.g. no hit "
                  "reported); GJK / int: wrong yes/no answers of ccdGJKIntersect / mink::intersects;\n   missed, fls, "
                  "GJK, int leave out the touching placement (d = 0), where the shapes are within 1e-13 of contact.\n");
    }
  }
  const double rAll = quantile(allMink, 0.5) / quantile(allGjk, 0.5);
  csv.value("paper", "all", "ratio_mink_over_gjk_pooled", rAll);
  std::printf("   pooled over all pairs: mink cold median %.2f us, ccdGJKIntersect median %.2f us, ratio %.2fx\n",
              quantile(allMink, 0.5), quantile(allGjk, 0.5), rAll);
}

// ---------------------------------------------------------------------------------------
// 2. Scaling, 3. coherence (per size and on a paper pair).

struct CoherenceOut {
  Summary warm, cold, nocache;
  double visitsWarm = 0, visitsCold = 0;
};

CoherenceOut coherencePath(const ConvexPolyhedron<double>& P, const ConvexPolyhedron<double>& Q, int frames,
                           int passes, double radius) {
  struct Frame {
    Pose<double> pose;
    Vec3d s;
  };
  std::vector<Frame> fr(frames);
  const Vec3d axis = Vec3d(0.3, -0.5, 1.0).normalized();
  for (int f = 0; f < frames; ++f) {
    const double a = 0.005 * f;  // 0.29 degrees of rotation and ~0.03 length units per frame
    fr[f].pose.rotation = Eigen::AngleAxisd(a, axis).toRotationMatrix();
    fr[f].pose.translation = Vec3d(radius * std::cos(a), radius * std::sin(a), 0.5);
    fr[f].s = -fr[f].pose.translation + Vec3d(0.3, -0.2, 0.1);
  }
  MinkRunner<double> warm, cold;
  const Pose<double> I;
  std::vector<double> tw(frames, 1e300), tc(frames, 1e300), tn(frames, 1e300);
  CoherenceOut out;
  for (int pass = 0; pass <= passes; ++pass) {
    long long vw = 0, vc = 0;
    for (int f = 0; f < frames; ++f) {
      auto t0 = Clock::now();
      const auto rw = mink::mdd(P, I, Q, fr[f].pose, fr[f].s, warm.cache);
      const double a = microsSince(t0);
      cold.clearHints();
      t0 = Clock::now();
      const auto rc = mink::mdd(P, I, Q, fr[f].pose, fr[f].s, cold.cache);
      const double b = microsSince(t0);
      t0 = Clock::now();
      gSink = gSink + mink::mdd(P, I, Q, fr[f].pose, fr[f].s).translation;
      const double c = microsSince(t0);
      vw += rw.visitedFV + rw.visitedVF + rw.visitedEE;
      vc += rc.visitedFV + rc.visitedVF + rc.visitedEE;
      if (pass > 0) {
        tw[f] = std::min(tw[f], a);
        tc[f] = std::min(tc[f], b);
        tn[f] = std::min(tn[f], c);
      }
    }
    out.visitsWarm = static_cast<double>(vw) / frames;
    out.visitsCold = static_cast<double>(vc) / frames;
  }
  out.warm = summarize(tw);
  out.cold = summarize(tc);
  out.nocache = summarize(tn);
  return out;
}

void scalingSection(const Options& opt, Targets& tg) {
  Csv csv(opt.outdir + "/mdd_scaling.csv", setupLine(opt));
  std::printf("\n== 2. Scaling: ellipsoid pairs (semi-axes 2, 2, 5, every point a hull vertex), %d orientations x 21 "
              "placements x %d directions per size ==\n",
              opt.scalingOrientations, opt.scalingDirections);
  std::printf("   builds: ms per shape (hull + adjacency = fromPoints; DK hierarchy; FCL's Convex from a CGAL hull); "
              "queries: us, median [mean]\n");
  std::printf("%7s | %8s %8s %8s | %-19s %-19s %-19s | %-17s %-17s %-17s %-17s\n", "n", "hull", "DK", "FCL",
              "mink cold", "mink no-cache", "mink warm (path)", "ccd GJK (y/n)", "ccd MPR (pen, 2x)", "FCL signed dist",
              "Bullet subsimplex");
  std::mt19937 rng(8u);
  for (int n : opt.sizes) {
    const auto ptsP = ellipsoidPoints(n, 100u + n), ptsQ = ellipsoidPoints(n, 200u + n);
    auto t0 = Clock::now();
    const auto P = ConvexPolyhedron<double>::fromPoints(ptsP);
    const double hullMs = microsSince(t0) * 1e-3;
    const auto Q = ConvexPolyhedron<double>::fromPoints(ptsQ);
    t0 = Clock::now();
    const bool hasH = mink::hierarchyOf(P) != nullptr;
    const double dkMs = hasH ? microsSince(t0) * 1e-3 : 0.0;
    mink::hierarchyOf(Q);
    t0 = Clock::now();
    const mink_test::GjkShape gP(ptsP);
    const double fclMs = microsSince(t0) * 1e-3;
    const mink_test::GjkShape gQ(ptsQ);
    std::vector<Orientation> orients;
    std::vector<Query> qs = makeQueries(P, Q, orients, opt.scalingOrientations, opt.scalingDirections, 0.15, rng);
    const std::size_t m = qs.size();
    MinkRunner<double> cold;
    mink_bench::CcdPair ccd(P, Q);
    mink_bench::BulletCast<btSubsimplexConvexCast> bsub(P, Q);
    std::vector<mink_bench::MprAnswer> rMpr(m);
    std::vector<MddStatus> st(m);
    const Pose<double> I;
    auto poseOf = [&](const Query& q) {
      Pose<double> p;
      p.rotation = q.R;
      p.translation = q.t;
      return p;
    };
    std::vector<Method> methods;
    methods.push_back({"mink_cold", [&](std::size_t i) {
                         const Pose<double> pq = poseOf(qs[i]);
                         cold.clearHints();
                         const auto t1 = Clock::now();
                         st[i] = mink::mdd(P, I, Q, pq, qs[i].s, cold.cache).status;
                         return microsSince(t1);
                       }, {}});
    methods.push_back({"mink_nocache", [&](std::size_t i) {
                         const Pose<double> pq = poseOf(qs[i]);
                         const auto t1 = Clock::now();
                         gSink = gSink + mink::mdd(P, I, Q, pq, qs[i].s).translation;
                         return microsSince(t1);
                       }, {}});
    methods.push_back({"ccd_gjk", [&](std::size_t i) {
                         const auto t1 = Clock::now();
                         ccd.place(Mat3d::Identity(), Vec3d::Zero(), qs[i].R, qs[i].t);
                         gSink = gSink + ccd.gjkIntersect();
                         return microsSince(t1);
                       }, {}});
    methods.push_back({"ccd_mpr", [&](std::size_t i) {
                         ccd.place(Mat3d::Identity(), Vec3d::Zero(), qs[i].R, qs[i].t);
                         rMpr[i] = ccd.mprDirectional(qs[i].s);
                         return rMpr[i].micros;
                       }, {}});
    methods.push_back({"fcl_signed", [&](std::size_t i) {
                         const auto t1 = Clock::now();
                         gSink = gSink + mink_bench::fclSignedDistance(gP.fclConvex(), Eigen::Isometry3d::Identity(),
                                                                       gQ.fclConvex(), iso(qs[i].R, qs[i].t));
                         return microsSince(t1);
                       }, {}});
    methods.push_back({"bullet_subsimplex_cast", [&](std::size_t i) {
                         const auto t1 = Clock::now();
                         gSink = gSink + bsub.directional(Mat3d::Identity(), Vec3d::Zero(), qs[i].R, qs[i].t, qs[i].s)
                                             .translation;
                         return microsSince(t1);
                       }, {}});
    timeMethods(methods, m, opt.quick ? 1 : std::max(1, opt.passes - 1));
    const CoherenceOut coh = coherencePath(P, Q, opt.quick ? 100 : 300, opt.quick ? 1 : 2, 6.0);
    const std::string cs = std::to_string(n);
    csv.value("scaling_build", cs, "hull_ms", hullMs);
    csv.value("scaling_build", cs, "dk_ms", dkMs, hasH ? "" : "no hierarchy below kHierarchyMinVertices");
    csv.value("scaling_build", cs, "fcl_convex_ms", fclMs, "CGAL Epick hull + fcl::Convexd");
    std::vector<int> mpr2;
    for (std::size_t i = 0; i < m; ++i)
      if (rMpr[i].overlap) mpr2.push_back(static_cast<int>(i));
    std::map<std::string, Summary> S;
    for (const Method& me : methods) {
      S[me.name] = summarize(me.best);
      csv.row("scaling", cs, me.name, "all", S[me.name]);
    }
    S["ccd_mpr2"] = summarize(subset(methods[3].best, mpr2));
    csv.row("scaling", cs, "ccd_mpr", "two_calls", S["ccd_mpr2"]);
    csv.row("scaling", cs, "mink_warm", "path", coh.warm, std::nan(""), std::nan(""), coh.visitsWarm,
            "value=faces visited per frame");
    csv.row("scaling", cs, "mink_cold", "path", coh.cold, std::nan(""), std::nan(""), coh.visitsCold,
            "value=faces visited per frame");
    csv.row("scaling", cs, "mink_nocache", "path", coh.nocache);
    if (n == 1000) tg.scalingCold1k = S["mink_cold"].median;
    if (n == 100000) tg.scalingCold100k = S["mink_cold"].median;
    auto cell = [](const Summary& s) {
      char b[64];
      std::snprintf(b, sizeof b, "%8.2f [%8.2f]", s.median, s.mean);
      return std::string(b);
    };
    std::printf("%7d | %8.1f %8.1f %8.1f | %-19s %-19s %-19s | %-17s %-17s %-17s %-17s\n", n, hullMs, dkMs, fclMs,
                cell(S["mink_cold"]).c_str(), cell(S["mink_nocache"]).c_str(), cell(coh.warm).c_str(),
                cell(S["ccd_gjk"]).c_str(), cell(S["ccd_mpr2"]).c_str(), cell(S["fcl_signed"]).c_str(),
                cell(S["bullet_subsimplex_cast"]).c_str());
    std::fflush(stdout);
  }
  if (tg.scalingCold1k > 0 && tg.scalingCold100k > 0) {
    std::printf("   mink cold: time(100k) / time(1k) = %.2f (target <= 3)\n", tg.scalingCold100k / tg.scalingCold1k);
    csv.value("scaling", "all", "ratio_cold_100k_over_1k", tg.scalingCold100k / tg.scalingCold1k);
  }
}

void coherenceSection(const Options& opt, const PaperShapes& shapes, Targets& tg) {
  Csv csv(opt.outdir + "/mdd_coherence.csv", setupLine(opt));
  std::printf("\n== 3. Coherence: Q moves along a smooth path (0.29 deg rotation, ~0.03 translation per frame), %d "
              "frames; us per query, median [mean] ==\n",
              opt.coherenceFrames);
  std::printf("%-7s | %-19s %-19s %-19s | %8s | %-11s %-11s\n", "pair", "warm (cache)", "cold (no hints)",
              "no cache", "cold/warm", "faces warm", "faces cold");
  std::vector<double> ratios;
  for (const auto& pr : {mink_test::kPaperPairs[3], mink_test::kPaperPairs[0], mink_test::kPaperPairs[7]}) {
    const auto& P = *shapes.poly[idx(pr.first)];
    const auto& Q = *shapes.poly[idx(pr.second)];
    const std::string name = std::string(mink_test::paperShapeName(pr.first)) + "-" +
                             mink_test::paperShapeName(pr.second);
    const CoherenceOut c = coherencePath(P, Q, opt.coherenceFrames, opt.passes, 6.0);
    csv.row("coherence", name, "mink_warm", "path", c.warm, std::nan(""), std::nan(""), c.visitsWarm,
            "value=faces visited per frame");
    csv.row("coherence", name, "mink_cold", "path", c.cold, std::nan(""), std::nan(""), c.visitsCold,
            "value=faces visited per frame");
    csv.row("coherence", name, "mink_nocache", "path", c.nocache);
    const double r = c.cold.median / c.warm.median;
    ratios.push_back(r);
    csv.value("coherence", name, "ratio_cold_over_warm", r);
    std::printf("%-7s | %8.2f [%8.2f] %8.2f [%8.2f] %8.2f [%8.2f] | %7.2fx | %11.1f %11.1f\n", name.c_str(),
                c.warm.median, c.warm.mean, c.cold.median, c.cold.mean, c.nocache.median, c.nocache.mean, r,
                c.visitsWarm, c.visitsCold);
  }
  tg.coherenceRatio = quantile(ratios, 0.5);
}

// ---------------------------------------------------------------------------------------
// 4. Precision: float, double, long double, exact rationals.

template <class T>
mink::Mat3<T> rotationFromQuaternion(const std::array<long, 4>& q) {
  const long w = q[0], x = q[1], y = q[2], z = q[3];
  const T n2 = T(w * w + x * x + y * y + z * z);
  const long m[3][3] = {{w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
                        {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
                        {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}};
  mink::Mat3<T> R;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R(i, j) = T(m[i][j]) / n2;
  return R;
}

template <class T>
mink::Vec3<T> castVec(const Vec3d& v) {
  return mink::Vec3<T>(T(v.x()), T(v.y()), T(v.z()));
}

template <class T>
std::vector<mink::Vec3<T>> castPts(const std::vector<Vec3d>& pts) {
  std::vector<mink::Vec3<T>> out;
  for (const auto& p : pts) out.push_back(castVec<T>(p));
  return out;
}

struct PrecisionOut {
  std::vector<double> times, errors;
  int statusWrong = 0;
};

/// mink in scalar T on the exact-subsample queries `sel` of one pair.
template <class T>
PrecisionOut runPrecision(const ConvexPolyhedron<T>& P, const ConvexPolyhedron<T>& Q, const PairData& pd,
                          const std::vector<int>& sel, int passes) {
  MinkRunner<T> runner;
  PrecisionOut out;
  std::vector<double> best(sel.size(), 1e300);
  std::vector<mink::MddResult<T>> res(sel.size());
  std::vector<Pose<T>> poses(sel.size());
  std::vector<mink::Vec3<T>> dirs(sel.size());
  for (std::size_t k = 0; k < sel.size(); ++k) {
    const Query& q = pd.queries[sel[k]];
    const Orientation& ori = pd.orients[q.orient];
    if constexpr (mink::ScalarTraits<T>::isExact) {
      poses[k].rotation = ori.rot.exact;
      poses[k].translation = mink_test::toExact(q.t);
      dirs[k] = mink_test::toExact(q.s);
    } else {
      poses[k].rotation = rotationFromQuaternion<T>(ori.rot.quaternion);
      poses[k].translation = castVec<T>(q.t);
      dirs[k] = castVec<T>(q.s);
    }
  }
  const Pose<T> I;
  for (int pass = 0; pass <= passes; ++pass) {
    for (std::size_t k = 0; k < sel.size(); ++k) {
      runner.clearHints();
      const auto t0 = Clock::now();
      res[k] = mink::mdd(P, I, Q, poses[k], dirs[k], runner.cache);
      const double us = microsSince(t0);
      if (pass > 0 || passes == 0) best[k] = std::min(best[k], us);
    }
  }
  for (std::size_t k = 0; k < sel.size(); ++k) {
    const Query& q = pd.queries[sel[k]];
    const auto& r = res[k];
    out.times.push_back(best[k]);
    const bool exactContact = q.exactStatus != mink_test::MddRefStatus::NoContact;
    const bool got = r.status != MddStatus::NoContact && r.status != MddStatus::IterationLimit;
    if (exactContact != got) {
      ++out.statusWrong;
      continue;
    }
    if (!exactContact) continue;
    if constexpr (mink::ScalarTraits<T>::isExact) {
      // |s| = 1 up to the rounding of the unit double vector: the length is parameter·|s|.
      double e = std::abs(CGAL::to_double(Rational(r.parameter - q.exactT)));
      if (q.exactTie) e = std::min(e, std::abs(CGAL::to_double(Rational(r.parameter + q.exactT))));
      out.errors.push_back(e * q.s.norm());
    } else {
      out.errors.push_back(errWithTie(static_cast<double>(r.translation), q));
    }
  }
  return out;
}

/// mddExact<Gmpq> on the double shapes and poses of the same queries: exact for the
/// numbers given (the rotation rounded to double), certified from the double search's
/// face or separating direction, mdd<Gmpq> otherwise. `certified` counts the former.
PrecisionOut runCertified(const ConvexPolyhedron<double>& P, const ConvexPolyhedron<double>& Q, const PairData& pd,
                          const std::vector<int>& sel, int passes, int& certified) {
  PrecisionOut out;
  const Pose<double> I;
  for (int k : sel) {
    const Query& q = pd.queries[k];
    Pose<double> pose;
    pose.rotation = rotationFromQuaternion<double>(pd.orients[q.orient].rot.quaternion);
    pose.translation = q.t;
    double best = 1e300;
    mink::ExactMdd<Rational> r;
    for (int pass = 0; pass <= passes; ++pass) {
      const auto t0 = Clock::now();
      r = mink::mddExact<Rational>(P, I, Q, pose, q.s);
      const double us = microsSince(t0);
      if (pass > 0 || passes == 0) best = std::min(best, us);
    }
    out.times.push_back(best);
    certified += r.certified;
    const bool exactContact = q.exactStatus != mink_test::MddRefStatus::NoContact;
    if (exactContact != (r.status != MddStatus::NoContact && r.status != MddStatus::IterationLimit)) {
      ++out.statusWrong;
      continue;
    }
    if (!exactContact) continue;
    double e = std::abs(CGAL::to_double(Rational(r.parameter - q.exactT)));
    if (q.exactTie) e = std::min(e, std::abs(CGAL::to_double(Rational(r.parameter + q.exactT))));
    out.errors.push_back(e * q.s.norm());
  }
  return out;
}

void precisionSection(const Options& opt, const PaperShapes& shapes, const std::vector<PairData>& pairs,
                      Targets& tg) {
  Csv csv(opt.outdir + "/mdd_precision.csv", setupLine(opt));
  std::printf("\n== 4. Precision: mink per scalar type (default tolerances: touchTolerance automatic, "
              "defaults::kMddTouchToleranceFactor x eps x scene size; 0 for rationals) ==\n");
  std::printf("   float/double/long double: the exact subsample of section 1 (input rounded to the type); exact: "
              "CGAL::Gmpq on %d direction(s) per placement of the first orientation\n",
              opt.gmpqDirections);
  std::printf("%-7s %-12s %6s | %-19s | %-9s %-9s %4s\n", "pair", "scalar", "count", "us median [mean]", "max err",
              "med err", "st");
  // Shapes per scalar type, built once.
  std::vector<std::unique_ptr<ConvexPolyhedron<float>>> pf;
  std::vector<std::unique_ptr<ConvexPolyhedron<long double>>> pl;
  std::vector<std::unique_ptr<ConvexPolyhedron<Rational>>> pr;
  std::vector<double> exactBuildMs;
  for (std::size_t i = 0; i < shapes.pts.size(); ++i) {
    pf.push_back(std::make_unique<ConvexPolyhedron<float>>(ConvexPolyhedron<float>::fromPoints(castPts<float>(shapes.pts[i]))));
    pl.push_back(std::make_unique<ConvexPolyhedron<long double>>(
        ConvexPolyhedron<long double>::fromPoints(castPts<long double>(shapes.pts[i]))));
    const auto t0 = Clock::now();
    pr.push_back(std::make_unique<ConvexPolyhedron<Rational>>(
        ConvexPolyhedron<Rational>::fromPoints(mink_test::toExact(shapes.pts[i]))));
    exactBuildMs.push_back(microsSince(t0) * 1e-3);
  }
  std::map<std::string, std::vector<double>> allT, allE;
  std::map<std::string, int> allSt;
  for (const PairData& pd : pairs) {
    std::vector<int> sel, selExact;
    for (std::size_t i = 0; i < pd.queries.size(); ++i) {
      const Query& q = pd.queries[i];
      if (!q.hasExact) continue;
      sel.push_back(static_cast<int>(i));
      if (q.orient == 0 && (static_cast<int>(i) % opt.directions) < opt.gmpqDirections) selExact.push_back(static_cast<int>(i));
    }
    auto report = [&](const std::string& type, const PrecisionOut& o) {
      const Summary t = summarize(o.times), e = summarize(o.errors);
      csv.row("precision", pd.name, type, "all", t, e.max, e.median, o.statusWrong, "value=status mismatches");
      std::printf("%-7s %-12s %6zu | %8.2f [%8.2f] | %9.2e %9.2e %4d\n", pd.name.c_str(), type.c_str(), t.n, t.median,
                  t.mean, e.max, e.median, o.statusWrong);
      for (double x : o.times) allT[type].push_back(x);
      for (double x : o.errors) allE[type].push_back(x);
      allSt[type] += o.statusWrong;
    };
    report("float", runPrecision<float>(*pf[pd.iP], *pf[pd.iQ], pd, sel, opt.passes));
    report("double", runPrecision<double>(*shapes.poly[pd.iP], *shapes.poly[pd.iQ], pd, sel, opt.passes));
    report("long_double", runPrecision<long double>(*pl[pd.iP], *pl[pd.iQ], pd, sel, opt.passes));
    int certified = 0;
    report("certified", runCertified(*shapes.poly[pd.iP], *shapes.poly[pd.iQ], pd, sel, opt.passes, certified));
    allSt["certified_count"] += certified;
    allSt["certified_queries"] += static_cast<int>(sel.size());
    report("exact_gmpq", runPrecision<Rational>(*pr[pd.iP], *pr[pd.iQ], pd, selExact, 0));
    // Double on exactly the Gmpq queries, for the cost ratio on the same queries.
    const PrecisionOut dSame = runPrecision<double>(*shapes.poly[pd.iP], *shapes.poly[pd.iQ], pd, selExact, opt.passes);
    for (double x : dSame.times) allT["double_on_exact_queries"].push_back(x);
    std::fflush(stdout);
  }
  std::printf("   all pairs:\n");
  for (const std::string type : {"float", "double", "long_double", "certified", "exact_gmpq"}) {
    const Summary t = summarize(allT[type]), e = summarize(allE[type]);
    csv.row("precision", "all", type, "all", t, e.max, e.median, allSt[type], "value=status mismatches");
    std::printf("%-7s %-12s %6zu | %8.2f [%8.2f] | %9.2e %9.2e %4d\n", "all", type.c_str(), t.n, t.median, t.mean, e.max,
                e.median, allSt[type]);
  }
  // The certified point against double on the same queries (the whole exact subsample).
  const double certRatio = quantile(allT["certified"], 0.5) / quantile(allT["double"], 0.5);
  const int certCount = allSt["certified_count"], certQueries = allSt["certified_queries"];
  csv.value("precision", "all", "ratio_certified_over_double", certRatio, "medians on the same queries");
  csv.value("precision", "all", "certified_share", double(certCount) / std::max(1, certQueries),
            "mddExact answers certified without the mdd<Gmpq> fallback");
  std::printf("   mddExact<Gmpq> (certified) costs %.1fx double (medians on the same %d queries); %d of them "
              "certified, %d through the mdd<Gmpq> fallback\n",
              certRatio, certQueries, certCount, certQueries - certCount);
  const double ratio = quantile(allT["exact_gmpq"], 0.5) / quantile(allT["double_on_exact_queries"], 0.5);
  tg.exactOverDouble = ratio;
  csv.value("precision", "all", "ratio_exact_over_double", ratio, "medians on the same queries");
  std::printf("   exact rationals cost %.0fx double (medians on the same %zu queries); exact hull builds: ", ratio,
              allT["exact_gmpq"].size());
  for (std::size_t i = 0; i < exactBuildMs.size(); ++i) {
    std::printf("P%zu %.0f ms%s", i + 1, exactBuildMs[i], i + 1 < exactBuildMs.size() ? ", " : "\n");
    csv.value("precision_build", "P" + std::to_string(i + 1), "exact_hull_ms", exactBuildMs[i]);
  }
}

// ---------------------------------------------------------------------------------------
// 5. prepare(): what the first query on a large shape costs with and without it.

/// Per size and repetition, two fresh shapes from the same points (fromPoints, untimed):
/// on the first, mdd() twice (the first call builds the hierarchy, the second is the
/// steady-state query); on the second, prepare() twice (the build, then the call that
/// finds everything built), then mdd(). Q is a small prepared ellipsoid; one fixed
/// separated query, no cache. Wall time (steady_clock, what a caller waits) and the
/// thread's CPU time (what the work costs on a shared machine); medians over the
/// repetitions.
void prepareSection(const Options& opt) {
  Csv csv(opt.outdir + "/mdd_prepare.csv", setupLine(opt));
  const std::vector<int> sizes = opt.quick ? std::vector<int>{10000} : std::vector<int>{10000, 100000};
  const int reps = opt.quick ? 2 : 5;
  std::printf("\n== 5. prepare(): the first mdd() on a fresh P (2:2:5 ellipsoid) against a 1000-vertex Q, "
              "unprepared vs after prepare(P); ms, median wall (median thread CPU) [min .. max wall] over %d fresh "
              "shapes ==\n",
              reps);
  std::printf("%7s | %-34s %-34s | %-34s %-34s %-34s\n", "n", "first query, unprepared", "second query",
              "prepare()", "prepare() again", "first query, prepared");
  const auto Q = ConvexPolyhedron<double>::fromPoints(ellipsoidPoints(1000, 501u));
  mink::prepare(Q);
  Pose<double> poseQ;
  poseQ.rotation = Eigen::AngleAxisd(0.3, Vec3d(0.2, 0.5, 1.0).normalized()).toRotationMatrix();
  poseQ.translation = Vec3d(7.0, 0.5, 0.2);
  const Vec3d s(-1.0, 0.1, 0.05);
  const Pose<double> I;
  struct Times {
    std::vector<double> wall, cpu;
    void time(const std::function<void()>& f) {
      const double w0 = mink_bench::wallMs(), c0 = mink_bench::threadCpuMs();
      f();
      cpu.push_back(mink_bench::threadCpuMs() - c0);
      wall.push_back(mink_bench::wallMs() - w0);
    }
  };
  for (int n : sizes) {
    const std::vector<Vec3d> pts = ellipsoidPoints(n, 500u + n);
    Times firstCold, second, prep, prepAgain, firstPrepared;
    auto query = [&](const ConvexPolyhedron<double>& P) { gSink = gSink + mink::mdd(P, I, Q, poseQ, s).translation; };
    for (int r = 0; r < reps; ++r) {
      {
        const auto P = ConvexPolyhedron<double>::fromPoints(pts);
        firstCold.time([&] { query(P); });
        second.time([&] { query(P); });
      }
      const auto P = ConvexPolyhedron<double>::fromPoints(pts);
      prep.time([&] { gSink = gSink + (mink::prepare(P) != nullptr); });
      prepAgain.time([&] { gSink = gSink + (mink::prepare(P) != nullptr); });
      firstPrepared.time([&] { query(P); });
    }
    auto ms = [](double x) {  // 4 significant digits, no exponent for seconds-long builds
      char b[32];
      std::snprintf(b, sizeof b, x >= 1000 ? "%.0f" : "%.4g", x);
      return std::string(b);
    };
    auto cell = [&](const Times& t) {
      return ms(quantile(t.wall, 0.5)) + " (" + ms(quantile(t.cpu, 0.5)) + ") [" +
             ms(*std::min_element(t.wall.begin(), t.wall.end())) + " .. " +
             ms(*std::max_element(t.wall.begin(), t.wall.end())) + "]";
    };
    std::printf("%7d | %-34s %-34s | %-34s %-34s %-34s\n", n, cell(firstCold).c_str(), cell(second).c_str(),
                cell(prep).c_str(), cell(prepAgain).c_str(), cell(firstPrepared).c_str());
    std::fflush(stdout);
    const std::string cs = std::to_string(n);
    // The CSV's time columns are in us.
    auto us = [](std::vector<double> v) {
      for (double& x : v) x *= 1e3;
      return summarize(v);
    };
    for (const auto& [name, t] : {std::pair<const char*, const Times*>{"mdd_first_unprepared", &firstCold},
                                  {"mdd_second", &second},
                                  {"prepare", &prep},
                                  {"prepare_again", &prepAgain},
                                  {"mdd_first_prepared", &firstPrepared}}) {
      csv.row("prepare", cs, name, "wall", us(t->wall));
      csv.row("prepare", cs, name, "thread_cpu", us(t->cpu));
    }
  }
}

}  // namespace

/// The usage, as in the comment at the top of this file.
constexpr const char* kUsage =
    "Usage: mink_mdd_bench [outdir] [--quick] [--orientations O] [--directions D]\n"
    "                      [--exact-orientations E] [--passes K] [--sections paper,scaling,...]\n"
    "  outdir default benchmarks/results; writes mdd_paper.csv, mdd_scaling.csv,\n"
    "  mdd_coherence.csv, mdd_precision.csv, mdd_prepare.csv and mdd_targets.csv (the printed tables go to\n"
    "  stdout). Defaults: 40 orientations x 21 placements x 10 directions per pair, the exact\n"
    "  reference on 4 orientations, 3 timed passes (about 3 minutes on 2 shared cores).\n";

int main(int argc, char** argv) {
  Options opt;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument("missing value after " + a);
      return argv[++i];
    };
    if (a == "--quick") {
      opt.quick = true;
    } else if (a == "--orientations") {
      opt.orientations = std::stoi(next());
    } else if (a == "--directions") {
      opt.directions = std::stoi(next());
    } else if (a == "--exact-orientations") {
      opt.exactOrientations = std::stoi(next());
    } else if (a == "--passes") {
      opt.passes = std::stoi(next());
    } else if (a == "--sections") {
      opt.sections = next();
    } else {
      opt.outdir = mink_bench::pathArgument(argv[i], kUsage);
    }
  }
  if (opt.quick) {
    opt.orientations = std::min(opt.orientations, 2);
    opt.directions = std::min(opt.directions, 3);
    opt.exactOrientations = std::min(opt.exactOrientations, 1);
    opt.passes = 1;
    opt.gmpqDirections = 1;
    opt.scalingOrientations = 1;
    opt.scalingDirections = 2;
    opt.coherenceFrames = 200;
    opt.sizes = {100, 1000, 10000};
  }
  opt.exactOrientations = std::min(opt.exactOrientations, opt.orientations);
  const auto start = Clock::now();
  std::printf("mink MDD benchmark (issue 4)\n");
  std::printf("  machine: %s; load average at start: %s\n  compiler: %s\n  setup: %s\n", machineLine().c_str(),
              loadAverage().c_str(), __VERSION__, setupLine(opt).c_str());
  std::printf("  timing: steady_clock per query, minimum over %d passes after a warm-up pass, methods interleaved\n",
              opt.passes);
  PaperShapes shapes;
  std::printf("  paper shapes (vertices/faces):");
  for (std::size_t i = 0; i < shapes.poly.size(); ++i)
    std::printf(" P%zu %d/%d", i + 1, shapes.poly[i]->numVertices(), shapes.poly[i]->numFaces());
  std::printf("\n");
  Targets tg;
  std::vector<PairData> pairs;
  if (opt.has("paper") || opt.has("precision")) paperSection(opt, shapes, pairs, tg);
  if (opt.has("scaling")) scalingSection(opt, tg);
  if (opt.has("coherence")) coherenceSection(opt, shapes, tg);
  if (opt.has("precision")) precisionSection(opt, shapes, pairs, tg);
  if (opt.has("prepare")) prepareSection(opt);

  // Targets, measured in this run.
  std::printf("\n== Targets (ratios of medians measured in this run) ==\n");
  Csv csv(opt.outdir + "/mdd_targets.csv", setupLine(opt));
  auto range = [](const std::vector<double>& v) {
    char b[96];
    if (v.empty()) return std::string("n/a");
    std::snprintf(b, sizeof b, "median %.2f, range %.2f .. %.2f", quantile(v, 0.5),
                  *std::min_element(v.begin(), v.end()), *std::max_element(v.begin(), v.end()));
    return std::string(b);
  };
  if (!tg.gjkRatio.empty()) {
    std::printf("  mink cold / ccdGJKIntersect per pair: %s (target <= 4)\n", range(tg.gjkRatio).c_str());
    std::printf("  mink cold (penetrating) / ccd MPR directional (2 calls) per pair: %s (target < 1); / one MPR call "
                "(its separated-query cost): %s\n",
                range(tg.mprRatio).c_str(), range(tg.mprRatio1).c_str());
    std::vector<double> inv;
    for (double r : tg.bulletRatio) inv.push_back(1.0 / r);
    std::printf("  Bullet subsimplex cast directional / mink cold per pair: %s (target >= 5)\n", range(inv).c_str());
    std::printf("  mink::intersects / ccdGJKIntersect per pair: %s (target <= 1.5)\n", range(tg.intersectsRatio).c_str());
    std::printf("  mink max error on the exact subsample: %.3g (target <= 1e-10)\n", tg.maxErr);
    std::printf("  faces of M visited: %.2f%% (target <= 5%%), EE faces: %.2f%% (target <= 1%%)\n",
                100 * tg.shareM / std::max(1LL, tg.shareCount), 100 * tg.shareEE / std::max(1LL, tg.shareCount));
    csv.value("targets", "all", "gjk_ratio_median", quantile(tg.gjkRatio, 0.5));
    csv.value("targets", "all", "mpr_ratio_median", quantile(tg.mprRatio, 0.5));
    csv.value("targets", "all", "bullet_over_mink_median", quantile(inv, 0.5));
    csv.value("targets", "all", "intersects_gjk_ratio_median", quantile(tg.intersectsRatio, 0.5));
    csv.value("targets", "all", "max_error", tg.maxErr);
    csv.value("targets", "all", "share_faces_M", tg.shareM / std::max(1LL, tg.shareCount));
    csv.value("targets", "all", "share_faces_EE", tg.shareEE / std::max(1LL, tg.shareCount));
  }
  if (tg.scalingCold1k > 0 && tg.scalingCold100k > 0) {
    std::printf("  mink cold time(100k)/time(1k): %.2f (target <= 3)\n", tg.scalingCold100k / tg.scalingCold1k);
    csv.value("targets", "all", "scaling_100k_over_1k", tg.scalingCold100k / tg.scalingCold1k);
  }
  if (tg.coherenceRatio > 0) {
    std::printf("  coherence cold/warm (median over the paths): %.2f (target >= 5)\n", tg.coherenceRatio);
    csv.value("targets", "all", "coherence_cold_over_warm", tg.coherenceRatio);
  }
  if (tg.exactOverDouble > 0) {
    std::printf("  exact rationals / double: %.0fx\n", tg.exactOverDouble);
    csv.value("targets", "all", "exact_over_double", tg.exactOverDouble);
  }
  std::printf("\n  libccd calls stopped by the support-call cap (peers.hpp, kCcdSupportCap): %lld\n",
              mink_bench::ccdSupportCapHits());
  std::printf("  load average at end: %s; wall time of the program %.0f s\n", loadAverage().c_str(),
              microsSince(start) * 1e-6);
  return gSink == 42 ? 1 : 0;
}
