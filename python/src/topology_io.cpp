// cmx._cmx: is_ball, boundary_faces, is_expandable, expand_topologically, replay_shelling
// (cmx/topology.hpp) and
// read / write (cmx/io.hpp).
#include <string>

#include "cmx/io.hpp"
#include "cmx/topology.hpp"
#include "python/src/common.hpp"

namespace cmx::python {

namespace {

// Steps as parallel arrays PREFIX_kind (0 vertex, 1 edge split, 2 face split), PREFIX_split
// ((n, 3), -1 where unused), PREFIX_vertex and PREFIX_expanded.
void add_replay_steps(py::dict& d, const std::string& prefix, const std::vector<ReplayStep>& steps) {
  const auto n = static_cast<py::ssize_t>(steps.size());
  py::array_t<std::uint8_t> kind(n);
  py::array_t<std::int64_t> split({n, py::ssize_t{3}});
  py::array_t<std::uint32_t> vertex(n);
  py::array_t<bool> expanded(n);
  for (py::ssize_t i = 0; i < n; ++i) {
    const ReplayStep& st = steps[static_cast<std::size_t>(i)];
    kind.mutable_at(i) = static_cast<std::uint8_t>(st.kind);
    for (py::ssize_t k = 0; k < 3; ++k)
      split.mutable_at(i, k) = st.split[k] == UINT32_MAX ? -1 : std::int64_t{st.split[k]};
    vertex.mutable_at(i) = st.vertex;
    expanded.mutable_at(i) = st.expanded;
  }
  d[(prefix + "_kind").c_str()] = kind;
  d[(prefix + "_split").c_str()] = split;
  d[(prefix + "_vertex").c_str()] = vertex;
  d[(prefix + "_expanded").c_str()] = expanded;
}

void bind_topology(py::module_& m) {
  m.def(
      "is_ball",
      [](const IndexArray& tets, std::size_t vertex_count) {
        const std::vector<Tet> t = tets_of(tets, "T");
        BallCheck b;
        {
          py::gil_scoped_release release;
          b = is_ball(t, vertex_count);
        }
        return py::make_tuple(b.ok, b.message);
      },
      py::arg("T"), py::arg("vertex_count"));
  m.def(
      "boundary_faces",
      [](const IndexArray& tets, std::size_t vertex_count) {
        const std::vector<std::array<std::uint32_t, 3>> f = boundary_faces(tets_of(tets, "T"), vertex_count);
        py::array_t<std::uint32_t> out({static_cast<py::ssize_t>(f.size()), py::ssize_t{3}});
        std::uint32_t* p = out.mutable_data();
        for (std::size_t i = 0; i < f.size(); ++i)
          for (std::size_t k = 0; k < 3; ++k) p[3 * i + k] = f[i][k];
        return out;
      },
      py::arg("T"), py::arg("vertex_count"));
  m.def(
      "is_expandable",
      [](const IndexArray& tets, std::size_t vertex_count, const IndexArray& cluster, std::uint32_t vertex) {
        return is_expandable(tets_of(tets, "T"), vertex_count, indices_of(cluster, "cluster_vertices"),
                             vertex);
      },
      py::arg("T"), py::arg("vertex_count"), py::arg("cluster_vertices"), py::arg("vertex"));
  m.def(
      "expand_topologically",
      [](const IndexArray& tets, std::size_t vertex_count, const IndexArray& cluster,
         const std::string& order) {
        const std::vector<Tet> t = tets_of(tets, "T");
        const std::vector<std::uint32_t> c = indices_of(cluster, "cluster_vertices");
        TopologicalExpansion x;
        {
          py::gil_scoped_release release;
          x = expand_topologically(t, vertex_count, c, order);
        }
        py::dict d;
        d["complete"] = x.complete;
        d["sequence"] = array_of(x.sequence);
        d["remaining"] = array_of(x.remaining);
        d["initially_simply_connected"] = x.initially_simply_connected;
        return d;
      },
      py::arg("T"), py::arg("vertex_count"), py::arg("cluster_vertices"), py::arg("order"));
  m.def(
      "replay_shelling",
      [](const IndexArray& tets, std::size_t vertex_count, std::uint64_t seed, std::size_t attempts,
         std::size_t check_every) {
        const std::vector<Tet> t = tets_of(tets, "T");
        ShellingReplay x;
        {
          py::gil_scoped_release release;
          x = replay_shelling(t, vertex_count, seed, attempts, check_every);
        }
        py::dict d;
        d["shelling_found"] = x.shelling_found;
        d["attempts"] = x.attempts;
        d["best_removed"] = x.best_removed;
        d["completed"] = x.completed;
        d["expansions"] = x.expansions;
        d["input_expansions"] = x.input_expansions;
        d["chord_expansions"] = x.chord_expansions;
        d["eq1_failures"] = x.eq1_failures;
        d["left"] = x.left;
        d["boundary_splits"] = x.boundary_splits;
        d["cluster_splits"] = x.cluster_splits;
        d["free_splits"] = x.free_splits;
        d["empty_cone_edge_splits"] = x.empty_cone_edge_splits;
        d["checks"] = x.checks;
        d["check_failures"] = x.check_failures;
        d["message"] = x.message;
        add_replay_steps(d, "chord", x.chords);
        add_replay_steps(d, "step", x.steps);
        return d;
      },
      py::arg("T"), py::arg("vertex_count"), py::arg("seed"), py::arg("attempts"), py::arg("check_every"));
}

void bind_io(py::module_& m) {
  m.def(
      "read",
      [](const std::string& path) {
        Mesh mesh;
        {
          py::gil_scoped_release release;
          mesh = read(path);
        }
        py::dict d;
        d["points"] = array_of(mesh.points);
        d["points_exact"] = text_rows(mesh.points_exact);
        d["tets"] = array_of(mesh.tets);
        d["target_exact"] = text_rows(mesh.target_exact);
        d["target"] = array_of(mesh.target);
        return d;
      },
      py::arg("path"));
  m.def(
      "write",
      [](const std::string& path, const DoubleArray& points, const std::vector<ExactPoint3>& points_exact,
         const IndexArray& tets, const DoubleArray& target, const std::vector<ExactPoint3>& target_exact) {
        Mesh mesh;
        mesh.points = points_of(points, "points");
        mesh.points_exact = points_exact;
        mesh.tets = tets_of(tets, "tets");
        mesh.target = points_of(target, "target");
        mesh.target_exact = target_exact;
        py::gil_scoped_release release;
        write(path, mesh);
      },
      py::arg("path"), py::arg("points"), py::arg("points_exact"), py::arg("tets"), py::arg("target"),
      py::arg("target_exact"));
}

}  // namespace

void bind_topology_io(py::module_& m) {
  bind_topology(m);
  bind_io(m);
}

}  // namespace cmx::python
