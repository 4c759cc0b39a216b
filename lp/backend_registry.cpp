#include "lp/backend_registry.hpp"

#include <map>

#include "lp/certified_solver.hpp"
#include "lp/exact_simplex.hpp"

namespace cmx::lp {
namespace {

Solution exact_backend(const Problem& p) {
  return exact_simplex(p);
}

struct Backend {
  SolveFunction solve;
  BackendCapabilities capabilities;
};

std::map<std::string, Backend, std::less<>>& registry() {
  static std::map<std::string, Backend, std::less<>> r{
      {"certified", {&certified_solve, {.certifies_float_basis = true}}}, {"exact", {&exact_backend, {}}}};
  return r;
}

const Backend* find(std::string_view name) {
  const auto& r = registry();
  const auto it = r.find(name);
  return it == r.end() ? nullptr : &it->second;
}

}  // namespace

void register_backend(std::string_view name, SolveFunction solve, BackendCapabilities capabilities) {
  registry()[std::string(name)] = {solve, capabilities};
}

SolveFunction find_backend(std::string_view name) {
  const Backend* b = find(name);
  return b ? b->solve : nullptr;
}

BackendCapabilities backend_capabilities(std::string_view name) {
  const Backend* b = find(name);
  if (!b) throw std::invalid_argument("lp: unknown backend '" + std::string(name) + "'");
  return b->capabilities;
}

std::vector<std::string> backend_names() {
  std::vector<std::string> names;
  for (const auto& [name, backend] : registry()) names.push_back(name);
  return names;
}

Solution solve(const Problem& p, std::string_view backend) {
  const SolveFunction fn = find_backend(backend);
  if (!fn) throw std::invalid_argument("lp: unknown backend '" + std::string(backend) + "'");
  return fn(p);
}

}  // namespace cmx::lp
