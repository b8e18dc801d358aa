// fuzz/fuzz_decoder.hpp — the byte decoder both libFuzzer targets read their inputs with
// (mdd_fuzz.cpp, mesh_fuzz.cpp): every read past the end yields 0, so any input decodes
// to something. Changing it changes what every saved corpus unit and regression means.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>

namespace mink_fuzz {

class Decoder {
 public:
  Decoder(const std::uint8_t* d, std::size_t n) : d_(d), n_(n) {}
  std::uint8_t u8() { return i_ < n_ ? d_[i_++] : 0; }
  std::int8_t i8() { return static_cast<std::int8_t>(u8()); }
  std::int16_t i16() {
    const std::uint16_t lo = u8(), hi = u8();
    return static_cast<std::int16_t>(lo | (hi << 8));
  }
  double f64() {
    std::uint64_t bits = 0;
    for (int k = 0; k < 8; ++k) bits |= static_cast<std::uint64_t>(u8()) << (8 * k);
    double x;
    std::memcpy(&x, &bits, sizeof x);
    return x;
  }
  double special() {
    static const double table[] = {0.0,
                                   1.0,
                                   -1.0,
                                   0.5,
                                   3.0,
                                   1e-9,
                                   1.0 + std::numeric_limits<double>::epsilon(),
                                   std::numeric_limits<double>::denorm_min(),
                                   std::numeric_limits<double>::min(),
                                   1e-300,
                                   1e300,
                                   -1e300,
                                   std::numeric_limits<double>::max(),
                                   std::numeric_limits<double>::quiet_NaN(),
                                   std::numeric_limits<double>::infinity(),
                                   -std::numeric_limits<double>::infinity()};
    return table[u8() % 16];
  }

 private:
  const std::uint8_t* d_;
  std::size_t n_;
  std::size_t i_ = 0;
};

}  // namespace mink_fuzz
