// mink/core/expansion.hpp — two number types for predicates of high degree on floating-point
// inputs: an interval (the filter) and an exact floating-point expansion (the fallback).
//
// A predicate written once as a template over its number type N is evaluated first with
// N = Interval: every operation rounds its bounds outward, so the result encloses the
// exact value, and a result interval that excludes 0 gives the exact sign at a few times
// the cost of plain double. Only when it contains 0 is the same template evaluated with
// N = Expansion: a sum of non-overlapping doubles equal to the value (J. R. Shewchuk,
// "Adaptive precision floating-point arithmetic and fast robust geometric predicates",
// DCG 18, 1997: Fast-Expansion-Sum, Scale-Expansion), whose largest component
// carries its sign. Exact while no product underflows or overflows: for the degrees used
// in mink (up to 9) that is inputs between about 2^-100 and 2^100 in magnitude (or 0).
// An expansion keeps up to kExpansionInline components in the object itself (on the
// stack for a local) and moves to the heap only beyond: the products of degree up to 9
// that mink evaluates rarely need more, so the expansion stage does not allocate either.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace mink {
namespace detail {

/// Components held inline by an expansion before it moves them to the heap.
inline constexpr std::size_t kExpansionInline = 64;

/// A vector of F with room for N elements in the object itself; beyond N the elements
/// move to a heap buffer, which is then kept (clear() keeps the capacity). Only what the
/// expansions below use: no constructors or destructors of elements (F is a float type).
template <class F, std::size_t N>
class SmallBuffer {
 public:
  SmallBuffer() = default;
  SmallBuffer(const SmallBuffer& o) { assign(o); }
  SmallBuffer(SmallBuffer&& o) noexcept { take(o); }
  SmallBuffer& operator=(const SmallBuffer& o) {
    if (this != &o) assign(o);
    return *this;
  }
  SmallBuffer& operator=(SmallBuffer&& o) noexcept {
    if (this != &o) take(o);
    return *this;
  }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  F* begin() { return data(); }
  F* end() { return data() + size_; }
  const F* begin() const { return data(); }
  const F* end() const { return data() + size_; }
  F& operator[](std::size_t i) { return data()[i]; }
  const F& operator[](std::size_t i) const { return data()[i]; }
  const F& back() const { return data()[size_ - 1]; }

  void clear() { size_ = 0; }
  void reserve(std::size_t n) {
    if (n > capacity()) grow(n);
  }
  void push_back(F x) {
    if (size_ == capacity()) grow(size_ + 1);
    data()[size_++] = x;
  }
  /// Shrinks to n elements, or grows with zeros.
  void resize(std::size_t n) {
    reserve(n);
    for (std::size_t i = size_; i < n; ++i) data()[i] = F(0);
    size_ = n;
  }
  void swap(SmallBuffer& o) noexcept {
    SmallBuffer t(std::move(o));
    o = std::move(*this);
    *this = std::move(t);
  }

 private:
  F* data() { return heap_.empty() ? inline_ : heap_.data(); }
  const F* data() const { return heap_.empty() ? inline_ : heap_.data(); }
  std::size_t capacity() const { return heap_.empty() ? N : heap_.size(); }
  void grow(std::size_t n) {
    std::vector<F> h(std::max(n, 2 * capacity()));
    std::copy(begin(), end(), h.begin());
    heap_.swap(h);
  }
  void assign(const SmallBuffer& o) {
    size_ = 0;
    reserve(o.size_);
    std::copy(o.begin(), o.end(), data());
    size_ = o.size_;
  }
  void take(SmallBuffer& o) {
    if (o.heap_.empty()) {
      size_ = 0;
      reserve(o.size_);
      std::copy(o.begin(), o.end(), data());
    } else {
      heap_ = std::move(o.heap_);
      o.heap_.clear();
    }
    size_ = o.size_;
    o.size_ = 0;
  }

  F inline_[N];
  std::vector<F> heap_;  // empty: the elements are inline_
  std::size_t size_ = 0;
};

/// A closed interval [lo, hi] of F (double or long double) enclosing a real value;
/// arithmetic rounds outward.
template <class F>
class IntervalOf {
  using Interval = IntervalOf;

 public:
  IntervalOf() = default;
  IntervalOf(F x) : lo_(x), hi_(x) {}  // NOLINT: an exact number is a point interval
  IntervalOf(F lo, F hi) : lo_(lo), hi_(hi) {}
  F lo() const { return lo_; }
  F hi() const { return hi_; }
  /// +1 / −1 when the interval excludes 0 (the sign of every value in it), 0 otherwise.
  int certainSign() const { return lo_ > F(0) ? 1 : (hi_ < F(0) ? -1 : 0); }
  bool excludesZero() const { return lo_ > F(0) || hi_ < F(0); }
  F mid() const { return F(0.5) * lo_ + F(0.5) * hi_; }

