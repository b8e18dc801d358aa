// mink/cpd/detail/trim_patches.hpp — Trimmer<T> (cpd/detail/trimming.hpp, which includes
// this file at its end; include that one): pieces stitched into patches where no facet
// separates them, one collision test per patch, and the wanted pieces of patches on the
// boundary emitted as triangles.
#pragma once

namespace mink {
namespace detail {

template <class T>
void Trimmer<T>::stitch() {
  parent_.resize(final_.size());
  for (std::size_t i = 0; i < final_.size(); ++i) parent_[i] = static_cast<int>(i);
  edgeUse_.clear();
  for (const Soup& f : soup_)
    for (int c = 0; c < f.nc; ++c) ++edgeUse_[TrimLabel::edge(f.m[c], f.m[(c + 1) % f.nc])];
  sideOwner_.clear();
  for (std::size_t i = 0; i < final_.size(); ++i) {
    const Final& f = final_[i];
    for (int k = 0; k < f.count; ++k) {
      const int a = finalV_[static_cast<std::size_t>(f.first + k)];
      const int b = finalV_[static_cast<std::size_t>(f.first + (k + 1) % f.count)];
      sideOwner_[sideKey(a, b)] = static_cast<int>(i);
    }
  }
  for (std::size_t i = 0; i < final_.size(); ++i) {
    const Final& f = final_[i];
    for (int k = 0; k < f.count; ++k) {
      const int a = finalV_[static_cast<std::size_t>(f.first + k)];
      const int b = finalV_[static_cast<std::size_t>(f.first + (k + 1) % f.count)];
      const auto it = sideOwner_.find(sideKey(b, a));
      if (it == sideOwner_.end()) continue;
      const int j = it->second;
      if (find(static_cast<int>(i)) == find(j)) continue;
      if (!separated(f.soup, final_[static_cast<std::size_t>(j)].soup, finalE_[static_cast<std::size_t>(f.first + k)], a, b))
        parent_[static_cast<std::size_t>(find(static_cast<int>(i)))] = find(j);
    }
  }
}

template <class T>
bool Trimmer<T>::sideCrossed(int F, int a, int b) const {
  // Once per side: the two pieces that share it ask with its ends swapped (every test
  // below is symmetric in a and b).
  const TrimKey key{{static_cast<std::uint64_t>(F), static_cast<std::uint64_t>(std::min(a, b)),
                     static_cast<std::uint64_t>(std::max(a, b))}};
  const auto it = sideCrossed_.find(key);
  if (it != sideCrossed_.end()) return it->second != 0;
  Box3 query;
  query.add(toD(coords_[static_cast<std::size_t>(a)]));
  query.add(toD(coords_[static_cast<std::size_t>(b)]));
  bool crossed = false;
  tree_.forOverlapping(padded(query), [&](int G) {
    if (crossed || G == F) return;
    const Soup& g = soup_[static_cast<std::size_t>(G)];
    const std::uint64_t plane = TrimLabel::plane(G);
    // Off G's plane by the filter at either end: no exact test of the other (most sides
    // near G have one end within the filter's width of its plane, the other clearly off).
    if constexpr (!ScalarTraits<T>::isExact) {
      const auto offByFilter = [&](int id) {
        const TrimKey& k = keys_[static_cast<std::size_t>(id)];
        return !k.isPoint() && !k.contains(plane) && filteredSide(F, id, plane) != 0;
      };
      if (offByFilter(a) || offByFilter(b)) return;
    }
    if (side(F, a, plane) != 0 || side(F, b, plane) != 0) return;
    bool inF = true;
    for (int c = 0; c < g.nc && inF; ++c) inF = pointSide(soup_[static_cast<std::size_t>(F)], g.m[c]) == 0;
    if (!inF) {
      crossed = segmentMayMeetTriangle(a, b, G);
      return;
    }
    for (int c = 0; c < g.nc && !crossed; ++c) {
      const int u = g.m[c], v = g.m[(c + 1) % g.nc];
      const std::uint64_t e = TrimLabel::edge(u, v);
      if (side(F, a, e) == 0 && side(F, b, e) == 0 && segmentOverlapsEdge(a, b, std::min(u, v), std::max(u, v)))
        crossed = true;
    }
  });
  sideCrossed_.emplace(key, crossed ? 1 : 0);
  return crossed;
}

template <class T>
bool Trimmer<T>::separated(int F, int G, std::uint64_t label, int a, int b) const {
  const Vec3<T>&xa = coords_[static_cast<std::size_t>(a)], &xb = coords_[static_cast<std::size_t>(b)];
  const T size = T((xa - xb).cwiseAbs().maxCoeff());
  const Soup& sf = soup_[static_cast<std::size_t>(F)];
  T scale = T(0);
  for (int c = 0; c < sf.nc; ++c) scale = std::max(scale, T(mCoord_[static_cast<std::size_t>(sf.m[c])].cwiseAbs().maxCoeff()));
  if (!(size > T(1e-9) * scale)) return true;
  if (TrimLabel::isBox(label)) return true;
  const Soup& f = soup_[static_cast<std::size_t>(F)];
  bool own = false;
  for (int c = 0; c < f.nc; ++c) own = own || label == TrimLabel::edge(f.m[c], f.m[(c + 1) % f.nc]);
  if (!own) {
    // A cut within F (a plane's trace, or a coplanar polygon's edge line): the pieces are
    // one if no polygon reaches the side along it — every polygon whose plane holds the
    // side is tested, not only the one that made the cut (several may share its line).
    if (F != G) return true;
    return sideCrossed(F, a, b);
  }
  if (F == G) return true;
  const auto it = edgeUse_.find(label);
  if (it == edgeUse_.end() || it->second != 2) return true;
  return blocked_.count(label) != 0;
}

template <class T>
bool Trimmer<T>::polygonMeetsBall(const int* v, int count) const {
  if constexpr (ScalarTraits<T>::isExact) {
    return ballTest<T>(v, count) > 0;
  } else {
    // In double first (T = double or float: no rounding on the way in), a certain answer
    // where the decision has room — a corner well inside the ball, the polygon's box well
    // outside it (relative errors below 8 ulps; an overflowed square is still the larger;
    // no subnormal radius) — then intervals, then expansions.
    const Vec3<T>& c = region_.centre;
    const double r = toDouble(region_.radius), u = std::ldexp(1.0, -50);
    if (std::numeric_limits<T>::digits <= 53 && r > 1e-140) {
      Eigen::Vector3d lo = toD(coords_[static_cast<std::size_t>(v[0])]), hi = lo;
      for (int i = 0; i < count; ++i) {
        const Eigen::Vector3d x = toD(coords_[static_cast<std::size_t>(v[i])]);
        if ((x - toD(c)).squaredNorm() * (1 + 16 * u) < r * r * (1 - 16 * u)) return true;
        lo = lo.cwiseMin(x);
        hi = hi.cwiseMax(x);
      }
      double gap2 = 0;
      for (int a = 0; a < 3; ++a) {
        const double ca = toDouble(c[a]), g = std::max({lo[a] - ca, ca - hi[a], 0.0});
        gap2 += g * g;
      }
      if (gap2 * (1 - 16 * u) > r * r * (1 + 16 * u)) return false;
    }
    const int filtered = ballTest<IV>(v, count);
    if (filtered != 0) return filtered > 0;
    return ballTest<EX>(v, count) > 0;
  }
}

template <class T>
template <class N>
int Trimmer<T>::ballTest(const int* v, int count) const {
  // The nearest point of a convex polygon to the centre c is a corner, a point inside a
  // side (its projection falls strictly between the side's ends) or a point inside the
  // polygon (c projects into it): the polygon meets the ball iff one of those within r.
  // Every decision is the sign of a polynomial in the given numbers, each homogeneous in
  // (c − corner, r), in a side's direction d and in the normal n, which are therefore
  // scaled apart by powers of two (exact) so that no product over- or underflows for a
  // ball of any size beside pieces of any size (a piece can be 2^-300 of the ball).
  constexpr bool exact = !std::is_same<N, IV>::value;
  auto sgn = [](const N& x) {
    if constexpr (std::is_same<N, IV>::value)
      return x.certainSign();
    else if constexpr (std::is_same<N, T>::value)
      return detail::sign(x);
    else
      return x.sign();
  };
  auto scale = [](double m) {  // 2^-e, m's exponent e (within ±960: a finite factor)
    int e = 0;
    if (m > 0 && std::isfinite(m)) std::frexp(m, &e);
    return N(static_cast<FloatOf>(std::ldexp(1.0, -std::max(-960, std::min(960, e)))));
  };
  auto x = [&](int i) -> const Vec3<T>& { return coords_[static_cast<std::size_t>(v[(i % count + count) % count])]; };
  const Vec3<T>& c = region_.centre;
  double big = toDouble(region_.radius);
  for (int i = 0; i < count; ++i) big = std::max(big, toD(x(i)).cwiseAbs().maxCoeff() + toD(c).cwiseAbs().maxCoeff());
  const N sw = exact && std::is_same<N, T>::value ? N(1) : scale(big);
  auto w = [&](int i, N out[3]) {
    for (int a = 0; a < 3; ++a) out[a] = (N(c[a]) - N(x(i)[a])) * sw;
  };
  auto diff = [&](int i, int j, N out[3]) {  // x(j) − x(i), scaled near one
    const double m = toD(Vec3<T>(x(j) - x(i))).cwiseAbs().maxCoeff();
    const N s = std::is_same<N, T>::value ? N(1) : scale(m);
    for (int a = 0; a < 3; ++a) out[a] = (N(x(j)[a]) - N(x(i)[a])) * s;
  };
  const N rr = N(region_.radius) * sw, r2 = rr * rr;
  bool unsure = false;
  // A "yes" is certain where its sign is (> 0, or = 0 with expansions); an interval that
  // cannot tell leaves the answer unsure unless another test says yes.
  auto yes = [&](int s) {
    if (s > 0 || (exact && s == 0)) return true;
    if (!exact && s == 0) unsure = true;
    return false;
  };
  for (int i = 0; i < count; ++i) {
    N wi[3];
    w(i, wi);
    if (yes(sgn(r2 - dot(wi, wi)))) return 1;
  }
  for (int i = 0; i < count; ++i) {
    N wa[3], wb[3], d[3];
    w(i, wa);
    w(i + 1, wb);
    diff(i, i + 1, d);
    const N wd = dot(wa, d);
    const int s1 = sgn(wd), s2 = -sgn(dot(wb, d));  // (c − a)·d > 0 and (c − b)·d < 0
    if (s1 < 0 || s2 < 0 || (exact && (s1 == 0 || s2 == 0))) continue;
    const N dd = dot(d, d);
    const bool within = yes(sgn(r2 * dd - (dot(wa, wa) * dd - wd * wd)));
    if (within && s1 > 0 && s2 > 0) return 1;
    if (within) unsure = true;  // the projection may fall on an end: intervals cannot tell
  }
  // The normal: the fan's cross products summed (no corner need be strictly convex).
  Eigen::Vector3d approx = Eigen::Vector3d::Zero();
  for (int i = 1; i + 1 < count; ++i) approx += toD(Vec3<T>(x(i) - x(0))).cross(toD(Vec3<T>(x(i + 1) - x(0))));
  const double nm = approx.cwiseAbs().maxCoeff();
  const N sn = std::is_same<N, T>::value ? N(1) : scale(nm > 0 ? nm : 1.0);
  N n[3] = {N(0), N(0), N(0)};
  for (int i = 1; i + 1 < count; ++i) {
    N p[3], q[3], t[3];
    for (int a = 0; a < 3; ++a) p[a] = N(x(i)[a]) - N(x(0)[a]), q[a] = N(x(i + 1)[a]) - N(x(0)[a]);
    cross(p, q, t);
    for (int a = 0; a < 3; ++a) n[a] += t[a] * sn;
  }
  const int sn2 = sgn(dot(n, n));
  if (sn2 == 0) return exact ? -1 : 0;  // no area (expansions): the sides decided it
  bool inside = true, maybe = false;
  for (int i = 0; i < count && inside; ++i) {
    N wa[3], d[3], t[3];
    w(i, wa);
    diff(i, i + 1, d);
    cross(d, wa, t);
    const int s = sgn(dot(t, n));
    if (s < 0) inside = false;
    if (!exact && s == 0) maybe = true;
  }
  if (inside) {
    N w0[3];
    w(0, w0);
    const N h = dot(n, w0);
    if (yes(sgn(r2 * dot(n, n) - h * h))) return maybe ? 0 : 1;
  }
  return unsure ? 0 : -1;
}

template <class T>
bool Trimmer<T>::ownedByOther(int F, const Poly& p) const {
  if (coplanar_.empty()) return false;
  const Soup& f = soup_[static_cast<std::size_t>(F)];
  const Vec3<T> x = centroid(p);
  for (int G : coplanar_) {
    if (G > F) continue;
    const Soup& g = soup_[static_cast<std::size_t>(G)];
    if (g.axis != f.axis || g.axisSign != f.axisSign) continue;  // opposite orientation
    bool inside = true;
    for (int c = 0; c < g.nc && inside; ++c)
      inside = f.axisSign * orient2d(mCoord_[g.m[c]], mCoord_[g.m[(c + 1) % g.nc]], x, f.axis) > 0;
    if (inside) return true;
  }
  return false;
}

template <class T>
void Trimmer<T>::classify(MeshOverlap<T>& overlap, MinkowskiPatch<T>& out) {
  // Each patch is classified at its largest piece (the nudge's room grows with the piece).
  status_.assign(final_.size(), -1);
  representative_.assign(final_.size(), -1);
  for (std::size_t i = 0; i < final_.size(); ++i) {
    int& r = representative_[static_cast<std::size_t>(find(static_cast<int>(i)))];
    if (r < 0 || final_[i].area > final_[static_cast<std::size_t>(r)].area) r = static_cast<int>(i);
  }
  // A patch with a piece on the inner side of a polygon that crosses it is inside M:
  // no test (-2: a patch with a wanted piece, not yet decided).
  for (std::size_t i = 0; i < final_.size(); ++i)
    if (final_[i].wanted) status_[static_cast<std::size_t>(find(static_cast<int>(i)))] = -2;
  for (std::size_t i = 0; i < final_.size(); ++i) {
    int& st = status_[static_cast<std::size_t>(find(static_cast<int>(i)))];
    if (st == -2 && insideAcrossCut(static_cast<int>(i))) st = 0;
  }
  emitted_.clear();
  for (std::size_t i = 0; i < final_.size(); ++i) {
    if (!final_[i].wanted) continue;
    const int root = find(static_cast<int>(i));
    int& st = status_[static_cast<std::size_t>(root)];
    if (st < 0) {
      ++out.overlapTests;
      st = onBoundary(representative_[static_cast<std::size_t>(root)], overlap) ? 1 : 0;
    }
    if (st == 1) emitted_.push_back(static_cast<int>(i));
  }
}

/// A piece with a side on the plane of a polygon G that crosses its facet F, the side's
/// open segment inside G's open polygon, and the piece on G's inner side, is inside M.
/// Every convolution facet has M on its inner side next to its open part: FV, a point
/// p − v with p inside a face of A, and p − εn inside A; VF, the same for B; EE (two
/// convex edges, A's faces on one side of the facet's plane and B's on the other), the
/// wedges of A and −B at the two edges sum to the closed half-space below the plane. So
/// the points of the piece next to that side have M on F's outer side (below G) as well as
/// on its inner side: they are interior points of M, not on ∂M, and neither is the piece
/// (a piece is on ∂M wholly or not at all). Exact: signs of the corners named by their
/// planes, as for the cuts.
template <class T>
bool Trimmer<T>::insideAcrossCut(int piece) const {
  const Final& fp = final_[static_cast<std::size_t>(piece)];
  const int* v = &finalV_[static_cast<std::size_t>(fp.first)];
  const std::uint64_t* e = &finalE_[static_cast<std::size_t>(fp.first)];
  for (int k = 0; k < fp.count; ++k) {
    if (!TrimLabel::isPlane(e[k]) || TrimLabel::index(e[k]) == fp.soup) continue;
    // The piece is convex and has this side on G's plane: its first corner off that
    // plane tells the piece's side.
    int s = 0;
    for (int c = 2; c < fp.count && s == 0; ++c) s = side(fp.soup, v[(k + c) % fp.count], e[k]);
    const int G = TrimLabel::index(e[k]);
    if (s < 0 && clearOfRounding(fp, k, G) && openSideInPolygon(v[k], v[(k + 1) % fp.count], G)) return true;
  }
  return false;
}

/// The signs above are exact on the soup, whose corners a_i − b_j are rounded in T: the
/// facets they stand for lie within 2^(1 − p) of the largest coordinate S (p: T's digits,
/// 53 for double, 24 for float). The shortcut is taken only where that cannot matter: the
/// side's midpoint 2^(13 − p) S or more inside each of G's edge lines and a corner of the
/// piece as far below G's plane (else the collision test decides); 2^-40 S for double and
/// for exact T (no rounding: a gate that only costs tests). Measured on the corners scaled
/// by a power of two to a size near one.
template <class T>
bool Trimmer<T>::clearOfRounding(const Final& fp, int k, int G) const {
  const Soup& g = soup_[static_cast<std::size_t>(G)];
  const int* v = &finalV_[static_cast<std::size_t>(fp.first)];
  double S = 0;
  for (int c = 0; c < fp.count; ++c) S = std::max(S, toD(coords_[static_cast<std::size_t>(v[c])]).cwiseAbs().maxCoeff());
  for (int c = 0; c < g.nc; ++c) S = std::max(S, toD(mCoord_[g.m[c]]).cwiseAbs().maxCoeff());
  if (!(S > 0) || !std::isfinite(S)) return false;
  int ex = 0;
  std::frexp(S, &ex);
  const auto scaled = [&](const Vec3<T>& x) { return timesPow2(toD(x), -ex); };
  constexpr int digits = ScalarTraits<T>::isExact ? 53 : std::numeric_limits<T>::digits;
  const double eta = std::ldexp(1.0, 13 - digits);
  const Eigen::Vector3d mid = 0.5 * (scaled(coords_[static_cast<std::size_t>(v[k])]) +
                                     scaled(coords_[static_cast<std::size_t>(v[(k + 1) % fp.count])]));
  for (int c = 0; c < g.nc; ++c) {
    const Eigen::Vector3d u = scaled(mCoord_[g.m[c]]), w = scaled(mCoord_[g.m[(c + 1) % g.nc]]);
    const double len = (w - u).norm();
    if (!(len > 0) || !((w - u).cross(mid - u).norm() >= eta * len)) return false;
  }
  const Eigen::Vector3d g0 = scaled(mCoord_[g.m[0]]);
  const Eigen::Vector3d n = (scaled(mCoord_[g.m[1]]) - g0).cross(scaled(mCoord_[g.m[2]]) - g0);
  const double nl = n.norm();
  if (!(nl > 0)) return false;
  double below = 0;
  for (int c = 0; c < fp.count; ++c) below = std::max(below, -(scaled(coords_[static_cast<std::size_t>(v[c])]) - mid).dot(n));
  return below >= eta * nl;
}

/// Does the open segment between corners a and b (points of G's plane) lie inside G's open
/// polygon: both ends inside or on each of G's edge lines, not both on one?
template <class T>
bool Trimmer<T>::openSideInPolygon(int a, int b, int G) const {
  const Soup& g = soup_[static_cast<std::size_t>(G)];
  for (int c = 0; c < g.nc; ++c) {
    const int u = g.m[c], w = g.m[(c + 1) % g.nc];
    // side() > 0 is the left of the edge's lower-id → higher-id end; G turns counter-clockwise.
    const int in = u < w ? 1 : -1;
    const std::uint64_t edge = TrimLabel::edge(u, w);
    const int sa = in * side(G, a, edge), sb = in * side(G, b, edge);
    if (sa < 0 || sb < 0 || (sa == 0 && sb == 0)) return false;
  }
  return true;
}

template <class T>
bool Trimmer<T>::onBoundary(int piece, MeshOverlap<T>& overlap) const {
  const Final& fp = final_[static_cast<std::size_t>(piece)];
  const int F = fp.soup;
  const Soup& f = soup_[static_cast<std::size_t>(F)];
  Vec3<T> x = Vec3<T>::Zero();
  for (int k = 0; k < fp.count; ++k) x += coords_[static_cast<std::size_t>(finalV_[static_cast<std::size_t>(fp.first + k)])];
  x /= T(fp.count);
  const Eigen::Vector3d xd = toD(x);
  // F's unit normal from its sides, each scaled by a power of two to a size near one:
  // f.n, their cross product in T, underflows for a facet of a mesh 2^-500 beside one
  // of size 1 (a NaN offset then sent every exact test to its slowest path). F's
  // dominant axis where even that rounds to zero.
  const auto scaledSide = [&](int c) { return unitOrder(toD(Vec3<T>(mCoord_[f.m[c]] - mCoord_[f.m[0]]))); };
  Eigen::Vector3d nd = scaledSide(1).cross(scaledSide(2));
  if (const double len = nd.norm(); len > 0 && std::isfinite(len)) {
    nd /= len;
  } else {
    nd.setZero();
    nd[f.axis] = f.axisSign;
  }
  double bound = std::numeric_limits<double>::infinity();
  if (region_.bounded)
    for (int a = 0; a < 3; ++a) {
      const double d = std::min(xd[a] - toDouble(region_.lo[a]), toDouble(region_.hi[a]) - xd[a]);
      bound = std::min(bound, d * d);
    }
  const double d2 = tree_.nearest(xd, bound, [&](int G) {
    if (G == F) return std::numeric_limits<double>::infinity();
    const Soup& g = soup_[static_cast<std::size_t>(G)];
    bool inPlane = true;
    for (int c = 0; c < g.nc && inPlane; ++c) inPlane = pointSide(f, g.m[c]) == 0;
    if (inPlane) return std::numeric_limits<double>::infinity();  // in F's plane: the motion leaves it
    double d = squaredDistanceToTriangle(xd, toD(mCoord_[g.m[0]]), toD(mCoord_[g.m[1]]), toD(mCoord_[g.m[2]]));
    if (g.nc == 4)
      d = std::min(d, squaredDistanceToTriangle(xd, toD(mCoord_[g.m[0]]), toD(mCoord_[g.m[2]]), toD(mCoord_[g.m[3]])));
    return d;
  });
  double delta = 0.5 * std::sqrt(d2);
  if (!std::isfinite(delta)) {
    delta = 0.0;
    for (int c = 0; c < f.nc; ++c) delta = std::max(delta, (toD(mCoord_[f.m[c]]) - xd).norm());
  }
  Vec3<T> y;
  for (int a = 0; a < 3; ++a) y[a] = x[a] + T(delta * nd[a]);
  // Most pieces inside M overlap where one of the last few did (they are tested in
  // order along the facets): those triangle pairs first, exactly, before a traversal.
  for (const std::pair<int, int>& w : witnesses_) {
    const auto& ta = frame_->A().triangle(w.first);
    const auto& tb = frame_->B().triangle(w.second);
    if (trianglesIntersect(frame_->a(ta[0]), frame_->a(ta[1]), frame_->a(ta[2]), Vec3<T>(frame_->b(tb[0]) + y),
                           Vec3<T>(frame_->b(tb[1]) + y), Vec3<T>(frame_->b(tb[2]) + y)))
      return false;
  }
  if (!overlap.overlaps(y)) return true;
  if (overlap.result().status == OverlapStatus::BoundariesMeet) {
    if (witnesses_.size() < kWitnesses)
      witnesses_.emplace_back(overlap.result().triangleA, overlap.result().triangleB);
    else
      witnesses_[nextWitness_] = {overlap.result().triangleA, overlap.result().triangleB};
    nextWitness_ = (nextWitness_ + 1) % kWitnesses;
  }
  return false;
}

/// A soup edge is one line in every polygon; the cut of F by G's plane is the cut of G by
/// F's; a box face meets each polygon in a line of its own.
template <class T>
TrimKey Trimmer<T>::lineOf(int soup, std::uint64_t label) {
  if (TrimLabel::isEdge(label)) return TrimKey{{label, TrimLabel::kNone, TrimLabel::kNone}};
  std::uint64_t own = TrimLabel::plane(soup);
  if (TrimLabel::isPlane(label) && label < own) std::swap(label, own);
  return TrimKey{{own, label, TrimLabel::kNone}};
}

template <class T>
bool Trimmer<T>::lineOrder(const std::pair<TrimKey, int>& x, const std::pair<TrimKey, int>& y) {
  for (int i = 0; i < 3; ++i)
    if (x.first.k[i] != y.first.k[i]) return x.first.k[i] < y.first.k[i];
  return x.second < y.second;
}

/// The corners of the emitted pieces by the line they lie on (each side's two ends, under
/// the side's line): a side of one piece may run past a corner of its neighbour across the
/// line (the neighbour cut there by a plane that does not reach this piece). emit() puts
/// such corners into the side, so that the patch's triangles meet edge to edge and share
/// their corners — the Phong surface's vertex normals are then continuous across facets
/// (with a T-junction, the normal field jumped along the side and Phong projections were
/// lost there: cone/axes needed two to four balls per frame).
template <class T>
void Trimmer<T>::conform() {
  lineCorners_.clear();
  for (const int i : emitted_) {
    const Final& f = final_[static_cast<std::size_t>(i)];
    for (int k = 0; k < f.count; ++k) {
      const TrimKey line = lineOf(f.soup, finalE_[static_cast<std::size_t>(f.first + k)]);
      lineCorners_.push_back({line, finalV_[static_cast<std::size_t>(f.first + k)]});
      lineCorners_.push_back({line, finalV_[static_cast<std::size_t>(f.first + (k + 1) % f.count)]});
    }
  }
  std::sort(lineCorners_.begin(), lineCorners_.end(), lineOrder);
  lineCorners_.erase(std::unique(lineCorners_.begin(), lineCorners_.end()), lineCorners_.end());
}

template <class T>
void Trimmer<T>::emit(int piece, MinkowskiPatch<T>& out) {
  const Final& fp = final_[static_cast<std::size_t>(piece)];
  const Soup& f = soup_[static_cast<std::size_t>(fp.soup)];
  const ConvolutionPair& pair = (*facets_)[static_cast<std::size_t>(f.facet)];
  auto index = [&](int id) {
    if (static_cast<std::size_t>(id) >= outVertex_.size()) outVertex_.resize(static_cast<std::size_t>(id) + 1, -1);
    int& o = outVertex_[static_cast<std::size_t>(id)];
    if (o < 0) {
      o = static_cast<int>(out.vertices.size());
      out.vertices.push_back(coords_[static_cast<std::size_t>(id)]);
    }
    return o;
  };
  auto add = [&](int a, int b, int c) {
    // A fan triangle of a piece that meets the ball may itself miss it: the patch keeps
    // only triangles that meet the ball.
    const int tri[3] = {a, b, c};
    if (region_.ball && !polygonMeetsBall(tri, 3)) return;
    out.triangles.push_back({index(a), index(b), index(c)});
    out.pairs.push_back(pair);
  };
  const int* v = &finalV_[static_cast<std::size_t>(fp.first)];
  const std::uint64_t* e = &finalE_[static_cast<std::size_t>(fp.first)];
  // The piece's corners with the corners of other pieces that lie inside its sides, in
  // order along each side (by the coordinate along the side's dominant axis: corners
  // equal there to an end are not inside).
  ring_.clear();
  for (int k = 0; k < fp.count; ++k) {
    const int a = v[k], b = v[(k + 1) % fp.count];
    ring_.push_back(a);
    const std::pair<TrimKey, int> lo{lineOf(fp.soup, e[k]), std::numeric_limits<int>::min()};
    auto it = std::lower_bound(lineCorners_.begin(), lineCorners_.end(), lo, lineOrder);
    const Vec3<T>&xa = coords_[static_cast<std::size_t>(a)], &xb = coords_[static_cast<std::size_t>(b)];
    int ax = 0;
    for (int d = 1; d < 3; ++d)
      if (absValue(T(xb[d] - xa[d])) > absValue(T(xb[ax] - xa[ax]))) ax = d;
    const T s = xb[ax] > xa[ax] ? T(1) : T(-1);
    const std::size_t first = ring_.size();
    for (; it != lineCorners_.end() && it->first == lo.first; ++it) {
      const T t = coords_[static_cast<std::size_t>(it->second)][ax];
      if (s * t > s * xa[ax] && s * t < s * xb[ax]) ring_.push_back(it->second);
    }
    std::sort(ring_.begin() + static_cast<std::ptrdiff_t>(first), ring_.end(), [&](int x, int y) {
      return s * coords_[static_cast<std::size_t>(x)][ax] < s * coords_[static_cast<std::size_t>(y)][ax];
    });
  }
  if (ring_.size() == static_cast<std::size_t>(fp.count)) {
    for (int i = 1; i + 1 < fp.count; ++i) add(v[0], v[i], v[i + 1]);
    return;
  }
  // A fan from the piece's centroid (inside it: the piece is convex and not a sliver), so
  // that no triangle is flat on a side that holds inserted corners.
  Vec3<T> c = Vec3<T>::Zero();
  for (int k = 0; k < fp.count; ++k) c += coords_[static_cast<std::size_t>(v[k])];
  c /= T(fp.count);
  const int mid = static_cast<int>(keys_.size());
  keys_.push_back(TrimKey{});
  coords_.push_back(c);
  if constexpr (!ScalarTraits<T>::isExact) hbox_.push_back(Homog());
  for (std::size_t k = 0; k < ring_.size(); ++k) add(mid, ring_[k], ring_[(k + 1) % ring_.size()]);
}

}  // namespace detail
}  // namespace mink
