// mink/cpd/detail/trim_pieces.hpp — Trimmer<T> (cpd/detail/trimming.hpp, which includes
// this file at its end; include that one): the soup of convolution polygons clipped to the
// region, and each polygon cut into convex pieces by every polygon that crosses it or lies
// in its plane.
#pragma once

namespace mink {
namespace detail {

template <class T>
int Trimmer<T>::mVertex(int i, int j) {
  const std::uint64_t key = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(i)) << 32) | static_cast<std::uint32_t>(j);
  const auto it = mIndex_.find(key);
  if (it != mIndex_.end()) return it->second;
  const int id = static_cast<int>(mCoord_.size());
  mIndex_.emplace(key, id);
  mPair_.push_back({i, j});
  mCoord_.push_back(frame_->m(i, j));
  return id;
}

template <class T>
void Trimmer<T>::buildSoup() {
  std::array<int, 2> poly[4];
  for (std::size_t f = 0; f < facets_->size(); ++f) {
    {
      Soup s;
      s.facet = static_cast<int>(f);
      s.nc = frame_->facetPolygon((*facets_)[f], poly);
      for (int c = 0; c < s.nc; ++c) s.m[c] = mVertex(poly[c][0], poly[c][1]);
      const Vec3<T>&p0 = mCoord_[s.m[0]], &p1 = mCoord_[s.m[1]], &p2 = mCoord_[s.m[2]];
      // Exactly collinear corners (a degenerate facet): no area, no cut.
      if (orient2d(p0, p1, p2, 0) == 0 && orient2d(p0, p1, p2, 1) == 0 && orient2d(p0, p1, p2, 2) == 0) continue;
      s.n = (p1 - p0).cross(p2 - p0);
      s.k = s.n.dot(p0);
      s.axis = 0;
      for (int a = 1; a < 3; ++a)
        if (absValue(s.n[a]) > absValue(s.n[s.axis])) s.axis = a;
      // The dominant axis by the exact projected orientations (the rounded normal may
      // hide a tiny component's sign): orient2d along an axis is the sign of n there.
      s.axisSign = orient2d(p0, p1, p2, s.axis);
      if (s.axisSign == 0) {
        for (int a = 0; a < 3; ++a)
          if (const int sg = orient2d(p0, p1, p2, a)) s.axis = a, s.axisSign = sg;
      }
      for (int c = 0; c < s.nc; ++c) s.box.add(toD(mCoord_[s.m[c]]));
      soup_.push_back(s);
    }
  }
}

template <class T>
bool Trimmer<T>::initialPiece(int F) {
  polyCount_ = 0;
  const Soup& f = soup_[static_cast<std::size_t>(F)];
  if (region_.bounded) {
    for (int a = 0; a < 3; ++a)
      if (f.box.lo[a] > toDouble(region_.hi[a]) || f.box.hi[a] < toDouble(region_.lo[a])) return false;
  }
  Poly& p = newPoly();
  for (int c = 0; c < f.nc; ++c) {
    p.v.push_back(pointCorner(f.m[c]));
    p.e.push_back(TrimLabel::edge(f.m[c], f.m[(c + 1) % f.nc]));
  }
  if (region_.bounded) {
    for (int b = 0; b < 6; ++b) {
      if (!clipKeep(F, 0, TrimLabel::box(b), -1)) return false;
    }
  }
  return true;
}

template <class T>
bool Trimmer<T>::clipKeep(int F, std::size_t i, std::uint64_t cut, int keepSide) {
  sides_.resize(polys_[i].v.size());
  bool pos = false, neg = false;
  for (std::size_t c = 0; c < polys_[i].v.size(); ++c) {
    sides_[c] = side(F, polys_[i].v[c], cut);
    pos |= sides_[c] > 0;
    neg |= sides_[c] < 0;
  }
  if (keepSide < 0) {
    if (!pos) return true;
    if (!neg) {
      polys_[i].dead = true;
      return false;
    }
    splitInto(F, i, cut, -1, scratch_);
    polys_[i].v.swap(scratch_.v);
    polys_[i].e.swap(scratch_.e);
    return polys_[i].v.size() >= 3;
  }
  if (!pos || !neg) return false;
  return true;  // the caller decides whether to split (see cutPlane / cutEdge)
}

