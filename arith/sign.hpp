#pragma once
// The result of every predicate: a sign. Shared by all number types and the kernel.
#include <optional>

namespace cmx {

enum class Sign : int { negative = -1, zero = 0, positive = 1 };

constexpr Sign operator-(Sign s) { return Sign(-int(s)); }
constexpr Sign operator*(Sign a, Sign b) { return Sign(int(a) * int(b)); }
constexpr char sign_char(Sign s) { return s == Sign::positive ? '+' : s == Sign::negative ? '-' : '0'; }

// A sign that an inexact evaluation could not decide is std::nullopt.
using UncertainSign = std::optional<Sign>;

template <class T>
constexpr Sign sign_of(const T& x) {
  return x > 0 ? Sign::positive : x < 0 ? Sign::negative : Sign::zero;
}

}  // namespace cmx
