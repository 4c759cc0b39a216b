#pragma once
// The option names of an enumeration (--snap, --precision, ...): one table that both parses and
// prints, so the two directions cannot disagree.
#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <utility>

namespace cmx::algorithm {

template <class E, std::size_t N>
struct OptionNames {
  std::array<std::pair<E, std::string_view>, N> entries;

  // The value called `name`, or nullopt.
  constexpr std::optional<E> parse(std::string_view name) const {
    for (const auto& [value, value_name] : entries)
      if (value_name == name) return value;
    return std::nullopt;
  }
  // The name of `value`; "?" for a value outside the table.
  constexpr std::string_view name(E value) const {
    for (const auto& [v, value_name] : entries)
      if (v == value) return value_name;
    return "?";
  }
};

}  // namespace cmx::algorithm
