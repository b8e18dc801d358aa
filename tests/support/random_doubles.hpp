// tests/support/random_doubles.hpp — doubles drawn over the whole range, for the tests of
// number types (intervals, expansions, double-doubles) against exact rationals.
#pragma once

#include <cmath>
#include <limits>
#include <random>

namespace mink_test {

/// Zeros, denormals, tiny, unit-order and huge numbers of both signs.
inline double anyDouble(std::mt19937& rng) {
  std::uniform_int_distribution<int> kind(0, 5), exponent(-1074, 1023);
  std::uniform_real_distribution<double> mant(0.5, 1.0);
  const double sign = rng() & 1 ? 1.0 : -1.0;
  switch (kind(rng)) {
    case 0:
      return 0.0;
    case 1:
      return sign * std::numeric_limits<double>::denorm_min() * double(1 + rng() % 1000);
    case 2:
      return sign * std::ldexp(mant(rng), exponent(rng));
    default:
      return sign * std::ldexp(mant(rng), static_cast<int>(rng() % 40) - 20);
  }
}

}  // namespace mink_test
