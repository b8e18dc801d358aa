// tests/support/to_rational.hpp — the exact value of every scalar mink runs on (float,
// double, long double, CGAL::Gmpq) as a CGAL::Gmpq, for exact references.
#pragma once

#include <CGAL/Gmpq.h>

#include <Eigen/Core>

#include <stdexcept>

namespace mink_test {

using Rational = CGAL::Gmpq;

inline Rational toQ(const Rational& x) { return x; }
inline Rational toQ(double x) { return Rational(x); }
inline Rational toQ(float x) { return Rational(static_cast<double>(x)); }
/// A long double is a sum of at most a few doubles; they are peeled off exactly.
inline Rational toQ(long double x) {
  Rational sum(0);
  long double rest = x;
  for (int i = 0; i < 4 && rest != 0.0L; ++i) {
    const double hi = static_cast<double>(rest);
    sum += Rational(hi);
    rest -= static_cast<long double>(hi);
  }
  if (rest != 0.0L) throw std::logic_error("toQ: long double not converted exactly");
  return sum;
}

template <class T>
Eigen::Matrix<Rational, 3, 1> toQ3(const Eigen::Matrix<T, 3, 1>& p) {
  return Eigen::Matrix<Rational, 3, 1>(toQ(p[0]), toQ(p[1]), toQ(p[2]));
}

}  // namespace mink_test
