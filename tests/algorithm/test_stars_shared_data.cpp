// Stars of the Galaxy Maps pairs under ../shared/data (written by others; read in place): the
// parameter meshes' interior positions are plain 3D Tutte maps, which invert some tets (counts in
// ../shared/data/README.md). Skipped when the folder is absent.
#include <doctest/doctest.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "algorithm/local/stars.hpp"
#include "io/read_mesh.hpp"
#include "skip.hpp"
#include "topology/complex_queries.hpp"

namespace fs = std::filesystem;
using namespace cmx;
using namespace cmx::algorithm;

namespace {

struct Pair {
  topology::TetMesh mesh;
  std::vector<HPoint> target;
  std::vector<char> boundary;
};

// The object mesh (normalised orientation) with the parameter mesh's positions by vertex index.
Pair load(const std::string& name) {
  const fs::path d = cmx::test::shared_dir() / "data" / "galaxy-maps";
  const io::TetMeshData object = io::read_tet_mesh((d / (name + "_object.vtk")).string());
  io::ReadOptions keep;
  keep.orientation = io::Orientation::keep;
  const io::TetMeshData parameter = io::read_tet_mesh((d / (name + "_parameter.vtk")).string(), keep);
  REQUIRE(parameter.positions.size() == object.positions.size());
  Pair p{topology::TetMesh(object.positions.size(), object.tets), {}, {}};
  for (const auto& q : parameter.positions) p.target.emplace_back(q[0], q[1], q[2]);
  p.boundary = topology::boundary_vertex_flags(p.mesh);
  return p;
}

std::string figures(const StarSet& s, const topology::TetMesh& mesh, double seconds) {
  std::size_t largest = 0;
  for (const Star& x : s.stars) largest = std::max(largest, x.tets.size());
  return std::to_string(s.inverted + s.flat) + " defects, " + std::to_string(s.stars.size()) + " stars, largest " +
         std::to_string(largest) + " tets, mean " +
         std::to_string(s.stars.empty() ? 0.0 : double(s.tets_in_stars) / double(s.stars.size())) + ", share " +
         std::to_string(double(s.tets_in_stars) / double(mesh.num_tets())) + ", " + std::to_string(seconds) + " s";
}

}  // namespace

TEST_CASE("stars of the Galaxy Maps pairs satisfy the star conditions") {
  if (!cmx::test::have_shared("data/galaxy-maps")) return;
  const std::pair<const char*, std::size_t> pairs[] = {
      {"cub_rockerarm291", 31}, {"tlc_polycube_bird", 146}, {"tgs_100349", 347}};
  for (const auto& [name_text, inverted] : pairs) {
    const std::string name = name_text;
    CAPTURE(name);
    const Pair p = load(name);
    const auto start = std::chrono::steady_clock::now();
    const StarSet s = grow_stars(p.mesh, p.target, p.boundary);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    REQUIRE_MESSAGE(s.ok, s.message);
    CHECK(s.inverted == inverted);
    CHECK(s.flat == 0);
    CHECK(check_stars(p.mesh, p.target, s) == "");
    MESSAGE(name << ": " << figures(s, p.mesh, seconds));
  }
}

TEST_CASE("the Galaxy Maps example needs a star of more than half its tets") {
  if (!cmx::test::have_shared("data/galaxy-maps")) return;
  const Pair p = load("example");
  const StarSet refused = grow_stars(p.mesh, p.target, p.boundary);
  CHECK_FALSE(refused.ok);
  CHECK(refused.inverted == 2);
  CHECK(refused.message.find("would hold more than") != std::string::npos);
  StarOptions all;
  all.max_share = 1.0;
  const StarSet s = grow_stars(p.mesh, p.target, p.boundary, all);
  REQUIRE_MESSAGE(s.ok, s.message);
  CHECK(check_stars(p.mesh, p.target, s) == "");
  REQUIRE(s.stars.size() == 1);
  CHECK(s.stars[0].interior.size() >= 1);
}
