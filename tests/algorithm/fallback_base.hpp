#pragma once
// A cluster vertex and the part of the method's state around it that the refinement steps read
// and edit, cut out of a run and kept as a file: the bases on which bends and pushes failed, kept
// as test data (tests/algorithm/fallback_bases/README.md says how they are made).
//
// The cut keeps every tet with a vertex in the closed star of v. So the stars of v and of every
// vertex of its link are whole: v's cone, Eq. (1) for v, the stars of its spokes and base edges
// (which the steps split) and of the vertices they make are exactly as in the run. Vertices
// further out are kept with their flags and positions; their own stars are cut, so nothing here
// classifies them.
//
// File format (text, one record per line, '#' lines are comments):
//   cmx-fallback-base 1
//   center X Y Z W                    p_c in homogeneous integers
//   vertex V                          the cluster vertex the steps are tried on
//   vertices N
//   B U sX sY sZ sW tX tY tZ tW       N lines: boundary and cluster flags, source, target
//   tets M
//   a b c d                           M lines, 0-based, positive in the source
#include <algorithm>
#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithm/embedding.hpp"
#include "arith/rational.hpp"
#include "kernel/homogeneous_point.hpp"

namespace cmx::test {

struct FallbackBase {
  algorithm::Embedding state;
  topology::VertexId v{0};
};

// The cut around cluster vertex v of a state with source geometry (not a combinatorial run).
inline FallbackBase cut_around(const algorithm::Embedding& e, topology::VertexId v) {
  if (e.source_free)
    throw std::invalid_argument("cut_around: a combinatorial run's state has no source to keep");
  std::vector<char> near(e.num_vertices(), 0);
  near[v] = 1;
  for (topology::TetId t : e.mesh.tets_of(v))
    for (topology::VertexId x : e.mesh.tet(t)) near[x] = 1;
  std::vector<topology::TetId> kept;
  for (topology::TetId t : e.mesh.live_tets()) {
    const topology::Tet& tet = e.mesh.tet(t);
    if (std::any_of(tet.begin(), tet.end(), [&](topology::VertexId x) { return near[x] != 0; }))
      kept.push_back(t);
  }
  std::map<std::uint32_t, std::uint32_t> renumber;  // old id -> new id, in the old order
  for (topology::TetId t : kept)
    for (topology::VertexId x : e.mesh.tet(t)) renumber.emplace(x.idx(), 0);
  FallbackBase out;
  algorithm::Embedding& s = out.state;
  std::uint32_t next = 0;
  for (auto& [old, now] : renumber) {
    now = next++;
    s.source.push_back(e.source[old]);
    s.target.push_back(e.target[old]);
    s.unexpanded.push_back(e.unexpanded[old]);
    s.boundary.push_back(e.boundary[old]);
  }
  std::vector<topology::Tet> tets;
  for (topology::TetId t : kept) {
    topology::Tet tet = e.mesh.tet(t);
    for (topology::VertexId& x : tet) x = topology::VertexId{renumber.at(x.idx())};
    tets.push_back(tet);
  }
  s.mesh = topology::TetMesh(next, tets);
  s.center = e.center;
  s.filter = e.filter;
  s.arith = e.arith;
  out.v = topology::VertexId{renumber.at(v.idx())};
  return out;
}

// Every boundary vertex where it sits: the prescribed positions of a cut (a valid state has its
// boundary vertices there).
inline std::vector<HPoint> prescribed_of(const algorithm::Embedding& e) {
  std::vector<HPoint> p(e.num_vertices());
  for (std::size_t i = 0; i < p.size(); ++i)
    if (e.boundary[i]) p[i] = e.target[i];
  return p;
}

namespace detail {
inline void write_point(std::ostream& out, const HPoint& p) {
  for (int i = 0; i < 4; ++i) out << ' ' << to_string(p.h(i));
}
inline HPoint read_point(std::istream& in) {
  std::string h[4];
  for (auto& x : h) in >> x;
  return HPoint::from_homogeneous(Integer(h[0]), Integer(h[1]), Integer(h[2]), Integer(h[3]));
}
// The next line that is not a comment or blank; throws at the end of the file.
inline std::string next_line(std::istream& in, const std::string& path) {
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') return line;
  throw std::runtime_error(path + ": ends early");
}
inline std::istringstream expect(std::istream& in, const std::string& path, const std::string& keyword) {
  std::istringstream line(next_line(in, path));
  std::string word;
  line >> word;
  if (word != keyword) throw std::runtime_error(path + ": expected '" + keyword + "', found '" + word + "'");
  return line;
}
}  // namespace detail

inline void write_fallback_base(const std::string& path, const FallbackBase& b, const std::string& comment) {
  const algorithm::Embedding& s = b.state;
  std::ofstream out(path);
  out << "cmx-fallback-base 1\n";
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) out << "# " << line << '\n';
  out << "center";
  detail::write_point(out, s.center);
  out << "\nvertex " << b.v.idx() << "\nvertices " << s.num_vertices() << '\n';
  for (std::size_t i = 0; i < s.num_vertices(); ++i) {
    out << int(s.boundary[i]) << ' ' << int(s.unexpanded[i]);
    detail::write_point(out, s.source[i]);
    detail::write_point(out, s.target[i]);
    out << '\n';
  }
  out << "tets " << s.mesh.num_tets() << '\n';
  for (topology::TetId t : s.mesh.live_tets()) {
    const topology::Tet& tet = s.mesh.tet(t);
    out << tet[0].idx() << ' ' << tet[1].idx() << ' ' << tet[2].idx() << ' ' << tet[3].idx() << '\n';
  }
  if (!out) throw std::runtime_error(path + ": could not be written");
}

inline FallbackBase read_fallback_base(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot be opened");
  if (detail::next_line(in, path) != "cmx-fallback-base 1")
    throw std::runtime_error(path + ": not a fallback base");
  FallbackBase b;
  algorithm::Embedding& s = b.state;
  {
    auto line = detail::expect(in, path, "center");
    s.center = detail::read_point(line);
  }
  std::uint32_t v = 0;
  std::size_t n = 0, m = 0;
  detail::expect(in, path, "vertex") >> v;
  detail::expect(in, path, "vertices") >> n;
  for (std::size_t i = 0; i < n; ++i) {
    std::istringstream line(detail::next_line(in, path));
    int boundary = 0, unexpanded = 0;
    line >> boundary >> unexpanded;
    s.boundary.push_back(static_cast<char>(boundary));
    s.unexpanded.push_back(static_cast<char>(unexpanded));
    s.source.push_back(detail::read_point(line));
    s.target.push_back(detail::read_point(line));
    if (!line) throw std::runtime_error(path + ": bad vertex line " + std::to_string(i));
  }
  detail::expect(in, path, "tets") >> m;
  std::vector<topology::TetIndices> tets(m);
  for (auto& t : tets) {
    std::istringstream line(detail::next_line(in, path));
    line >> t[0] >> t[1] >> t[2] >> t[3];
    if (!line || *std::max_element(t.begin(), t.end()) >= n)
      throw std::runtime_error(path + ": bad tet line");
  }
  s.mesh = topology::TetMesh(n, tets);
  if (v >= n) throw std::runtime_error(path + ": vertex out of range");
  b.v = topology::VertexId{v};
  return b;
}

}  // namespace cmx::test
