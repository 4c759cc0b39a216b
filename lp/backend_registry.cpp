#include "lp/backend_registry.hpp"

#include <map>

#include "lp/certified_solver.hpp"
#include "lp/exact_simplex.hpp"

namespace cmx::lp {
namespace {

Solution exact_backend(const Problem& p) { return exact_simplex(p); }

std::map<std::string, SolveFunction, std::less<>>& registry() {
  static std::map<std::string, SolveFunction, std::less<>> r{{"certified", &certified_solve},
                                                              {"exact", &exact_backend}};
  return r;
}

}  // namespace

void register_backend(std::string_view name, SolveFunction solve) { registry()[std::string(name)] = solve; }

SolveFunction find_backend(std::string_view name) {
  const auto& r = registry();
  const auto it = r.find(name);
  return it == r.end() ? nullptr : it->second;
}

std::vector<std::string> backend_names() {
  std::vector<std::string> names;
  for (const auto& [name, fn] : registry()) names.push_back(name);
  return names;
}

Solution solve(const Problem& p, std::string_view backend) {
  const SolveFunction fn = find_backend(backend);
  if (!fn) throw std::invalid_argument("lp: unknown backend '" + std::string(backend) + "'");
  return fn(p);
}

}  // namespace cmx::lp
