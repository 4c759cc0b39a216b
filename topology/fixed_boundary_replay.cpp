#include "topology/fixed_boundary_replay.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "topology/chords.hpp"
#include "topology/cluster_links.hpp"
#include "topology/complex_queries.hpp"
#include "topology/mesh_edits.hpp"

namespace cmx::topology {
namespace {

// A face is on the boundary when one tet has it; an edge when one of its faces is.
bool on_mesh_boundary(const TetMesh& m, const std::array<VertexId, 3>& s, int n) {
  return n == 3 ? tets_around_face(m, s[0], s[1], s[2]).size() == 1 : edge_on_boundary(m, s[0], s[1]);
}

// Split vertex m of cluster edge (x, y): does a tet (m, ., s, t) with s, t expanded exist?
bool faces_mirrored_pair(const TetMesh& m, VertexId mid, const std::vector<char>& unexpanded) {
  for (TetId t : m.tets_of(mid)) {
    std::size_t expanded = 0;
    for (VertexId w : m.tet(t))
      if (!unexpanded[w]) ++expanded;
    if (expanded == 2) return true;
  }
  return false;
}

// The fallback's one-sentence verdict, once the search (and the replay, when it ran) is done.
std::string fallback_message(const ShellingFallback& f) {
  const std::string tets = std::to_string(f.tets) + " tets";
  const std::string chords = std::to_string(f.chords.size()) + " chord splits";
  if (!f.shelling_found)
    return "no shelling found in " + std::to_string(f.attempts) + " greedy attempts (at most " +
           std::to_string(f.best_removed) + " of " + tets + " peeled" +
           (f.chords.empty() ? "" : ", after " + chords) + (f.stopped_at_deadline ? ", cut short" : "") +
           "): the input may not be shellable";
  const std::string found =
      "a shelling of the " + tets + (f.chords.empty() ? "" : " (after " + chords + ")") + " found in " +
      std::to_string(f.attempts) + (f.attempts == 1 ? " greedy attempt" : " greedy attempts");
  if (f.replay.ok)
    return found +
           "; Alg. 2 replayed from the start with the boundary in place expands every interior vertex (" +
           std::to_string(f.replay.expansions) + " expansions, " + std::to_string(f.replay.cluster_splits) +
           " of them split vertices)";
  return found + ", but its replay failed: " +
         (f.replay.first_failure.empty() ? std::to_string(f.replay.left) + " cluster vertices left"
                                         : f.replay.first_failure);
}

}  // namespace

FixedBoundaryReplay replay_with_fixed_boundary(const TetMesh& input, const ShellingExpansion& sequence,
                                               std::size_t check_every, const ReplayStop& stop_when,
                                               const std::vector<char>* start) {
  FixedBoundaryReplay r;
  TetMesh m = input;
  std::vector<char> unexpanded(m.num_vertices());
  if (start) {
    for (std::size_t v = 0; v < unexpanded.size() && v < start->size(); ++v)
      unexpanded[v] = (*start)[v] ? 1 : 0;
  } else {
    const std::vector<char> boundary = boundary_vertex_flags(m);
    for (std::size_t v = 0; v < unexpanded.size(); ++v) unexpanded[v] = boundary[v] ? 0 : 1;
  }
  std::size_t cluster_left = static_cast<std::size_t>(std::count(unexpanded.begin(), unexpanded.end(), 1));
  ClusterLinkWorkspace ws;
  r.step_expanded.assign(sequence.steps.size(), 0);
  const auto check = [&](const TetMesh& now, const std::string& when) {
    ++r.checks;
    const SubcomplexCounts c = cluster_mesh_counts(now, unexpanded);
    if (c.vertices == 0 || (c.components == 1 && c.euler == 1)) return;
    if (r.check_failures++ == 0 && r.first_failure.empty())
      r.first_failure = when + ": the cluster mesh is not simply connected (" + std::to_string(c.components) +
                        " components, Euler characteristic " + std::to_string(c.euler) + ")";
  };
  if (check_every > 0) check(m, "before the first step");
  for (std::size_t i = 0; i < sequence.steps.size(); ++i) {
    const ExpansionStep& st = sequence.steps[i];
    bool edge_of_cluster = false;
    if (st.kind != ExpansionStepKind::plain_vertex) {
      const int n = st.kind == ExpansionStepKind::edge_split ? 2 : 3;
      bool all_cluster = true, any_cluster = false;
      for (int a = 0; a < n; ++a) {
        all_cluster = all_cluster && unexpanded[st.split[a]];
        any_cluster = any_cluster || unexpanded[st.split[a]];
      }
      const bool on_boundary = on_mesh_boundary(m, st.split, n);
      const SplitResult s = n == 2 ? split_edge(m, st.split[0], st.split[1])
                                   : split_face(m, st.split[0], st.split[1], st.split[2]);
      if (!s.ok || s.new_vertex != st.vertex) {
        r.first_failure = "step " + std::to_string(i) + ": the split does not match the sequence";
        return r;
      }
      unexpanded.resize(m.num_vertices(), 0);
      if (on_boundary)
        ++r.boundary_splits;
      else if (!any_cluster)
        ++r.free_splits;
      else {
        ++r.cluster_splits;
        unexpanded[st.vertex] = 1;
        ++cluster_left;
        edge_of_cluster = n == 2 && all_cluster;
      }
    }
    if (!unexpanded[st.vertex]) continue;
    ++r.expansions;
    r.step_expanded[i] = 1;
    if (st.vertex < input.num_vertices()) ++r.input_expansions;
    if (edge_of_cluster && faces_mirrored_pair(m, st.vertex, unexpanded)) ++r.empty_cone_edge_splits;
    // The last cluster vertex goes automatically (its Lk• is empty), as in topological_expansion.
    // That is not always the paper's last step: boundary vertices of the last cells may follow.
    if (cluster_left > 1 && !is_topologically_expandable(m, st.vertex, unexpanded, ws)) {
      if (r.eq1_failures++ == 0 && r.first_failure.empty())
        r.first_failure =
            "step " + std::to_string(i) + ": vertex " + std::to_string(st.vertex) + " fails Eq. (1)";
    }
    unexpanded[st.vertex] = 0;
    --cluster_left;
    if (check_every > 0 && r.expansions % check_every == 0) check(m, "after step " + std::to_string(i));
    if (stop_when && stop_when(m, unexpanded)) {
      r.stopped = true;
      r.left = static_cast<std::size_t>(std::count(unexpanded.begin(), unexpanded.end(), 1));
      return r;
    }
  }
  if (check_every > 0 && r.expansions % check_every != 0) check(m, "after the last step");
  r.left = static_cast<std::size_t>(std::count(unexpanded.begin(), unexpanded.end(), 1));
  r.ok = r.eq1_failures == 0 && r.check_failures == 0 && r.left == 0;
  return r;
}

ShellingFallback shelling_fallback(TetMesh input, const ShellingOptions& options, std::size_t check_every) {
  ShellingFallback f;
  const std::size_t input_vertices = input.num_vertices();  // the chord vertices come next
  std::vector<char> boundary = boundary_vertex_flags(input);
  std::vector<char> interior = interior_vertex_flags(input);
  ChordContext context{input, boundary, interior, [&](VertexId a, VertexId b, VertexId c) {
                         const SplitResult r =
                             c == invalid_index ? split_edge(input, a, b) : split_face(input, a, b, c);
                         boundary.push_back(0);
                         interior.push_back(1);
                         f.chords.push_back({{a, b, c}, r.new_vertex});
                         return r.new_vertex;
                       }};
  split_all_chords(context);
  const ShellingResult shelling = find_shelling(input, options);
  f.shelling_found = shelling.found;
  f.attempts = shelling.attempts;
  f.best_removed = shelling.best_removed;
  f.stopped_at_deadline = shelling.stopped_at_deadline;
  f.tets = input.num_tets();
  if (!shelling.found) {
    f.message = fallback_message(f);
    return f;
  }
  const ShellingExpansion sequence = shelling_to_expansion_sequence(input, shelling.order);
  if (!sequence.ok) {
    f.message = "a shelling of the " + std::to_string(f.tets) +
                " tets was found, but Alg. 2 could not convert it: " + sequence.message;
    return f;
  }
  f.replayed = true;
  f.replay = replay_with_fixed_boundary(input, sequence, check_every);
  f.steps = sequence.steps;
  // The replay counts the chord vertices as vertices of the mesh it replays; report them apart.
  const std::size_t first_chord = input_vertices, past_chords = first_chord + f.chords.size();
  for (std::size_t i = 0; i < f.steps.size(); ++i)
    if (f.replay.step_expanded[i] && f.steps[i].vertex >= first_chord && f.steps[i].vertex < past_chords)
      ++f.chord_expansions;
  f.replay.input_expansions -= f.chord_expansions;
  f.message = fallback_message(f);
  return f;
}

}  // namespace cmx::topology