  friend Interval operator+(const Interval& a, const Interval& b) {
    return {sumDown(a.lo_, b.lo_), sumUp(a.hi_, b.hi_)};
  }
  friend Interval operator-(const Interval& a, const Interval& b) {
    return {sumDown(a.lo_, -b.hi_), sumUp(a.hi_, -b.lo_)};
  }
  friend Interval operator-(const Interval& a) { return {-a.hi_, -a.lo_}; }
  friend Interval operator*(const Interval& a, const Interval& b) {
    // By the signs of the bounds: the two products that are the extremes, lo = lx · ly and
    // hi = hx · hy (four only when both intervals hold 0 inside). The same rounded products
    // as the min and max of all four; a NaN bound (or 0 times an infinite one) gives the
    // whole line.
    F lx, ly, hx, hy;
    if (a.lo_ >= F(0)) {
      if (b.lo_ >= F(0))
        lx = a.lo_, ly = b.lo_, hx = a.hi_, hy = b.hi_;
      else if (b.hi_ <= F(0))
        lx = a.hi_, ly = b.lo_, hx = a.lo_, hy = b.hi_;
      else
        lx = a.hi_, ly = b.lo_, hx = a.hi_, hy = b.hi_;
    } else if (a.hi_ <= F(0)) {
      if (b.lo_ >= F(0))
        lx = a.lo_, ly = b.hi_, hx = a.hi_, hy = b.lo_;
      else if (b.hi_ <= F(0))
        lx = a.hi_, ly = b.hi_, hx = a.lo_, hy = b.lo_;
      else
        lx = a.lo_, ly = b.hi_, hx = a.lo_, hy = b.lo_;
    } else if (b.lo_ >= F(0)) {
      lx = a.lo_, ly = b.hi_, hx = a.hi_, hy = b.hi_;
    } else if (b.hi_ <= F(0)) {
      lx = a.hi_, ly = b.lo_, hx = a.lo_, hy = b.lo_;
    } else {  // both hold 0 inside: no bound is 0
      const F l1 = a.lo_ * b.hi_, l2 = a.hi_ * b.lo_, h1 = a.lo_ * b.lo_, h2 = a.hi_ * b.hi_;
      if (std::isnan(l1) || std::isnan(l2) || std::isnan(h1) || std::isnan(h2))
        return {-std::numeric_limits<F>::infinity(), std::numeric_limits<F>::infinity()};
      return {down(l1 < l2 ? l1 : l2), up(h1 > h2 ? h1 : h2)};
    }
    const F lo = lx * ly, hi = hx * hy;
    if (std::isnan(lo) || std::isnan(hi)) return {-std::numeric_limits<F>::infinity(), std::numeric_limits<F>::infinity()};
    // A zero factor makes an exact zero (its partner is finite: the product is not NaN).
    return {lo == F(0) && (lx == F(0) || ly == F(0)) ? lo : down(lo), hi == F(0) && (hx == F(0) || hy == F(0)) ? hi : up(hi)};
  }
  /// Enclosure of a / b; the whole line when b contains 0.
  friend Interval operator/(const Interval& a, const Interval& b) {
    if (!b.excludesZero()) return {-std::numeric_limits<F>::infinity(), std::numeric_limits<F>::infinity()};
    const F q[4] = {a.lo_ / b.lo_, a.lo_ / b.hi_, a.hi_ / b.lo_, a.hi_ / b.hi_};
    F lo = q[0], hi = q[0];
    for (F x : q) {
      if (std::isnan(x)) return {-std::numeric_limits<F>::infinity(), std::numeric_limits<F>::infinity()};
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    return {down(lo), up(hi)};
  }
  Interval& operator+=(const Interval& b) { return *this = *this + b; }
  Interval& operator-=(const Interval& b) { return *this = *this - b; }

 private:
  // The bounds of a sum x + y, outward; exact when it is an exact zero (y = −x; NaN for
  // infinities of both signs, as before). Exact zeros stay exact, here and in products
  // with a zero factor: widened to ±(the least normal number), a zero became a bound
  // whose products with numbers below 1 are denormal, each a microcode assist on x86 (a
  // few hundred cycles for double, more for the x87's long double). Meshes with
  // coordinates 0 or equal along an axis (axis-aligned boxes, the CPD scenes' axes) made
  // such bounds in most planes, and the trimming's long double stage ran at ~0.5 µs per
  // product. The test y = −x rather than a zero result: with flush-to-zero on, a sum with
  // a denormal value comes out 0 without being exact.
  static F sumDown(F x, F y) {
    const F s = x + y;
    return s == F(0) && x == -y ? s : down(s);
  }
  static F sumUp(F x, F y) {
    const F s = x + y;
    return s == F(0) && x == -y ? s : up(s);
  }
  // Outward by at least one ulp: the exact result is within half an ulp of the rounded x
  // (or half the least subnormal below the normal range), and x − (|x|·2^(1−p) + the
  // least normal number) rounds to at most x − ulp(x) / 2 (the product is exact, a
  // power-of-two scaling). The least normal rather than the least subnormal: as sound,
  // and no denormal sum, which costs a microcode assist on x86. A result rounded to ±∞
  // may be finite: its inner bound is ±max; its outer bound stays infinite.
  static F down(F x) {
    if (!(std::abs(x) <= kMax)) return x == std::numeric_limits<F>::infinity() ? kMax : x;
    return x - (std::abs(x) * kEps + kTiny);
  }
  static F up(F x) {
    if (!(std::abs(x) <= kMax)) return x == -std::numeric_limits<F>::infinity() ? -kMax : x;
    return x + (std::abs(x) * kEps + kTiny);
  }
  // Constants of F made at compile time: under -frounding-math (which CGAL asks of its
  // users) GCC would otherwise convert the limits' long double literals at run time on
  // the x87 unit (for denorm_min a denormal result: about a microsecond per operation).
  static constexpr F kMax = std::numeric_limits<F>::max();
  static constexpr F kEps = std::numeric_limits<F>::epsilon();
  static constexpr F kTiny = std::numeric_limits<F>::min();
  F lo_ = F(0), hi_ = F(0);
};
using Interval = IntervalOf<double>;

/// An interval as its rounded midpoint m and a radius r with r·(1 + 3·eps) >= the distance
/// of any of its values from m: half the rounded width, plus eps·|m| for the midpoint's
/// rounding, plus 4·(least normal number) for underflow, flushed to zero or not (for
/// dotSignByRadius).
template <class F>
void toMidRadius(const IntervalOf<F>& x, F& m, F& r) {
  m = F(0.5) * x.lo() + F(0.5) * x.hi();
  r = (x.hi() - x.lo()) * F(0.5) + std::numeric_limits<F>::epsilon() * std::abs(m) + F(4) * std::numeric_limits<F>::min();
}

/// The sign of Σ a_i · b_i (i < n) for every a_i within ra_i of ma_i and b_i within rb_i
/// of mb_i (toMidRadius), or 0 when this bound cannot tell: a cheaper first filter in
/// front of interval arithmetic for narrow intervals, without branches (the interval
/// product picks its bounds by their signs, and mispredicts where they vary). The value
/// is Σ ma mb within Σ |ma| rb + ra (|mb| + rb), the rounded sum within (n + 1)·eps·
/// Σ |ma mb| of that; both bounds are enlarged by a relative (4n + 16)·eps and an
/// absolute (4n + 8)·(least normal) for their own rounding and underflow. An exact zero
/// is never certified (the bound is > 0); an infinite or NaN input gives 0.
template <class F>
int dotSignByRadius(const F* ma, const F* ra, const F* mb, const F* rb, int n) {
  constexpr F kEps = std::numeric_limits<F>::epsilon(), kTiny = std::numeric_limits<F>::min();
  F v = F(0), s = F(0), e = F(0);
  for (int i = 0; i < n; ++i) {
    const F p = ma[i] * mb[i];
    v += p;
    s += std::abs(p);
    e += std::abs(ma[i]) * rb[i] + ra[i] * (std::abs(mb[i]) + rb[i]);
  }
  const F bound = (e + F(n + 1) * kEps * s) * (F(1) + F(4 * n + 16) * kEps) + F(4 * n + 8) * kTiny;
  return v > bound ? 1 : (v < -bound ? -1 : 0);
}

/// dotSignByRadius of intervals (n <= 4).
template <class F>
int dotSignByRadius(const IntervalOf<F>* a, const IntervalOf<F>* b, int n) {
  F ma[4], ra[4], mb[4], rb[4];
  for (int i = 0; i < n; ++i) toMidRadius(a[i], ma[i], ra[i]), toMidRadius(b[i], mb[i], rb[i]);
  return dotSignByRadius(ma, ra, mb, rb, n);
}

/// An exact sum of non-overlapping numbers of F (double or long double; increasing
/// magnitude, no zeros).
template <class F>
class ExpansionOf {
  using Expansion = ExpansionOf;
  using Components = SmallBuffer<F, kExpansionInline>;

