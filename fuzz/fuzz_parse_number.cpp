// Fuzz target: the exact number parser never crashes; anything it accepts prints canonically,
// and the canonical text re-parses to the same value and prints identically.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "arith/rational.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  std::string why;
  const auto q = cmx::parse_rational(text, &why);
  if (!q) {
    if (why.empty()) {
      std::fprintf(stderr, "fuzz_parse_number: rejected without a reason\n");
      std::abort();
    }
    return 0;
  }
  const std::string canonical = cmx::to_string(*q);
  const auto again = cmx::parse_rational(canonical);
  if (!again || *again != *q || cmx::to_string(*again) != canonical) {
    std::fprintf(stderr, "fuzz_parse_number: '%s' does not round-trip\n", canonical.c_str());
    std::abort();
  }
  return 0;
}