template <class T>
void Trimmer<T>::splitInto(int F, std::size_t i, std::uint64_t cut, int keep, Poly& out) {
  out.v.clear();
  out.e.clear();
  const Poly& p = polys_[i];
  const std::size_t n = p.v.size();
  for (std::size_t c = 0; c < n; ++c) {
    const std::size_t d = (c + 1) % n;
    const int a = keep * sides_[c], b = keep * sides_[d];
    if (a >= 0) {
      out.v.push_back(p.v[c]);
      out.e.push_back((b >= 0 || a > 0) ? p.e[c] : cut);
    }
    if ((a > 0 && b < 0) || (a < 0 && b > 0)) {
      out.v.push_back(crossing(F, p.e[c], cut, p.v[c], p.v[d]));
      out.e.push_back(a > 0 ? cut : p.e[c]);
    }
  }
}

template <class T>
std::pair<int, int> Trimmer<T>::crossingCorners(int F, std::size_t i, std::uint64_t cut) {
  const Poly& p = polys_[i];
  const std::size_t n = p.v.size();
  int c0 = -1, c1 = -1;
  for (std::size_t c = 0; c < n; ++c) {
    const std::size_t d = (c + 1) % n;
    const int a = sides_[c], b = sides_[d];
    int x = -1;
    if (a == 0 && b != 0) x = p.v[c];
    if ((a > 0 && b < 0) || (a < 0 && b > 0)) x = crossing(F, p.e[c], cut, p.v[c], p.v[d]);
    if (x < 0) continue;
    if (c0 < 0)
      c0 = x;
    else if (x != c0)
      c1 = x;
  }
  return {c0, c1 < 0 ? c0 : c1};
}

template <class T>
template <class Meets>
void Trimmer<T>::cutPieces(int F, std::uint64_t cut, const Box3& reach, Meets&& meets) {
  const std::size_t n = polyCount_;
  for (std::size_t i = 0; i < n; ++i) {
    if (polys_[i].dead) continue;
    // The cut's polygon (or edge) lies in `reach`; a piece whose box misses it (with
    // room for rounding) cannot be crossed by it: no exact test is needed.
    if (!pieceBox(polys_[i]).overlaps(reach)) continue;
    if (!clipKeep(F, i, cut, 0)) continue;
    const std::pair<int, int> c = crossingCorners(F, i, cut);
    if (!meets(c.first, c.second)) continue;
    Poly& neg = newPoly();  // may reallocate polys_: index, not reference
    splitInto(F, i, cut, -1, neg);
    Poly& pos = newPoly();
    splitInto(F, i, cut, +1, pos);
    polys_[i].dead = true;
  }
}

template <class T>
Box3 Trimmer<T>::pieceBox(const Poly& p) const {
  Box3 b;
  for (int id : p.v) b.add(toD(coords_[static_cast<std::size_t>(id)]));
  const Eigen::Vector3d pad = Eigen::Vector3d::Constant(
      std::ldexp(1.0, -30) * (b.hi - b.lo).cwiseAbs().maxCoeff() + std::ldexp(1.0, -30) * b.hi.cwiseAbs().maxCoeff() +
      std::ldexp(1.0, -30) * b.lo.cwiseAbs().maxCoeff());
  b.lo -= pad;
  b.hi += pad;
  return b;
}

template <class T>
void Trimmer<T>::cutByOthers(int F) {
  const Soup& f = soup_[static_cast<std::size_t>(F)];
  Box3 query = f.box;
  if (region_.bounded)
    for (int a = 0; a < 3; ++a) {
      query.lo[a] = std::max(query.lo[a], toDouble(region_.lo[a]));
      query.hi[a] = std::min(query.hi[a], toDouble(region_.hi[a]));
    }
  cutters_.clear();
  tree_.forOverlapping(query, [&](int g) {
    if (g != F) cutters_.push_back(g);
  });
  coplanar_.clear();
  for (int G : cutters_) {
    const Soup& g = soup_[static_cast<std::size_t>(G)];
    // An edge of F in G's plane (G not one of its two polygons): a third sheet through
    // it, across which the pieces beside it must not be joined.
    for (int c = 0; c < f.nc; ++c) {
      const int a = f.m[c], b = f.m[(c + 1) % f.nc];
      if (pointSide(g, a) != 0 || pointSide(g, b) != 0) continue;
      bool side = false;
      for (int k = 0; k < g.nc; ++k)
        side = side || (g.m[k] == b && g.m[(k + 1) % g.nc] == a) || (g.m[k] == a && g.m[(k + 1) % g.nc] == b);
      if (!side) blocked_.insert(TrimLabel::edge(a, b));
    }
    int pos = 0, neg = 0;
    for (int c = 0; c < g.nc; ++c) {
      const int sc = pointSide(f, g.m[c]);
      pos += sc > 0;
      neg += sc < 0;
    }
    if (pos == 0 && neg == 0) {
      // In F's plane: cut by G's edges; remember G for the duplicate test.
      coplanar_.push_back(G);
      for (int c = 0; c < g.nc; ++c) {
        const int u = g.m[c], v = g.m[(c + 1) % g.nc];
        const std::uint64_t cut = TrimLabel::edge(u, v);
        Box3 reach;
        reach.add(toD(mCoord_[static_cast<std::size_t>(u)]));
        reach.add(toD(mCoord_[static_cast<std::size_t>(v)]));
        cutPieces(F, cut, padded(reach), [&](int c0, int c1) { return segmentOverlapsEdge(c0, c1, u, v); });
      }
      continue;
    }
    // On one side of F's plane: no crossing, unless an edge of G lies in F's plane (G
    // touches F along a line, as two walls meeting at a right angle in an aligned
    // configuration do): F's status may change across that line, so it is a cut.
    if ((pos == 0 || neg == 0) && g.nc - pos - neg < 2) continue;
    // Does F reach both sides of G's plane? Else no crossing either.
    int fp = 0, fn = 0;
    for (int c = 0; c < f.nc; ++c) {
      const int t = pointSide(g, f.m[c]);
      fp += t > 0;
      fn += t < 0;
    }
    if (fp == 0 || fn == 0) continue;
    cutPieces(F, TrimLabel::plane(G), padded(g.box), [&](int c0, int c1) { return segmentMayMeetTriangle(c0, c1, G); });
  }
}