 public:
  ExpansionOf() = default;
  ExpansionOf(F x) {  // NOLINT: every number of F is an expansion
    if (x != F(0)) c_.push_back(x);
  }
  int sign() const { return c_.empty() ? 0 : (c_.back() > F(0) ? 1 : -1); }
  /// The value rounded (about 1 ulp).
  F approx() const {
    F s = F(0);
    for (F x : c_) s += x;
    return s;
  }

  /// The value in an exact type Q constructible from F (a rational): the expansion is
  /// compressed first (Shewchuk's Compress: the same value in few components, usually
  /// two or three), so that only a few additions run in Q.
  template <class Q>
  Q exactValue() const {
    const Components h = compressed();
    Q value(0);
    for (F x : h) value += Q(x);
    return value;
  }

  friend Expansion operator+(const Expansion& a, const Expansion& b) {
    Expansion r;
    sum(a.c_, b.c_, r.c_);
    return r;
  }
  friend Expansion operator-(const Expansion& a) {
    Expansion r = a;
    for (F& x : r.c_) x = -x;
    return r;
  }
  friend Expansion operator-(const Expansion& a, const Expansion& b) { return a + (-b); }
  friend Expansion operator*(const Expansion& x0, const Expansion& y0) {
    // One scaled copy of the longer factor per component of the shorter, summed.
    const bool swap = x0.c_.size() < y0.c_.size();
    const Expansion& a = swap ? y0 : x0;
    const Expansion& b = swap ? x0 : y0;
    Expansion r, s;
    Components t;
    for (F x : b.c_) {
      a.scaled(x, s);
      sum(r.c_, s.c_, t);
      r.c_.swap(t);
    }
    if (r.c_.size() > 4) r.c_ = r.compressed();
    return r;
  }
  Expansion& operator+=(const Expansion& b) { return *this = *this + b; }
  Expansion& operator-=(const Expansion& b) { return *this = *this - b; }

