// tests/support/mdd_reference.hpp — exact brute-force reference for the minimum
// directional distance (MDD) of two convex polyhedra. Test/benchmark support only.
//
// Source: Choi, Li, Rong, Wang, Cameron, "Computing the Minimum Directional Distance
// between Two Convex Polyhedra", eq. (1) and Sec. II-C (MDD = directional distance from the
// origin to M = P ⊕ −Q), with the conventions of DESIGN.md "Definitions". Steps:
//   1. M is the hull of all differences p − q of the vertices of P and Q (world frame);
//      CGAL::convex_hull_3 over Epeck (exact predicates, lazily exact constructions).
//   2. Every hull facet becomes an exact rational half-space n·x <= c (n outward); coplanar
//      triangles are merged by scaling each plane canonically and deduplicating.
//   3. A query (direction s, extra translation u of Q) clips the line {u + t s} against all
//      planes exactly: [t_lo, t_hi] = { t : u + t s ∈ M } (moving Q by u shifts M by −u).
//   4. The origin is classified exactly against M − u (inside / on the boundary / outside),
//      and status and translation follow DESIGN.md. The status comes from that location,
//      not from the signs of t_lo, t_hi alone: a line running inside a facet plane through
//      the origin has t_lo < 0 < t_hi although P and Q only touch (Touching, t = 0).
// Interval arithmetic (CGAL::Interval_nt) only pre-selects which planes need an exact
// evaluation; every reported value is exact. setFiltered(false) evaluates everything in
// Gmpq (used to cross-check the filter).
//
// Cost: building is O(|P||Q| log) — about 1 s for 500 x 500 vertices in Release — so build
// one reference per relative orientation and query it for many directions and offsets.
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <boost/multiprecision/gmp.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace mink_test {

using Rational = CGAL::Gmpq;
using Vec3r = Eigen::Matrix<Rational, 3, 1>;

/// Mirrors mink::MddStatus (same names, same meaning), kept separate so that this header
/// does not depend on the code it checks.
enum class MddRefStatus { Separated, Touching, Penetrating, NoContact };

/// Position of the origin relative to M (after Q's extra translation u, i.e. of u in M).
/// Inside: P and Q overlap with interior contact; Boundary: they touch; Outside: disjoint.
enum class OriginLocation { Inside, Boundary, Outside };

inline const char* toString(MddRefStatus s) {
  switch (s) {
    case MddRefStatus::Separated: return "Separated";
    case MddRefStatus::Touching: return "Touching";
    case MddRefStatus::Penetrating: return "Penetrating";
    case MddRefStatus::NoContact: return "NoContact";
  }
  return "?";
}

inline const char* toString(OriginLocation o) {
  switch (o) {
    case OriginLocation::Inside: return "Inside";
    case OriginLocation::Boundary: return "Boundary";
    case OriginLocation::Outside: return "Outside";
  }
  return "?";
}

/// A facet of M as the half-space { x : normal·x <= offset }. `normal` points outward and
/// is scaled so that its first non-zero component is +1 or −1 (so equal planes compare
/// equal); it is not unit length.
struct MddRefPlane {
  Vec3r normal;
  Rational offset;
};

/// A point u + t s of the line on the boundary of M.
struct MddRefHit {
  Rational t;                               // exact line parameter (multiples of s, not a length)
  double length = 0.0;                      // t·|s|, signed, units of length (within 2 ulp)
  std::vector<Vec3r> normals;               // outward normals (canonical scale, see MddRefPlane) of
                                            // EVERY facet of M whose plane contains the point:
                                            // one on a face, two on an edge, >= 3 at a vertex
  std::vector<Eigen::Vector3d> unitNormals; // the same, normalised in double
};

/// Exact answer for one direction. Conventions follow mink::MddResult: moving Q by
/// translation · s/|s| (equivalently by t·s) brings P and Q into touching contact, |t| minimal.
struct MddRefResult {
  MddRefStatus status = MddRefStatus::NoContact;
  OriginLocation origin = OriginLocation::Outside;
  bool lineMeetsM = false;      // [t_lo, t_hi] non-empty
  bool lineInFacetPlane = false;// the line lies in a facet plane of M (then it never enters the
                                // interior; if it meets M it runs along ∂M)
  Rational tLo, tHi;            // valid iff lineMeetsM; tLo == tHi when the line only grazes M
  MddRefHit lo, hi;             // the hits at tLo and tHi (valid iff lineMeetsM)

  Rational t;                   // exact parameter of the reported translation (0 for Touching)
  double translation = 0.0;     // t·|s|: signed, along s/|s|, applied to Q, units of length
  double distance = std::numeric_limits<double>::infinity();
                                // MDD: +|translation| Separated, −|translation| Penetrating,
                                // 0 Touching, +infinity NoContact (translation is then 0)
  bool tie = false;             // Penetrating with −tLo == tHi: t = tHi is reported; tLo is
                                // equally minimal and callers must accept either
  MddRefHit contact;            // the boundary point u + t s with its facet normals
                                // (empty for NoContact)
};

namespace mdd_reference_detail {

using Kernel = CGAL::Epeck;
using FT = Kernel::FT;
using ET = FT::ET;  // Gmpq, mpq_class or boost's gmp_rational, depending on CGAL's build flags
using Interval = CGAL::Interval_nt<true>;  // sets the rounding mode itself

inline mpq_srcptr mpqOf(const CGAL::Gmpq& x) { return x.mpq(); }
#ifdef CGAL_USE_GMPXX
inline mpq_srcptr mpqOf(const mpq_class& x) { return x.get_mpq_t(); }
#endif
template <class Backend, boost::multiprecision::expression_template_option E>
mpq_srcptr mpqOf(const boost::multiprecision::number<Backend, E>& x) {
  return x.backend().data();
}

inline FT toFT(const Rational& x) { return FT(ET(x.mpq())); }
inline Rational fromET(const ET& x) { return Rational(mpqOf(x)); }

inline Interval toInterval(const Rational& x) { return Interval(CGAL::to_interval(x)); }

inline int sign(const Rational& x) { return x > 0 ? 1 : (x < 0 ? -1 : 0); }

inline Rational dot(const Vec3r& a, const Vec3r& b) {
  return a.x() * b.x() + a.y() * b.y() + a.z() * b.z();
}

inline Vec3r cross(const Vec3r& a, const Vec3r& b) {
  return Vec3r(a.y() * b.z() - a.z() * b.y(), a.z() * b.x() - a.x() * b.z(),
               a.x() * b.y() - a.y() * b.x());
}

inline bool lessPlane(const MddRefPlane& a, const MddRefPlane& b) {
  for (int i = 0; i < 3; ++i) {
    if (a.normal[i] < b.normal[i]) return true;
    if (b.normal[i] < a.normal[i]) return false;
  }
  return a.offset < b.offset;
}

inline bool equalPlane(const MddRefPlane& a, const MddRefPlane& b) {
  return a.normal == b.normal && a.offset == b.offset;
}

/// t·|s| in double: sqrt of the exactly formed t²|s|², so only two roundings happen.
inline double signedLength(const Rational& t, const Rational& s2) {
  const int sg = sign(t);
  if (sg == 0) return 0.0;
  // t^2 s2 is scaled by powers of 4 into the double range first: for lengths of 1e-223
  // it is 1e-446, zero in double (and 1e-223 is a length double holds).
  Rational x = t * t * s2;
  int half = 0;  // x = (t^2 s2) 4^half
  const Rational up(std::ldexp(1.0, 400)), down(std::ldexp(1.0, -400));
  while (CGAL::to_double(x) < 1e-200) x *= up, half += 200;
  while (CGAL::to_double(x) > 1e200) x *= down, half -= 200;
  const double v = std::ldexp(std::sqrt(CGAL::to_double(x)), -half);
  return sg > 0 ? v : -v;
}

inline Eigen::Vector3d unitDouble(const Vec3r& n) {
  Eigen::Vector3d v(CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z()));
  return v / v.norm();
}

}  // namespace mdd_reference_detail

