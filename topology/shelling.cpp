#include "topology/shelling.hpp"

#include <algorithm>
#include <queue>
#include <random>
#include <tuple>

#include "topology/complex_queries.hpp"
#include "topology/indexed_tasks.hpp"
#include "topology/mesh_edits.hpp"
#include "topology/shelling_counts.hpp"
#include "topology/shelling_rule.hpp"

namespace cmx::topology {
namespace {

// Face i of remaining tet t is shared iff the tet across it (input adjacency) is remaining.
// Splits done by shelling_to_expansion_sequence only touch removed tets and the current cell,
// so the input adjacency stays right for the faces of remaining tets.
bool face_shared(const TetAdjacency& adj, TetId t, int i, const std::vector<char>& remaining) {
  const TetId n = adj.neighbor[t][i];
  return n != invalid_index && n < remaining.size() && remaining[n];
}

bool on_boundary_of_remaining(const TetMesh& m, const TetAdjacency& adj, const std::vector<char>& remaining,
                              VertexId a, VertexId b /* invalid_vertex for a vertex */) {
  for (TetId o : m.tets_of(a)) {
    if (o >= remaining.size() || !remaining[o]) continue;
    const Tet& x = m.tet(o);
    if (b != invalid_index && !contains(x, b)) continue;
    for (int k = 0; k < 4; ++k)
      if (x[k] != a && x[k] != b && !face_shared(adj, o, k, remaining)) return true;
  }
  return false;
}

std::size_t others_containing(const TetMesh& m, TetId t, const std::vector<char>& remaining, VertexId a,
                              VertexId b /* invalid_vertex for a vertex */) {
  std::size_t n = 0;
  for (TetId o : m.tets_of(a)) {
    if (o == t || o >= remaining.size() || !remaining[o]) continue;
    if (b == invalid_index || contains(m.tet(o), b)) ++n;
  }
  return n;
}

std::array<bool, 4> shared_faces(const TetAdjacency& adj, TetId t, const std::vector<char>& remaining) {
  std::array<bool, 4> s{};
  for (int i = 0; i < 4; ++i) s[i] = face_shared(adj, t, i, remaining);
  return s;
}

}  // namespace

bool is_shelling_removable(const TetMesh& m, const TetAdjacency& adj, TetId t, const std::vector<char>& remaining,
                           std::size_t remaining_count) {
  if (!m.is_alive(t) || t >= remaining.size() || !remaining[t]) return false;
  if (remaining_count == 1) return true;
  const Tet& x = m.tet(t);
  const auto second = [&](int l) { return l < 0 ? invalid_vertex : x[l]; };
  return detail::shelling_rule(
      shared_faces(adj, t, remaining),
      [&](int k, int l) { return on_boundary_of_remaining(m, adj, remaining, x[k], second(l)); },
      [&](int k, int l) { return others_containing(m, t, remaining, x[k], second(l)) > 0; });
}

namespace {

// The cost of the step Alg. 2 makes of removing t now (ShellingOptions::interior).
int step_cost(const TetMesh& m, const TetAdjacency& adj, const ShellingCounts& state, TetId t,
              const std::vector<char>& interior) {
  const Tet& x = m.tet(t);
  int shared = 0;
  bool all_interior = true;
  for (int i = 0; i < 4; ++i) {
    const TetId n = adj.neighbor[t][i];
    if (n == invalid_index || !state.remaining(n)) continue;
    ++shared;
    all_interior = all_interior && interior[x[i]];  // the simplex: the vertices opposite shared faces
  }
  if (shared == 0 || !all_interior) return 0;
  return shared;
}

// One greedy attempt from `state` (every tet remaining): the removal order it reached.
std::vector<TetId> greedy_attempt(const TetMesh& m, const TetAdjacency& adj, const std::vector<TetId>& live,
                                  std::uint64_t seed, ShellingCounts& state,
                                  const std::vector<char>* interior) {
  std::mt19937_64 rng(seed);
  std::vector<std::uint64_t> key(m.tet_capacity(), 0);
  for (TetId t : live) key[t] = rng();
  std::vector<char> queued(m.tet_capacity(), 0);
  std::vector<int> queued_cost(m.tet_capacity(), 0);
  const auto cost = [&](TetId t) { return interior ? step_cost(m, adj, state, t, *interior) : 0; };
  using Item = std::tuple<int, std::uint64_t, TetId>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  // A tet is queued once per cost: a copy pushed again with the same cost would carry the same
  // key and be popped right after the first, with nothing removed in between. A queued tet whose
  // cost fell is queued again; an entry whose cost is no longer the tet's is dropped when popped.
  const auto push = [&](TetId t) {
    if (!state.removable(t)) return;
    const int c = cost(t);
    if (queued[t] && c >= queued_cost[t]) return;
    queued[t] = 1;
    queued_cost[t] = c;
    queue.push({c, key[t], t});
  };
  for (TetId t : live) push(t);
  std::vector<TetId> order;
  order.reserve(live.size());
  while (!queue.empty() && state.remaining_count() > 0) {
    const auto [c, k, t] = queue.top();
    queue.pop();
    if (!queued[t] || c != queued_cost[t]) continue;
    queued[t] = 0;
    if (!state.removable(t)) continue;
    if (const int now = cost(t); now != c) {  // dearer since it was queued
      push(t);
      continue;
    }
    state.remove(t);
    order.push_back(t);
    // Removability can change only for tets sharing a vertex with t.
    for (VertexId v : m.tet(t))
      for (TetId o : m.tets_of(v)) push(o);
  }
  return order;
}

}  // namespace

ShellingResult find_shelling(const TetMesh& m, const ShellingOptions& options) {
  ShellingResult r;
  const std::vector<TetId> live = m.live_tets();
  const TetAdjacency adj = tet_adjacency(m);
  const ShellingCounts fresh(m, adj);
  const std::size_t attempts = std::max<std::size_t>(options.max_attempts, 1);
  const std::size_t threads = thread_count(options.threads, attempts);
  // Attempts run in batches of `threads`, each on a copy of the fresh counts; their results are
  // taken in attempt order, so the outcome is the one-thread outcome whatever the count.
  for (std::size_t first = 0; first < attempts; first += threads) {
    if (first > 0 && options.should_stop && options.should_stop()) {
      r.stopped_at_deadline = true;
      break;
    }
    const std::size_t n = std::min(threads, attempts - first);
    std::vector<std::vector<TetId>> orders(n);
    // An attempt that shells is the last one looked at below: none after it need run.
    run_indexed(n, n, [&](std::size_t i) {
      ShellingCounts state = fresh;
      orders[i] = greedy_attempt(m, adj, live, options.seed + 0x9e3779b97f4a7c15ull * (first + i), state,
                                 options.interior);
      return orders[i].size() == live.size();
    });
    for (std::size_t i = 0; i < n; ++i) {
      ++r.attempts;
      r.best_removed = std::max(r.best_removed, orders[i].size());
      if (orders[i].size() == live.size()) {
        r.found = true;
        r.order = std::move(orders[i]);
        r.message = "shelling found";
        return r;
      }
    }
  }
  r.message = "no shelling found within " + std::to_string(r.attempts) + " greedy attempts (best removed " +
              std::to_string(r.best_removed) + " of " + std::to_string(live.size()) + " tets)" +
              (r.stopped_at_deadline ? ", cut short by the deadline" : "");
  return r;
}

ShellingExpansion shelling_to_expansion_sequence(const TetMesh& input, const std::vector<TetId>& shelling) {
  ShellingExpansion out;
  out.mesh = input;
  TetMesh& m = out.mesh;
  std::vector<char> remaining(m.tet_capacity(), 0);
  for (TetId t : shelling) {
    if (!m.is_alive(t) || remaining[t]) {
      out.message = "shelling lists a dead or repeated tet " + std::to_string(t);
      return out;
    }
    remaining[t] = 1;
  }
  if (shelling.size() != m.num_tets()) {
    out.message = "shelling does not list every tet";
    return out;
  }
  std::size_t count = shelling.size();
  const TetAdjacency adj = tet_adjacency(input);
  for (std::size_t s = 0; s + 1 < shelling.size(); ++s) {
    const TetId t = shelling[s];
    // Splits only touch tets around the split simplex, which (by the removability rule) are t
    // and already removed tets: t keeps its handle and vertices until it is processed.
    if (!is_shelling_removable(m, adj, t, remaining, count)) {
      out.message = "step " + std::to_string(s) + ": tet " + std::to_string(t) + " is not removable";
      return out;
    }
    const Tet x = m.tet(t);
    const std::array<bool, 4> sh = shared_faces(adj, t, remaining);
    const int j = static_cast<int>(std::count(sh.begin(), sh.end(), true));
    ExpansionStep step;
    step.cell = t;
    if (j == 1) {
      for (int i = 0; i < 4; ++i)
        if (sh[i]) step.vertex = x[i];
    } else if (j == 2) {
      VertexId e[2];
      int n = 0;
      for (int i = 0; i < 4; ++i)
        if (sh[i]) e[n++] = x[i];
      const SplitResult sr = split_edge(m, e[0], e[1]);
      step.kind = ExpansionStepKind::edge_split;
      step.split = {e[0], e[1], invalid_vertex};
      step.vertex = sr.new_vertex;
    } else {
      int free_face = 0;
      for (int i = 0; i < 4; ++i)
        if (!sh[i]) free_face = i;
      const Triangle f = tet_face(x, free_face);
      const SplitResult sr = split_face(m, f[0], f[1], f[2]);
      step.kind = ExpansionStepKind::face_split;
      step.split = f;
      step.vertex = sr.new_vertex;
    }
    // Tets created by the split are parts of t or of removed tets: never "remaining".
    remaining.resize(m.tet_capacity(), 0);
    remaining[t] = 0;
    --count;
    out.steps.push_back(step);
  }
  // The last cell: expand three of its vertices; the fourth follows automatically.
  const Tet last = m.tet(shelling.back());
  for (int i = 0; i < 4; ++i) {
    ExpansionStep step;
    step.cell = shelling.back();
    step.vertex = last[i];
    step.automatic = i == 3;
    out.steps.push_back(step);
  }
  out.ok = true;
  out.message = "ok";
  return out;
}

}  // namespace cmx::topology