 private:
  static void twoSum(F a, F b, F& x, F& y) {
    x = a + b;
    const F bv = x - a, av = x - bv;
    y = (a - av) + (b - bv);
  }
  static void twoProduct(F a, F b, F& x, F& y) {
    x = a * b;
    y = std::fma(a, b, -x);
  }
  static void fastTwoSum(F a, F b, F& x, F& y) {  // |a| >= |b|
    x = a + b;
    y = b - (x - a);
  }
  // h := e + f exactly (Fast-Expansion-Sum with zero elimination: the two sequences merged
  // by magnitude, then one pass; linear, where growing e by each term of f is quadratic).
  // Valid for the strongly non-overlapping expansions every operation here keeps (IEEE
  // round-to-nearest-even).
  static void sum(const Components& e, const Components& f, Components& h) {
    h.clear();
    if (e.empty() || f.empty()) {
      h = e.empty() ? f : e;
      return;
    }
    h.reserve(e.size() + f.size());
    std::size_t i = 0, j = 0;
    auto next = [&]() {
      if (j == f.size() || (i < e.size() && std::abs(e[i]) < std::abs(f[j]))) return e[i++];
      return f[j++];
    };
    F q = next(), x, y;
    fastTwoSum(next(), q, x, y);
    q = x;
    if (y != F(0)) h.push_back(y);
    while (i < e.size() || j < f.size()) {
      twoSum(q, next(), x, y);
      q = x;
      if (y != F(0)) h.push_back(y);
    }
    if (q != F(0)) h.push_back(q);
  }
  // The same value with non-adjacent components: a pass from the largest down folds each
  // component into a running sum, keeping what that sum cannot hold; a pass back up
  // renormalises what was kept.
  Components compressed() const {
    Components g(c_);
    if (g.size() < 2) return g;
    std::size_t bottom = g.size() - 1;
    F big = g[bottom], sum1, low;
    for (std::size_t i = g.size() - 1; i-- > 0;) {
      fastTwoSum(big, g[i], sum1, low);
      if (low != F(0)) {
        g[bottom--] = sum1;
        big = low;
      } else {
        big = sum1;
      }
    }
    std::size_t top = 0;
    for (std::size_t i = bottom + 1; i < g.size(); ++i) {
      fastTwoSum(g[i], big, sum1, low);
      if (low != F(0)) g[top++] = low;
      big = sum1;
    }
    g[top++] = big;
    g.resize(top);
    return g;
  }
  // r := this * b exactly (Scale-Expansion, zeros eliminated).
  void scaled(F b, Expansion& r) const {
    r.c_.clear();
    if (c_.empty() || b == F(0)) return;
    F q, h;
    twoProduct(c_[0], b, q, h);
    if (h != F(0)) r.c_.push_back(h);
    for (std::size_t i = 1; i < c_.size(); ++i) {
      F t1, t0, s, e;
      twoProduct(c_[i], b, t1, t0);
      twoSum(q, t0, s, e);
      if (e != F(0)) r.c_.push_back(e);
      twoSum(t1, s, q, e);
      if (e != F(0)) r.c_.push_back(e);
    }
    if (q != F(0)) r.c_.push_back(q);
  }
  Components c_;
};
using Expansion = ExpansionOf<double>;

}  // namespace detail
}  // namespace mink
