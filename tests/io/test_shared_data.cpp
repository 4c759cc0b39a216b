// Every mesh under ../shared/data reads in its native format, with its boundary file (skipped
// when that folder is absent: the project's own tests must pass without it).
#include <doctest/doctest.h>

#include <filesystem>

#include "io/boundary.hpp"
#include "io/io_error.hpp"
#include "io/read_mesh.hpp"
#include "io/tmap.hpp"
#include "skip.hpp"

namespace fs = std::filesystem;
using namespace cmx::io;

static fs::path shared_data() { return cmx::test::shared_dir() / "data"; }

static bool have_shared_data() { return cmx::test::have_shared("data"); }

TEST_CASE("shrink-and-expand domains read with their boundary files") {
  if (!have_shared_data()) return;
  struct Case {
    const char* domain;
    const char* boundary;
    std::size_t vertices, tets, boundary_vertices;
  };
  const Case cases[] = {{"notch_domain.ovm", "notch_stiff_tet_boundary.txt", 502, 1850, 290},
                        {"prism_domain.ovm", "prism_ball_boundary.txt", 169, 619, 84},
                        {"thingi10k_83715_domain.ovm", "thingi10k_83715_tet_boundary.txt", 303, 607, 298},
                        {"thingi10k_81152_domain.ovm", "thingi10k_81152_random_star_boundary.txt", 1212, 3867, 973}};
  for (const auto& c : cases) {
    const auto dir = shared_data() / "shrink-and-expand";
    CAPTURE(c.domain);
    const auto mesh = read_tet_mesh((dir / c.domain).string());
    CHECK(mesh.positions.size() == c.vertices);
    CHECK(mesh.tets.size() == c.tets);
    CHECK_FALSE(mesh.orientation_flipped);  // documented: these files list tets positively
    const auto b = read_boundary_positions((dir / c.boundary).string(), mesh.positions.size());
    CHECK(b.vertices.size() == c.boundary_vertices);
    CHECK_NOTHROW(check_boundary_coverage(mesh, b, c.boundary));
  }
}

TEST_CASE("galaxy-maps pairs read, and boundary from the parameter mesh") {
  if (!have_shared_data()) return;
  const char* names[] = {"example", "cub_rockerarm291", "tlc_polycube_bird", "tgs_100349"};
  const std::size_t vertices[] = {7, 2328, 5650, 8895};
  const std::size_t tets[] = {10, 8682, 20203, 34879};
  for (int i = 0; i < 4; ++i) {
    CAPTURE(names[i]);
    const auto dir = shared_data() / "galaxy-maps";
    const auto object = read_tet_mesh((dir / (std::string(names[i]) + "_object.vtk")).string());
    CHECK(object.positions.size() == vertices[i]);
    CHECK(object.tets.size() == tets[i]);
    CHECK(object.orientation_flipped);  // documented: Galaxy Maps lists tets negatively
    // The parameter mesh is a folded Tutte embedding: mixed orientation by design.
    CHECK_THROWS_AS(read_tet_mesh((dir / (std::string(names[i]) + "_parameter.vtk")).string()), IoError);
    const auto b = read_boundary_positions_from_codomain(object, (dir / (std::string(names[i]) + "_parameter.vtk")).string());
    CHECK(b.vertices.size() == mesh_boundary(object).vertices.size());
    CHECK(b.vertices.size() < object.positions.size());
  }
}

TEST_CASE("public cases read in their native format with their boundary files") {
  if (!have_shared_data()) return;
  std::size_t seen = 0;
  for (const auto& entry : fs::directory_iterator(shared_data() / "public")) {
    if (!entry.is_directory()) continue;
    for (const auto& file : fs::directory_iterator(entry.path())) {
      if (file.path().stem() != "domain") continue;
      CAPTURE(file.path().string());
      TetMeshData mesh;
      REQUIRE_NOTHROW(mesh = read_tet_mesh(file.path().string()));
      CHECK(mesh.tets.size() > 0);
      const auto b = read_boundary_positions((entry.path() / "boundary.txt").string(), mesh.positions.size());
      CHECK_NOTHROW(check_boundary_coverage(mesh, b, "boundary.txt"));
      ++seen;
    }
  }
  CHECK(seen == 9);
}