/// Exact M = P ⊕ −Q for fixed world placements of P and Q, queried for any direction s and
/// any extra translation u of Q.
class MinkowskiDifferenceReference {
 public:
  /// P, Q: vertex (or any point) lists in world coordinates; interior points are allowed.
  /// Throws std::invalid_argument when P or Q is empty or when M is flat (P and Q both
  /// coplanar in parallel planes, or lower-dimensional).
  MinkowskiDifferenceReference(const std::vector<Vec3r>& P, const std::vector<Vec3r>& Q) {
    build(P, Q);
  }

  /// Double input, converted exactly to rationals.
  MinkowskiDifferenceReference(const std::vector<Eigen::Vector3d>& P,
                               const std::vector<Eigen::Vector3d>& Q) {
    build(convert(P), convert(Q));
  }

  /// Exact MDD along s (s != 0, any length) with Q additionally translated by qOffset
  /// (moving P by w is the same as moving Q by −w).
  MddRefResult query(const Vec3r& s, const Vec3r& qOffset) const;
  MddRefResult query(const Vec3r& s) const { return query(s, zero()); }
  MddRefResult query(const Eigen::Vector3d& s) const { return query(convert(s), zero()); }

  /// Where the origin lies relative to M − qOffset: P and Q (Q moved by qOffset) overlap
  /// iff the result is not Outside, and touch without interior overlap iff it is Boundary.
  OriginLocation classifyOrigin(const Vec3r& qOffset) const;
  OriginLocation classifyOrigin() const { return classifyOrigin(zero()); }

