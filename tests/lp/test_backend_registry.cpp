// The backend registry: names, capabilities and what happens with an unknown name.
#include <doctest/doctest.h>

#include <algorithm>
#include <stdexcept>

#include "lp/backend_registry.hpp"
#include "lp/exact_simplex.hpp"

namespace {

using namespace cmx::lp;

Solution exact_under_another_name(const Problem& p) {
  return exact_simplex(p);
}

bool listed(std::string_view name) {
  const auto names = backend_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

TEST_CASE("only the certified built-in backend certifies a float basis") {
  CHECK(backend_capabilities("certified").certifies_float_basis);
  CHECK_FALSE(backend_capabilities("exact").certifies_float_basis);
  CHECK(backend_capabilities(default_backend).certifies_float_basis);
  CHECK_THROWS_AS(backend_capabilities("no-such-backend"), std::invalid_argument);
  CHECK((find_backend("no-such-backend") == nullptr));
}

TEST_CASE("a registered backend is found with the capabilities it declared") {
  CHECK_FALSE(listed("test-exact-alias"));
  register_backend("test-exact-alias", &exact_under_another_name);
  CHECK(listed("test-exact-alias"));
  CHECK((find_backend("test-exact-alias") == &exact_under_another_name));
  CHECK_FALSE(backend_capabilities("test-exact-alias").certifies_float_basis);

  register_backend("test-exact-alias", &exact_under_another_name, {.certifies_float_basis = true});
  CHECK(backend_capabilities("test-exact-alias").certifies_float_basis);
}
