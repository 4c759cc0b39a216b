#pragma once
// Decoding of fixed-size binary numbers (legacy VTK is big-endian, VTU and Gmsh say which), and
// the exact value of binary floats.
#include <cstdint>
#include <cstring>
#include <string_view>

#include "arith/rational.hpp"

namespace cmx::io {

inline std::uint64_t load_unsigned(const char* p, int size, bool big_endian) {
  std::uint64_t v = 0;
  for (int i = 0; i < size; ++i) {
    const auto byte = std::uint64_t(static_cast<unsigned char>(p[big_endian ? i : size - 1 - i]));
    v = (v << 8) | byte;
  }
  return v;
}

inline std::int64_t load_signed(const char* p, int size, bool big_endian) {
  const std::uint64_t u = load_unsigned(p, size, big_endian);
  if (size == 8) return std::int64_t(u);
  const std::uint64_t sign = std::uint64_t(1) << (8 * size - 1);
  return (u & sign) ? std::int64_t(u) - std::int64_t(sign << 1) : std::int64_t(u);
}

inline double load_double(const char* p, bool big_endian) {
  const std::uint64_t u = load_unsigned(p, 8, big_endian);
  double d;
  std::memcpy(&d, &u, 8);
  return d;
}

inline float load_float(const char* p, bool big_endian) {
  const auto u = std::uint32_t(load_unsigned(p, 4, big_endian));
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}

}  // namespace cmx::io