  /// Outward normals (canonical scale) of every facet whose plane contains the point x.
  std::vector<Vec3r> facetNormalsThrough(const Vec3r& x) const;

  const std::vector<MddRefPlane>& facets() const { return planes_; }  // one per facet of M
  const std::vector<Vec3r>& vertices() const { return vertices_; }    // vertices of M
  std::size_t triangleCount() const { return triangles_; }            // CGAL hull triangles

  /// false: evaluate every plane in Gmpq, no interval pre-selection (slow, for cross-checks).
  void setFiltered(bool on) { filtered_ = on; }

  static Vec3r convert(const Eigen::Vector3d& v) {
    return Vec3r(Rational(v.x()), Rational(v.y()), Rational(v.z()));
  }
  static std::vector<Vec3r> convert(const std::vector<Eigen::Vector3d>& pts) {
    std::vector<Vec3r> out;
    out.reserve(pts.size());
    for (const auto& p : pts) out.push_back(convert(p));
    return out;
  }

 private:
  using Interval = mdd_reference_detail::Interval;
  struct IntervalPlane {
    Interval n[3];
    Interval c;
  };

  static Vec3r zero() { return Vec3r(Rational(0), Rational(0), Rational(0)); }

  void build(const std::vector<Vec3r>& P, const std::vector<Vec3r>& Q);

  // Sign of n_k·x − c_k: −1 strictly inside the half-space, 0 on the plane, +1 outside.
  int sideExact(std::size_t k, const Vec3r& x) const {
    return mdd_reference_detail::sign(
        Rational(mdd_reference_detail::dot(planes_[k].normal, x) - planes_[k].offset));
  }
  int side(std::size_t k, const Vec3r& x, const Interval (&xi)[3]) const {
    if (filtered_) {
      const IntervalPlane& p = iplanes_[k];
      const Interval v = p.n[0] * xi[0] + p.n[1] * xi[1] + p.n[2] * xi[2] - p.c;
      if (v.sup() < 0) return -1;
      if (v.inf() > 0) return 1;
    }
    return sideExact(k, x);
  }

  MddRefHit makeHit(const Rational& t, const Vec3r& s, const Vec3r& u,
                    const Rational& s2) const {
    MddRefHit h;
    h.t = t;
    h.length = mdd_reference_detail::signedLength(t, s2);
    h.normals = facetNormalsThrough(Vec3r(u + s * t));
    for (const auto& n : h.normals) h.unitNormals.push_back(mdd_reference_detail::unitDouble(n));
    return h;
  }

  std::vector<MddRefPlane> planes_;
  std::vector<IntervalPlane> iplanes_;
  std::vector<Vec3r> vertices_;
  std::size_t triangles_ = 0;
  bool filtered_ = true;
};