/// Has the piece no area to rounding: below (2^-40 of its size)², its size the largest
/// coordinate of its corners or of their spread? Decided on the corners scaled by a
/// power of two to a size near one, so that neither square over- or underflows.
template <class T>
bool Trimmer<T>::isSliver(const Poly& p) const {
  Box3 b;
  for (int id : p.v) b.add(toD(coords_[static_cast<std::size_t>(id)]));
  const double size = std::max((b.hi - b.lo).maxCoeff(), std::max(b.hi.cwiseAbs().maxCoeff(), b.lo.cwiseAbs().maxCoeff()));
  if (!(size > 0)) return true;
  int e = 0;
  std::frexp(size, &e);
  const auto at = [&](std::size_t i) { return timesPow2(toD(coords_[static_cast<std::size_t>(p.v[i])]), -e); };
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  const Eigen::Vector3d x0 = at(0);
  for (std::size_t i = 1; i + 1 < p.v.size(); ++i) n += (at(i) - x0).cross(at(i + 1) - x0);
  const double s = std::ldexp(1.0, -40);
  return !(0.5 * n.norm() > s * s);
}

/// Would every piece cut from p be a sliver (isSliver)? True when p's box is narrower
/// than 2^-42 of m, the least largest |coordinate| of a point of the box: a piece of p
/// (corners in p's box, to their rounding) then has size >= m and area <= sqrt(2) w² <
/// (2^-40 m)², w the box's widest side. Such a polygon (a facet of meshes 2^-42 the size
/// of their distance from the origin) is not cut: its pieces would all be dropped, and
/// cutting them cost an arrangement of every coplanar neighbour's edges in exact
/// arithmetic (seconds for two subnormal cubes 3 apart).
template <class T>
bool Trimmer<T>::belowResolution(const Poly& p) const {
  Box3 b;
  for (int id : p.v) b.add(toD(coords_[static_cast<std::size_t>(id)]));
  double m = 0;
  for (int a = 0; a < 3; ++a)
    if (b.lo[a] > 0 || b.hi[a] < 0) m = std::max(m, std::min(std::abs(b.lo[a]), std::abs(b.hi[a])));
  const double w = (b.hi - b.lo).maxCoeff();
  return std::isfinite(m) && std::isfinite(w) && w <= std::ldexp(m, -42);
}

template <class T>
bool Trimmer<T>::segmentMayMeetTriangle(int c0, int c1, int G) const {
  const Soup& g = soup_[static_cast<std::size_t>(G)];
  for (int c = 0; c < g.nc; ++c) {
    const std::uint64_t e = TrimLabel::edge(g.m[c], g.m[(c + 1) % g.nc]);
    // side() > 0 is the left of the edge's first → second point; polygon G is
    // counter-clockwise, so outside is the right when m[c] < m[c + 1], else the left.
    const int out = g.m[c] < g.m[(c + 1) % g.nc] ? -1 : 1;
    if (side(G, c0, e) == out && side(G, c1, e) == out) return false;
  }
  return true;
}

}  // namespace detail
}  // namespace mink
