#include "algorithm/expansion/candidate_queue.hpp"

namespace cmx::algorithm::detail {

namespace {

std::uint64_t splitmix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

}  // namespace

CandidateQueue::CandidateQueue(Embedding& e, topology::ExpansionOrder order, std::size_t planned)
    : e_(e),
      order_(order),
      planned_(planned),
      version_(e.properties.make<std::uint32_t>(e.num_vertices(), 0)),
      is_marked_(e.properties.make<char>(e.num_vertices(), 0)) {}

void CandidateQueue::mark(VertexId v) {
  if (!is_marked_[v]) {
    is_marked_[v] = 1;
    marked_.push_back(v);
  }
}

void CandidateQueue::mark_star(VertexId v) {
  for (TetId t : e_.mesh.tets_of(v))
    for (VertexId w : e_.mesh.tet(t))
      if (e_.unexpanded[w]) mark(w);
}

std::optional<VertexId> CandidateQueue::take_marked() {
  if (marked_.empty()) return std::nullopt;
  const VertexId v = marked_.back();
  marked_.pop_back();
  is_marked_[v] = 0;
  return v;
}

void CandidateQueue::invalidate(VertexId v) { ++version_[v]; }

void CandidateQueue::push(VertexId v, Kind kind, int k, std::uint32_t expanded_neighbors) {
  queue_.push({key(kind, k, expanded_neighbors, v), version_[v], v, kind, std::uint8_t(k)});
}

std::optional<Entry> CandidateQueue::pop() {
  while (!queue_.empty()) {
    const Entry top = queue_.top();
    queue_.pop();
    if (top.version == version_[top.v] && e_.unexpanded[top.v]) return top;
  }
  return std::nullopt;
}

std::int64_t CandidateQueue::random_rank(VertexId v) const {
  return std::int64_t(splitmix(order_.seed ^ splitmix(v)) >> 1);
}

// The class comes first: refinement only when no simple expansion is left, whatever the order
// among equals (paper Sec. 4.1.2 for `priority`). A planned order comes before the class:
// the plan's next vertex is refined before any other is expanded simply, since expanding others
// first is what can leave a NOBUENOSS.
std::array<std::int64_t, 4> CandidateQueue::key(Kind kind, int k, std::uint32_t expanded_neighbors,
                                                VertexId v) const {
  std::array<std::int64_t, 4> r = order_key(kind, k, expanded_neighbors, v);
  // A deferred vertex comes after every other, refined ones included (ExpansionOrder::deferred).
  if (order_.deferred(v)) r[0] += std::int64_t{1} << 40;
  return r;
}

std::array<std::int64_t, 4> CandidateQueue::order_key(Kind kind, int k, std::uint32_t expanded_neighbors,
                                                      VertexId v) const {
  if (planned_ > 0) {
    const std::int64_t r = kind == Kind::automatic || v >= planned_ ? 0 : std::int64_t(v) + 1;
    const std::int64_t tie = order_.kind == topology::ExpansionOrderKind::random ? random_rank(v) : v;
    return {r, std::int64_t(kind), 0, tie};
  }
  switch (order_.kind) {
    case topology::ExpansionOrderKind::strict_index:  // planned: expand_cluster sets planned_
    case topology::ExpansionOrderKind::index:
      return {std::int64_t(kind), 0, 0, v};
    case topology::ExpansionOrderKind::random:
      return {std::int64_t(kind), 0, 0, random_rank(v)};
    case topology::ExpansionOrderKind::priority:
      break;
  }
  const std::int64_t kk = k == 0 ? 4 : k;
  const std::int64_t n =
      kind == Kind::simple ? -std::int64_t(expanded_neighbors) : std::int64_t(expanded_neighbors);
  return {std::int64_t(kind), kk, n, v};
}

}  // namespace cmx::algorithm::detail