inline void MinkowskiDifferenceReference::build(const std::vector<Vec3r>& P,
                                                const std::vector<Vec3r>& Q) {
  namespace d = mdd_reference_detail;
  using Point = d::Kernel::Point_3;
  if (P.empty() || Q.empty())
    throw std::invalid_argument("MinkowskiDifferenceReference: P and Q must be non-empty");

  auto toPoint = [](const Vec3r& v) { return Point(d::toFT(v.x()), d::toFT(v.y()), d::toFT(v.z())); };
  std::vector<Point> pp, qq;
  pp.reserve(P.size());
  qq.reserve(Q.size());
  for (const auto& p : P) pp.push_back(toPoint(p));
  for (const auto& q : Q) qq.push_back(toPoint(q));

  // Lazy differences: the exact value is only computed when a predicate needs it.
  std::vector<Point> diff;
  diff.reserve(P.size() * Q.size());
  for (const auto& p : pp)
    for (const auto& q : qq) diff.push_back(CGAL::ORIGIN + (p - q));

  // Four affinely independent differences, both to reject flat M (convex_hull_3 would
  // return a degenerate mesh) and to get an interior point for the orientation check.
  std::size_t idx[4] = {0, 0, 0, 0};
  int found = 1;
  for (std::size_t i = 1; i < diff.size() && found < 4; ++i) {
    const Point& x = diff[i];
    bool independent = false;
    if (found == 1) independent = (x != diff[idx[0]]);
    else if (found == 2) independent = !CGAL::collinear(diff[idx[0]], diff[idx[1]], x);
    else independent = !CGAL::coplanar(diff[idx[0]], diff[idx[1]], diff[idx[2]], x);
    if (independent) idx[found++] = i;
  }
  if (found < 4)
    throw std::invalid_argument(
        "MinkowskiDifferenceReference: P ⊕ −Q is flat (dimension " + std::to_string(found - 1) +
        "); the reference needs a 3-dimensional Minkowski difference");

  CGAL::Surface_mesh<Point> mesh;
  CGAL::convex_hull_3(diff.begin(), diff.end(), mesh);
  diff.clear();
  diff.shrink_to_fit();

  std::vector<Vec3r> exactOf(mesh.num_vertices());
  vertices_.clear();
  for (auto v : mesh.vertices()) {
    const auto e = CGAL::exact(mesh.point(v));
    exactOf[v.idx()] = Vec3r(d::fromET(e.x()), d::fromET(e.y()), d::fromET(e.z()));
    vertices_.push_back(exactOf[v.idx()]);
  }
  // In lexicographic order: the hull's own vertex order depends on more than the input
  // (the stress tests sample lines through these vertices; it must not vary between runs).
  std::sort(vertices_.begin(), vertices_.end(), [](const Vec3r& a, const Vec3r& b) {
    for (int i = 0; i < 3; ++i) {
      if (a[i] < b[i]) return true;
      if (b[i] < a[i]) return false;
    }
    return false;
  });

  std::vector<MddRefPlane> planes;
  triangles_ = 0;
  for (auto f : mesh.faces()) {
    Vec3r tri[3];
    int k = 0;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      if (k == 3) throw std::logic_error("MinkowskiDifferenceReference: non-triangular hull facet");
      tri[k++] = exactOf[v.idx()];
    }
    if (k != 3) throw std::logic_error("MinkowskiDifferenceReference: degenerate hull facet");
    ++triangles_;
    // convex_hull_3 orients faces counter-clockwise seen from outside.
    MddRefPlane pl;
    pl.normal = d::cross(Vec3r(tri[1] - tri[0]), Vec3r(tri[2] - tri[0]));
    int lead = 0;
    while (lead < 3 && d::sign(pl.normal[lead]) == 0) ++lead;
    if (lead == 3) throw std::logic_error("MinkowskiDifferenceReference: zero-area hull facet");
    const Rational scale = pl.normal[lead] > 0 ? pl.normal[lead] : Rational(-pl.normal[lead]);
    for (int i = 0; i < 3; ++i) pl.normal[i] /= scale;
    pl.offset = d::dot(pl.normal, tri[0]);
    planes.push_back(pl);
  }
  std::sort(planes.begin(), planes.end(), d::lessPlane);
  planes.erase(std::unique(planes.begin(), planes.end(), d::equalPlane), planes.end());

  // The centroid of the four independent differences is strictly inside M: every plane must
  // have it strictly on its inner side, which catches an inward-oriented facet.
  Vec3r centre = zero();
  for (int i = 0; i < 4; ++i) {
    const std::size_t pi = idx[i] / Q.size(), qi = idx[i] % Q.size();
    centre += P[pi] - Q[qi];
  }
  for (int i = 0; i < 3; ++i) centre[i] /= Rational(4);
  for (const auto& pl : planes) {
    if (!(d::dot(pl.normal, centre) < pl.offset))
      throw std::logic_error("MinkowskiDifferenceReference: hull facet not oriented outward");
  }

  planes_ = std::move(planes);
  iplanes_.clear();
  iplanes_.reserve(planes_.size());
  for (const auto& pl : planes_) {
    IntervalPlane ip;
    for (int i = 0; i < 3; ++i) ip.n[i] = d::toInterval(pl.normal[i]);
    ip.c = d::toInterval(pl.offset);
    iplanes_.push_back(ip);
  }
}

