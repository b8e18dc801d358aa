// mink/cpd/detail/trim_corners.hpp — Trimmer<T> (cpd/detail/trimming.hpp, which includes
// this file at its end; include that one): the corners of the pieces — named by how they
// are made, computed once from their names — and the exact side of a corner with respect to
// a line of a facet's plane (interval filter, then expansions on the named inputs).
#pragma once

namespace mink {
namespace detail {

template <class T>
int Trimmer<T>::addCorner(const TrimKey& key, const Vec3<T>& x) {
  if constexpr (!ScalarTraits<T>::isExact) {
    Homog h;
    if (!key.isPoint()) enclose(key, h);
    return addCorner(key, x, h);
  } else {
    return addCorner(key, x, Homog());
  }
}

template <class T>
int Trimmer<T>::crossing(int F, std::uint64_t side, std::uint64_t cut, int ia, int ib) {
  const bool es = TrimLabel::isEdge(side), ec = TrimLabel::isEdge(cut);
  if (es && ec) {
    const int a = TrimLabel::edgeFirst(side), b = TrimLabel::edgeSecond(side);
    const int c = TrimLabel::edgeFirst(cut), d = TrimLabel::edgeSecond(cut);
    if (a == c || a == d) return pointCorner(a);
    if (b == c || b == d) return pointCorner(b);
    const int axis = soup_[static_cast<std::size_t>(F)].axis;
    if (orient2d(mCoord_[c], mCoord_[d], mCoord_[a], axis) == 0) return pointCorner(a);
    if (orient2d(mCoord_[c], mCoord_[d], mCoord_[b], axis) == 0) return pointCorner(b);
    if (orient2d(mCoord_[a], mCoord_[b], mCoord_[c], axis) == 0) return pointCorner(c);
    if (orient2d(mCoord_[a], mCoord_[b], mCoord_[d], axis) == 0) return pointCorner(d);
    return cornerOn(keyOf(side, cut), F, cut, ia, ib);
  }
  if (es || ec) {
    const std::uint64_t e = es ? side : cut, o = es ? cut : side;
    for (const int end : {TrimLabel::edgeFirst(e), TrimLabel::edgeSecond(e)})
      if (onPlaneLike(mCoord_[static_cast<std::size_t>(end)], o)) return pointCorner(end);
    return cornerOn(keyOf(side, cut), F, cut, ia, ib);
  }
  // Two polygons' planes that share an edge lying in both meet along it: the corner is
  // that edge's crossing with F's plane (one name for the point).
  if (TrimLabel::isPlane(side) && TrimLabel::isPlane(cut)) {
    const Soup& g = soup_[static_cast<std::size_t>(TrimLabel::index(side))];
    const Soup& h = soup_[static_cast<std::size_t>(TrimLabel::index(cut))];
    int shared[2], count = 0;
    for (int i = 0; i < g.nc; ++i)
      for (int j = 0; j < h.nc; ++j)
        if (g.m[i] == h.m[j] && count < 2) shared[count++] = g.m[i];
    // (A parallelogram's plane is that of its first three corners; its other sides may
    // be off it by rounding, and then the point is not on it.)
    if (count == 2 && pointSide(g, shared[0]) == 0 && pointSide(g, shared[1]) == 0 && pointSide(h, shared[0]) == 0 &&
        pointSide(h, shared[1]) == 0) {
      const std::uint64_t e = TrimLabel::edge(shared[0], shared[1]);
      for (const int end : {shared[0], shared[1]})
        if (onPlaneLike(mCoord_[static_cast<std::size_t>(end)], TrimLabel::plane(F))) return pointCorner(end);
      return cornerOn(keyOf(e, TrimLabel::plane(F)), F, cut, ia, ib);
    }
  }
  return cornerOn(keyOf(TrimLabel::plane(F), side, cut), F, cut, ia, ib);
}

template <class T>
int Trimmer<T>::cornerOn(const TrimKey& key, int F, std::uint64_t cut, int ia, int ib) {
  const auto it = keyIndex_.find(key);
  if (it != keyIndex_.end()) return it->second;
  if constexpr (ScalarTraits<T>::isExact) {
    return addCorner(key, compute(key));
  } else {
    // The enclosure of the exact corner: its midpoint where it is tight; else (nearly
    // parallel planes) the exact X / W in expansion arithmetic, rounded once each.
    (void)F;
    (void)cut;
    Homog h;
    enclose(key, h);
    const Vec3<T>&a = coords_[static_cast<std::size_t>(ia)], &b = coords_[static_cast<std::size_t>(ib)];
    const T scale = T((b - a).cwiseAbs().maxCoeff());
    Vec3<T> x;
    bool tight = h.boxed;
    for (int k = 0; k < 3 && tight; ++k) {
      x[k] = T(h.x[k].mid());
      tight = T(h.x[k].hi() - h.x[k].lo()) <= std::ldexp(T(1), -40) * (absValue(x[k]) + scale);
    }
    CornerOf<IVL> wide;  // made here: kept for the corner's exact predicates
    if (!tight && std::numeric_limits<long double>::digits > std::numeric_limits<FloatOf>::digits) {
      IVL* X = wide.X;
      IVL& W = wide.W;
      homogeneous<IVL>(key, X, W);
      wide.ready = true;
      tight = W.excludesZero();
      for (int k = 0; k < 3 && tight; ++k) {
        const IVL q = X[k] / W;
        x[k] = T(q.mid());
        tight = std::isfinite(static_cast<double>(q.lo())) && std::isfinite(static_cast<double>(q.hi())) &&
                T(q.hi() - q.lo()) <= std::ldexp(T(1), -40) * (absValue(x[k]) + scale);
      }
    }
    if (!tight) {
      EX X[3], W;
      homogeneous<EX>(key, X, W);
      const FloatOf w = W.approx();
      for (int k = 0; k < 3; ++k) x[k] = w != FloatOf(0) ? T(X[k].approx() / w) : T((a[k] + b[k]) / T(2));
    }
    const int id = addCorner(key, x, h);
    if (wide.ready) {
      if (cornerL_.size() < keys_.size()) cornerL_.resize(keys_.size());
      cornerL_[static_cast<std::size_t>(id)] = wide;
    }
    return id;
  }
}

template <class T>
auto Trimmer<T>::planeOf(std::uint64_t x) const -> PlaneEq {
  if (TrimLabel::isPlane(x)) {
    const Soup& s = soup_[static_cast<std::size_t>(TrimLabel::index(x))];
    return {s.n, s.k};
  }
  const int b = TrimLabel::index(x), axis = b / 2;
  Vec3<T> n = Vec3<T>::Zero();
  n[axis] = T(1);
  return {n, (b % 2) ? region_.hi[axis] : region_.lo[axis]};
}

template <class T>
Vec3<T> Trimmer<T>::compute(const TrimKey& key) const {
  if (key.isPoint()) return mCoord_[static_cast<std::size_t>(key.k[0])];
  if (key.isPair()) {
    // Sorted: an edge label is the larger; the other is a plane, a box face or an edge.
    const std::uint64_t e = key.k[1], o = key.k[0];
    const Vec3<T>& p = mCoord_[static_cast<std::size_t>(TrimLabel::edgeFirst(e))];
    const Vec3<T>& q = mCoord_[static_cast<std::size_t>(TrimLabel::edgeSecond(e))];
    if (TrimLabel::isEdge(o)) {
      const Vec3<T>& r = mCoord_[static_cast<std::size_t>(TrimLabel::edgeFirst(o))];
      const Vec3<T>& s = mCoord_[static_cast<std::size_t>(TrimLabel::edgeSecond(o))];
      const Vec3<T> d1 = q - p, d2 = s - r, c = d1.cross(d2);
      const T den = c.squaredNorm();
      if (den == T(0)) return p;
      return p + (((r - p).cross(d2)).dot(c) / den) * d1;
    }
    const PlaneEq pl = planeOf(o);
    const T dp = pl.n.dot(p) - pl.k, dq = pl.n.dot(q) - pl.k;
    if (dp == dq) return p;
    Vec3<T> x = p + (dp / (dp - dq)) * (q - p);
    if (TrimLabel::isBox(o)) x[TrimLabel::index(o) / 2] = pl.k;  // exactly on the face
    return x;
  }
  // Three planes (box faces among them): Cramer's rule.
  const PlaneEq a = planeOf(key.k[0]), b = planeOf(key.k[1]), c = planeOf(key.k[2]);
  const Vec3<T> bc = b.n.cross(c.n), ca = c.n.cross(a.n), ab = a.n.cross(b.n);
  const T det = a.n.dot(bc);
  if (det == T(0)) return mCoord_[0];
  Vec3<T> x = (a.k * bc + b.k * ca + c.k * ab) / det;
  for (const std::uint64_t l : key.k)
    if (TrimLabel::isBox(l)) x[TrimLabel::index(l) / 2] = planeOf(l).k;
  return x;
}

template <class T>
int Trimmer<T>::side(int F, int id, std::uint64_t cut) const {
  const TrimKey& key = keys_[static_cast<std::size_t>(id)];
  if (key.contains(cut)) return 0;
  // Floating T, a constructed corner: the interval filter first (it can only certify a
  // non-zero side, so it never contradicts the test by names below).
  if constexpr (!ScalarTraits<T>::isExact) {
    if (!key.isPoint()) {
      const int filtered = filteredSide(F, id, cut);
      if (filtered != 0) return filtered;
    }
  }
  // A corner made on a line of F's plane that is the cut's line is on the cut: decided
  // from the inputs that name the lines (exactly), not from the rounded corner.
  if (!key.isPoint())
    for (const std::uint64_t l : key.k)
      if (l != TrimLabel::kNone && l != TrimLabel::plane(F) && sameLineCached(F, l, cut)) return 0;
  if constexpr (!ScalarTraits<T>::isExact) {
    if (!key.isPoint()) return exactSide(F, id, cut);
  }
  const Vec3<T>& x = coords_[static_cast<std::size_t>(id)];
  if (TrimLabel::isPlane(cut)) {
    const Soup& g = soup_[static_cast<std::size_t>(TrimLabel::index(cut))];
    if (key.isPoint()) return pointSide(g, static_cast<int>(key.k[0]));
    return orient3d(mCoord_[g.m[0]], mCoord_[g.m[1]], mCoord_[g.m[2]], x);
  }
  if (TrimLabel::isBox(cut)) {
    const int b = TrimLabel::index(cut), axis = b / 2;
    if (b % 2) return detail::sign(T(x[axis] - region_.hi[axis]));
    return detail::sign(T(region_.lo[axis] - x[axis]));
  }
  const Soup& f = soup_[static_cast<std::size_t>(F)];
  const int u = TrimLabel::edgeFirst(cut), v = TrimLabel::edgeSecond(cut);
  return f.axisSign * orient2d(mCoord_[u], mCoord_[v], x, f.axis);
}

template <class T>
bool Trimmer<T>::sameLineCached(int F, std::uint64_t l, std::uint64_t cut) const {
  // F matters only to two edge lines (compared in F's projection).
  const bool edges = TrimLabel::isEdge(l) && TrimLabel::isEdge(cut);
  const TrimKey key{{std::min(l, cut), std::max(l, cut), edges ? static_cast<std::uint64_t>(F) : TrimLabel::kNone}};
  const auto it = sameLine_.find(key);
  if (it != sameLine_.end()) return it->second != 0;
  const bool same = sameLine(F, l, cut);
  sameLine_.emplace(key, same ? 1 : 0);
  return same;
}

template <class T>
bool Trimmer<T>::sameLine(int F, std::uint64_t l, std::uint64_t cut) const {
  if (TrimLabel::isEdge(l)) {
    const Vec3<T>& a = mCoord_[static_cast<std::size_t>(TrimLabel::edgeFirst(l))];
    const Vec3<T>& b = mCoord_[static_cast<std::size_t>(TrimLabel::edgeSecond(l))];
    if (TrimLabel::isEdge(cut)) {
      const int axis = soup_[static_cast<std::size_t>(F)].axis;
      const Vec3<T>& u = mCoord_[static_cast<std::size_t>(TrimLabel::edgeFirst(cut))];
      const Vec3<T>& v = mCoord_[static_cast<std::size_t>(TrimLabel::edgeSecond(cut))];
      return orient2d(u, v, a, axis) == 0 && orient2d(u, v, b, axis) == 0;
    }
    return onPlaneLike(a, cut) && onPlaneLike(b, cut);
  }
  if (TrimLabel::isEdge(cut)) return sameLine(F, cut, l);
  // Two planes (or box faces): the same plane.
  if (TrimLabel::isPlane(l)) {
    const Soup& h = soup_[static_cast<std::size_t>(TrimLabel::index(l))];
    for (int c = 0; c < 3; ++c)
      if (!onPlaneLike(mCoord_[h.m[c]], cut)) return false;
    return true;
  }
  if (TrimLabel::isPlane(cut)) return sameLine(F, cut, l);
  return false;  // two different box faces
}

template <class T>
template <class N>
void Trimmer<T>::planeN(std::uint64_t l, N n[3], N& k) const {
  if (TrimLabel::isPlane(l)) {
    const Soup& g = soup_[static_cast<std::size_t>(TrimLabel::index(l))];
    N p0[3], p1[3], p2[3], u[3], v[3];
    point(g.m[0], p0);
    point(g.m[1], p1);
    point(g.m[2], p2);
    for (int a = 0; a < 3; ++a) u[a] = p1[a] - p0[a], v[a] = p2[a] - p0[a];
    cross(u, v, n);
    k = dot(n, p0);
    return;
  }
  const int b = TrimLabel::index(l), axis = b / 2;
  for (int a = 0; a < 3; ++a) n[a] = N(FloatOf(a == axis ? 1 : 0));
  k = N(static_cast<FloatOf>((b % 2) ? region_.hi[axis] : region_.lo[axis]));
}

template <class T>
template <class N>
void Trimmer<T>::homogeneous(const TrimKey& key, N X[3], N& W) const {
  if (key.isPoint()) {
    point(static_cast<int>(key.k[0]), X);
    W = N(FloatOf(1));
    return;
  }
  if (key.isPair()) {
    const std::uint64_t e = key.k[1], o = key.k[0];
    N p[3], q[3], d[3];
    point(TrimLabel::edgeFirst(e), p);
    point(TrimLabel::edgeSecond(e), q);
    for (int a = 0; a < 3; ++a) d[a] = q[a] - p[a];
    if (TrimLabel::isEdge(o)) {
      N r[3], t[3], d2[3], c[3], rp[3], m[3];
      point(TrimLabel::edgeFirst(o), r);
      point(TrimLabel::edgeSecond(o), t);
      for (int a = 0; a < 3; ++a) d2[a] = t[a] - r[a], rp[a] = r[a] - p[a];
      cross(d, d2, c);
      cross(rp, d2, m);
      W = dot(c, c);
      const N s = dot(m, c);
      for (int a = 0; a < 3; ++a) X[a] = p[a] * W + s * d[a];
      return;
    }
    N bn[3], bk;
    const N *n, *k;
    planeCached(o, n, k, bn, bk);
    W = dot(n, d);
    const N s = *k - dot(n, p);
    for (int a = 0; a < 3; ++a) X[a] = p[a] * W + s * d[a];
    return;
  }
  N b1[3], b2[3], b3[3], bk1, bk2, bk3, c23[3], c31[3], c12[3];
  const N *n1, *n2, *n3, *k1, *k2, *k3;
  planeCached(key.k[0], n1, k1, b1, bk1);
  planeCached(key.k[1], n2, k2, b2, bk2);
  planeCached(key.k[2], n3, k3, b3, bk3);
  cross(n2, n3, c23);
  cross(n3, n1, c31);
  cross(n1, n2, c12);
  W = dot(n1, c23);
  for (int a = 0; a < 3; ++a) X[a] = *k1 * c23[a] + *k2 * c31[a] + *k3 * c12[a];
}

template <class T>
template <class N>
void Trimmer<T>::planeCached(std::uint64_t l, const N*& n, const N*& k, N boxN[3], N& boxK) const {
  if constexpr (!ScalarTraits<T>::isExact) {
    if (TrimLabel::isPlane(l)) {
      std::vector<PlaneCacheOf<N>>& cache = planeCacheFor<N>();
      if (cache.size() < soup_.size()) cache.resize(soup_.size());  // soup_ is complete: no later growth
      PlaneCacheOf<N>& c = cache[static_cast<std::size_t>(TrimLabel::index(l))];
      if (!c.ready) {
        planeN<N>(l, c.n, c.k);
        c.ready = true;
      }
      n = c.n;
      k = &c.k;
      return;
    }
  }
  planeN<N>(l, boxN, boxK);
  n = boxN;
  k = &boxK;
}

template <class T>
void Trimmer<T>::planeIV(std::uint64_t l, const IV*& n, const IV*& k, const FloatOf** mr) const {
  PlaneIVCache* c;
  if (TrimLabel::isPlane(l)) {
    IV unusedN[3], unusedK;
    planeCached<IV>(l, n, k, unusedN, unusedK);
    c = &planeCache_[static_cast<std::size_t>(TrimLabel::index(l))];
  } else {
    c = &boxCache_[TrimLabel::index(l)];
    if (!c->ready) {
      planeN<IV>(l, c->n, c->k);
      c->ready = true;
      c->mr[4] = FloatOf(0);
    }
    n = c->n;
    k = &c->k;
  }
  if (mr == nullptr) return;
  if (c->mr[4] == FloatOf(0)) {  // a radius is > 0 once made
    for (int a = 0; a < 3; ++a) toMidRadius(c->n[a], c->mr[a], c->mr[a + 4]);
    toMidRadius(c->k, c->mr[3], c->mr[7]);
  }
  *mr = c->mr;
}

template <class T>
template <class N>
N Trimmer<T>::cutValue(int F, std::uint64_t cut, const N X[3], const N& W) const {
  if constexpr (std::is_same<N, IV>::value) {
    if (!TrimLabel::isEdge(cut)) {
      const IV* n;
      const IV* k;
      planeIV(cut, n, k);
      const IV val = dot(n, X) - *k * W;
      if (TrimLabel::isBox(cut) && TrimLabel::index(cut) % 2 == 0) return -val;
      return val;
    }
  }
  if (TrimLabel::isEdge(cut)) {
    const Soup& f = soup_[static_cast<std::size_t>(F)];
    N u[3], v[3], d[3], r[3];
    point(TrimLabel::edgeFirst(cut), u);
    point(TrimLabel::edgeSecond(cut), v);
    for (int a = 0; a < 3; ++a) d[a] = v[a] - u[a], r[a] = X[a] - u[a] * W;
    const int i = (f.axis + 1) % 3, j = (f.axis + 2) % 3;
    const N c = d[i] * r[j] - d[j] * r[i];
    return f.axisSign > 0 ? c : N(-c);
  }
  N bn[3], bk;
  const N *n, *k;
  planeCached(cut, n, k, bn, bk);
  const N val = dot(n, X) - *k * W;
  if (TrimLabel::isBox(cut) && TrimLabel::index(cut) % 2 == 0) return -val;  // outside: below the lower face
  return val;
}

template <class T>
int Trimmer<T>::filteredSide(int F, int id, std::uint64_t cut) const {
  const Homog& h = hbox_[static_cast<std::size_t>(id)];
  if (h.boxed && !TrimLabel::isEdge(cut)) {
    // A plane or box face: n · x − k by midpoints and radii first (dotSignByRadius).
    const IV *n, *k;
    const FloatOf* mr;
    planeIV(cut, n, k, &mr);
    const int sv = dotSignByRadius(mr, mr + 4, h.mr, h.mr + 4, 4);
    if (sv != 0) return TrimLabel::isBox(cut) && TrimLabel::index(cut) % 2 == 0 ? -sv : sv;
  } else if (h.boxed) {
    // An edge line u v: d_i r_j − d_j r_i (cutValue) with d = v − u, r = x − u, the same way.
    const Soup& f = soup_[static_cast<std::size_t>(F)];
    const Vec3<T>&u = mCoord_[static_cast<std::size_t>(TrimLabel::edgeFirst(cut))],
                  &v = mCoord_[static_cast<std::size_t>(TrimLabel::edgeSecond(cut))];
    const int i = (f.axis + 1) % 3, j = (f.axis + 2) % 3;
    constexpr FloatOf kEps = std::numeric_limits<FloatOf>::epsilon(), kTiny = FloatOf(4) * std::numeric_limits<FloatOf>::min();
    FloatOf a[4], b[4];  // midpoints a[0..1], b[0..1]; radii a[2..3], b[2..3]
    a[0] = FloatOf(v[i]) - FloatOf(u[i]), a[1] = FloatOf(u[j]) - FloatOf(v[j]);
    b[0] = h.mr[j] - FloatOf(u[j]), b[1] = h.mr[i] - FloatOf(u[i]);
    for (int c = 0; c < 2; ++c) a[c + 2] = kEps * std::abs(a[c]) + kTiny;
    b[2] = h.mr[j + 4] + kEps * std::abs(b[0]) + kTiny, b[3] = h.mr[i + 4] + kEps * std::abs(b[1]) + kTiny;
    const int sv = dotSignByRadius(a, a + 2, b, b + 2, 2);
    if (sv != 0) return f.axisSign > 0 ? sv : -sv;
  }
  if (h.boxed) {
    const IV one(FloatOf(1));
    const int sv = cutValue<IV>(F, cut, h.x, one).certainSign();
    if (sv != 0) return sv;
  }
  const int sw = h.W.certainSign();
  if (sw != 0) {
    const int sv = cutValue<IV>(F, cut, h.X, h.W).certainSign();
    if (sv != 0) return sv * sw;
  }
  return 0;
}

template <class T>
template <class Value>
int Trimmer<T>::namedSign(int id, const Value& value) const {
  const TrimKey& key = keys_[static_cast<std::size_t>(id)];
  // Second filters: the corner recomputed from its name in wider intervals. The corners
  // that reach here mostly sit at a vertex of M within the double filter's width of the
  // cut but not on it (an edge-edge facet's fourth point is off its plane by a rounding of
  // the inputs, about 2^-53 of the value's terms). Double-double intervals (about 106
  // bits, core/double_double.hpp) settle them at a small fraction of the expansions' cost
  // (README, "The double-double stage"). Long double intervals, where long double is
  // wider (x87: 11 more bits and a far wider exponent), then settle most of what is left:
  // products below double's range (a subnormal mesh beside a unit one), where the
  // double-double's absolute error bound and the expansions' underflow tell nothing.
  auto wider = [&](auto& c, auto tag) {
    using N = decltype(tag);
    if (!c.ready) {
      homogeneous<N>(key, c.X, c.W);
      c.ready = true;
    }
    const int sw = c.W.certainSign();
    if (sw == 0) return 0;
    return value(c.X, c.W).certainSign() * sw;
  };
  if constexpr (std::is_same<FloatOf, double>::value && kDoubleDoubleExact) {
    if (cornerD_.size() < keys_.size()) cornerD_.resize(keys_.size());
    if (const int sv = wider(cornerD_[static_cast<std::size_t>(id)], IVD())) return sv;
  }
  if constexpr (std::numeric_limits<long double>::digits > std::numeric_limits<FloatOf>::digits) {
    if (cornerL_.size() < keys_.size()) cornerL_.resize(keys_.size());
    if (const int sv = wider(cornerL_[static_cast<std::size_t>(id)], IVL())) return sv;
  }
  if (cornerXIndex_.size() < keys_.size()) cornerXIndex_.resize(keys_.size(), -1);
  int& slot = cornerXIndex_[static_cast<std::size_t>(id)];
  if (slot < 0) {
    if (cornerXCount_ == cornerX_.size()) cornerX_.emplace_back();
    slot = static_cast<int>(cornerXCount_++);
    CornerX& c = cornerX_[static_cast<std::size_t>(slot)];
    homogeneous<EX>(key, c.X, c.W);
  }
  const CornerX& c = cornerX_[static_cast<std::size_t>(slot)];
  return value(c.X, c.W).sign() * c.W.sign();
}

template <class T>
int Trimmer<T>::exactSide(int F, int id, std::uint64_t cut) const {
  // Once per corner and cut (F matters only for an edge line's orientation).
  const TrimKey cached{{static_cast<std::uint64_t>(id), cut, TrimLabel::isEdge(cut) ? static_cast<std::uint64_t>(F) : TrimLabel::kNone}};
  const auto it = exactSide_.find(cached);
  if (it != exactSide_.end()) return it->second;
  const int sv = namedSign(id, [&](const auto* X, const auto& W) {
    using N = std::decay_t<decltype(W)>;
    return cutValue<N>(F, cut, X, W);
  });
  exactSide_.emplace(cached, sv);
  return sv;
}

template <class T>
int Trimmer<T>::dotSign(int id, int p, int q) const {
  const TrimKey& key = keys_[static_cast<std::size_t>(id)];
  if constexpr (!ScalarTraits<T>::isExact) {
    // (X − p·W) · (q − p), whose sign times sign(W) is the answer (W = 1 for a point).
    auto value = [&](const auto* X, const auto& W) {
      using N = std::decay_t<decltype(W)>;
      N pp[3], qq[3];
      point(p, pp);
      point(q, qq);
      N v = N(FloatOf(0));
      for (int a = 0; a < 3; ++a) v += (X[a] - pp[a] * W) * (qq[a] - pp[a]);
      return v;
    };
    if (!key.isPoint()) {
      const Homog& h = hbox_[static_cast<std::size_t>(id)];
      const int sw = h.W.certainSign();
      if (sw != 0) {
        const int sv = value(h.X, h.W).certainSign();
        if (sv != 0) return sv * sw;
      }
    }
    return namedSign(id, value);
  } else {
    const Vec3<T>& x = coords_[static_cast<std::size_t>(id)];
    return detail::sign(T((x - mCoord_[static_cast<std::size_t>(p)]).dot(mCoord_[static_cast<std::size_t>(q)] - mCoord_[static_cast<std::size_t>(p)])));
  }
}

}  // namespace detail
}  // namespace mink
