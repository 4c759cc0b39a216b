// Fuzz target: bytes -> a small LP (general, with bounds, or a Chebyshev LP of half-spaces).
// The certified, exact and (when linked) GLPK backends must agree exactly on status and optimal
// value; every optimum must be feasible and its basis must pass the exact certificate; an
// interior Chebyshev centre must be strictly inside. Aborts on any disagreement.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "lp/backend_registry.hpp"
#include "lp/certify_basis.hpp"
#include "lp/chebyshev_center.hpp"
#ifdef CMX_HAVE_GLPK
#include "lp/glpk/glpk_backend.hpp"
#endif

using namespace cmx;
using namespace cmx::lp;

namespace {

struct Bytes {
  const std::uint8_t* p;
  std::size_t n;
  std::uint8_t next() {
    if (n == 0) return 0;
    --n;
    return *p++;
  }
  bool empty() const { return n == 0; }
  // A small rational: numerator in [-128, 127] times 2^(0..3) or divided by 1..4.
  Rational number() {
    const int num = int(std::int8_t(next()));
    const std::uint8_t shape = next();
    Rational q(num);
    if (shape & 0x80) q *= Rational(1 << (shape & 3));
    else q /= Rational(1 + (shape & 3));
    return q;
  }
};

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz_lp: %s\n", what.c_str());
  std::abort();
}

std::vector<std::string> backends() {
#ifdef CMX_HAVE_GLPK
  register_glpk_backend();
#endif
  return backend_names();
}

void check_lp(const Problem& p) {
  std::optional<Solution> ref;
  for (const auto& name : backends()) {
    Solution s;
    try {
      s = solve(p, name);
    } catch (const UnsupportedProblem&) {
      continue;
    }
    if (s.status == Status::optimal) {
      if (!is_feasible(p, s.x)) fail(name + ": infeasible optimum");
      if (certify_basis(p, s.basis).verdict != Certificate::Verdict::optimal) fail(name + ": basis not optimal");
    }
    if (!ref) {
      ref = s;
    } else if (s.status != ref->status || (s.status == Status::optimal && s.value != ref->value)) {
      fail(name + " disagrees with " + ref->info.backend);
    }
  }
}

void check_chebyshev(const std::vector<HalfSpace>& h, unsigned weight_bits, Norm norm) {
  std::optional<ChebyshevResult> ref;
  for (const auto& name : backends()) {
    ChebyshevOptions o;
    o.backend = name;
    o.weight_bits = weight_bits;
    o.norm = norm;
    ChebyshevResult r;
    try {
      r = chebyshev_center(h, o);
    } catch (const UnsupportedProblem&) {
      continue;
    }
    if (r.status == ChebyshevStatus::interior && !strictly_inside(h, r.center)) fail(name + ": centre not inside");
    if (r.status == ChebyshevStatus::empty_interior && !inside(h, r.center)) fail(name + ": point not in the set");
    if (!ref) ref = r;
    else if (r.status != ref->status || r.radius != ref->radius) fail(name + ": Chebyshev disagreement");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in{data, size};
  const std::uint8_t head = in.next();
  if (head & 1) {  // Chebyshev: up to 24 half-spaces
    std::vector<HalfSpace> h;
    while (!in.empty() && h.size() < 24) h.push_back({in.number(), in.number(), in.number(), in.number()});
    check_chebyshev(h, (head & 2) ? 53 : 24, (head & 4) ? Norm::l1 : Norm::l2_upper);
    return 0;
  }
  const std::size_t n = 1 + (head >> 1) % 5;  // general LP: 1..5 variables, up to 16 rows
  Problem p(n);
  for (auto& c : p.objective) c = in.number();
  const std::uint8_t bounds = in.next();
  for (std::size_t j = 0; j < n; ++j) {
    if (bounds & (1u << j)) p.set_lower(j, in.number());
    if (bounds & (0x20u << (j % 3))) p.set_upper(j, in.number());
  }
  while (!in.empty() && p.num_rows() < 16) {
    std::vector<Rational> row(n);
    for (auto& a : row) a = in.number();
    p.add_row(row, in.number());
  }
  check_lp(p);
  return 0;
}