inline std::vector<Vec3r> MinkowskiDifferenceReference::facetNormalsThrough(const Vec3r& x) const {
  namespace d = mdd_reference_detail;
  const Interval xi[3] = {d::toInterval(x.x()), d::toInterval(x.y()), d::toInterval(x.z())};
  std::vector<Vec3r> out;
  for (std::size_t k = 0; k < planes_.size(); ++k)
    if (side(k, x, xi) == 0) out.push_back(planes_[k].normal);
  return out;
}

inline OriginLocation MinkowskiDifferenceReference::classifyOrigin(const Vec3r& qOffset) const {
  namespace d = mdd_reference_detail;
  // The origin is in M − u iff u is in M.
  const Interval ui[3] = {d::toInterval(qOffset.x()), d::toInterval(qOffset.y()),
                          d::toInterval(qOffset.z())};
  bool onSomePlane = false;
  for (std::size_t k = 0; k < planes_.size(); ++k) {
    const int sd = side(k, qOffset, ui);
    if (sd > 0) return OriginLocation::Outside;
    if (sd == 0) onSomePlane = true;
  }
  return onSomePlane ? OriginLocation::Boundary : OriginLocation::Inside;
}

inline MddRefResult MinkowskiDifferenceReference::query(const Vec3r& s, const Vec3r& u) const {
  namespace d = mdd_reference_detail;
  const Rational s2 = d::dot(s, s);
  if (d::sign(s2) == 0) throw std::invalid_argument("MinkowskiDifferenceReference: s = 0");

  MddRefResult r;
  r.origin = classifyOrigin(u);

  // Plane k constrains the line by t·(n·s) <= c − n·u.
  auto exactDen = [&](std::size_t k) { return d::dot(planes_[k].normal, s); };
  auto exactNum = [&](std::size_t k) {
    return Rational(planes_[k].offset - d::dot(planes_[k].normal, u));
  };

  bool empty = false;
  bool haveLo = false, haveHi = false;
  if (!filtered_) {
    for (std::size_t k = 0; k < planes_.size(); ++k) {
      const Rational den = exactDen(k), num = exactNum(k);
      const int ds = d::sign(den);
      if (ds == 0) {
        const int ns = d::sign(num);
        if (ns < 0) empty = true;
        if (ns == 0) r.lineInFacetPlane = true;
        continue;
      }
      const Rational t = num / den;
      if (ds > 0) {
        if (!haveHi || t < r.tHi) r.tHi = t;
        haveHi = true;
      } else {
        if (!haveLo || r.tLo < t) r.tLo = t;
        haveLo = true;
      }
    }
  } else {
    const Interval si[3] = {d::toInterval(s.x()), d::toInterval(s.y()), d::toInterval(s.z())};
    const Interval ui[3] = {d::toInterval(u.x()), d::toInterval(u.y()), d::toInterval(u.z())};
    struct Candidate {
      std::size_t k;
      Interval t;
    };
    std::vector<Candidate> lowers, uppers;
    for (std::size_t k = 0; k < planes_.size(); ++k) {
      const IntervalPlane& p = iplanes_[k];
      const Interval den = p.n[0] * si[0] + p.n[1] * si[1] + p.n[2] * si[2];
      int ds;
      Interval t;
      if (den.inf() > 0 || den.sup() < 0) {
        ds = den.inf() > 0 ? 1 : -1;
        t = (p.c - (p.n[0] * ui[0] + p.n[1] * ui[1] + p.n[2] * ui[2])) / den;
      } else {
        const Rational de = exactDen(k), num = exactNum(k);
        ds = d::sign(de);
        if (ds == 0) {
          const int ns = d::sign(num);
          if (ns < 0) empty = true;
          if (ns == 0) r.lineInFacetPlane = true;
          continue;
        }
        t = d::toInterval(Rational(num / de));
      }
      (ds > 0 ? uppers : lowers).push_back({k, t});
    }
    // t_lo is the largest lower bound. Every bound whose interval reaches the largest
    // certain minimum could be it; only those are evaluated exactly. Same for t_hi.
    if (!lowers.empty()) {
      double best = -std::numeric_limits<double>::infinity();
      for (const auto& c : lowers) best = std::max(best, c.t.inf());
      for (const auto& c : lowers) {
        if (c.t.sup() < best) continue;
        const Rational t = exactNum(c.k) / exactDen(c.k);
        if (!haveLo || r.tLo < t) r.tLo = t;
        haveLo = true;
      }
    }
    if (!uppers.empty()) {
      double best = std::numeric_limits<double>::infinity();
      for (const auto& c : uppers) best = std::min(best, c.t.sup());
      for (const auto& c : uppers) {
        if (c.t.inf() > best) continue;
        const Rational t = exactNum(c.k) / exactDen(c.k);
        if (!haveHi || t < r.tHi) r.tHi = t;
        haveHi = true;
      }
    }
  }
  // M is bounded, so both ends of the line are cut by some facet.
  if (!haveLo || !haveHi)
    throw std::logic_error("MinkowskiDifferenceReference: line not bounded by M's facets");

  r.lineMeetsM = !empty && !(r.tHi < r.tLo);
  if (!r.lineMeetsM) {
    if (r.origin != OriginLocation::Outside)
      throw std::logic_error("MinkowskiDifferenceReference: origin in M but line misses M");
    r.status = MddRefStatus::NoContact;
    r.t = 0;
    return r;
  }
  r.lo = makeHit(r.tLo, s, u, s2);
  r.hi = makeHit(r.tHi, s, u, s2);

  const int sLo = d::sign(r.tLo), sHi = d::sign(r.tHi);
  switch (r.origin) {
    case OriginLocation::Boundary:
      // Includes the line running inside a facet plane through the origin, where
      // t_lo < 0 < t_hi although P and Q only touch.
      if (sLo > 0 || sHi < 0)
        throw std::logic_error("MinkowskiDifferenceReference: boundary origin off the segment");
      r.status = MddRefStatus::Touching;
      r.t = 0;
      break;
    case OriginLocation::Inside:
      if (!(sLo < 0 && sHi > 0))
        throw std::logic_error("MinkowskiDifferenceReference: interior origin not inside segment");
      r.status = MddRefStatus::Penetrating;
      {
        const Rational negLo = -r.tLo;
        r.tie = (negLo == r.tHi);
        r.t = (negLo < r.tHi) ? r.tLo : r.tHi;  // on a tie: t_hi
      }
      break;
    case OriginLocation::Outside:
      if (sLo <= 0 && sHi >= 0)
        throw std::logic_error("MinkowskiDifferenceReference: exterior origin on the segment");
      r.status = MddRefStatus::Separated;
      r.t = sLo > 0 ? r.tLo : r.tHi;  // includes the graze t_lo == t_hi
      break;
  }
  r.contact = (r.t == r.tLo) ? r.lo : (r.t == r.tHi) ? r.hi : makeHit(r.t, s, u, s2);
  r.translation = r.contact.length;
  r.distance = r.status == MddRefStatus::Touching      ? 0.0
               : r.status == MddRefStatus::Penetrating ? -std::abs(r.translation)
                                                      : std::abs(r.translation);
  return r;
}

/// One-shot exact MDD of P and Q (world vertex lists) along s.
inline MddRefResult mddReference(const std::vector<Vec3r>& P, const std::vector<Vec3r>& Q,
                                 const Vec3r& s) {
  return MinkowskiDifferenceReference(P, Q).query(s);
}

}  // namespace mink_test
