// The examples under ../shared/data (written by others; read in place, never copied) map and
// verify, and P10 is refused as not star-shaped. Skipped when the folder is absent. Under the
// sanitizers only the cases below 10,000 tets run (10x slower there); the polycube bird, which
// takes minutes, runs only with CMX_LONG_TESTS=1 (its figures are in bench/RESULTS.md).
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "algorithm/map.hpp"
#include "io/boundary.hpp"
#include "io/read_mesh.hpp"
#include "skip.hpp"

namespace fs = std::filesystem;
using namespace cmx;
using namespace cmx::algorithm;

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr std::size_t max_tets = 10000;
#else
constexpr std::size_t max_tets = 100000;
#endif

fs::path data() { return cmx::test::shared_dir() / "data"; }

bool have_data() { return cmx::test::have_shared("data"); }

MapProblem load(const fs::path& domain, const fs::path& boundary, bool codomain) {
  io::TetMeshData mesh = io::read_tet_mesh(domain.string());
  const io::BoundaryPositions b = codomain ? io::read_boundary_positions_from_codomain(mesh, boundary.string())
                                           : io::read_boundary_positions(boundary.string(), mesh.positions.size());
  MapProblem p;
  p.tets = topology::make_tets(mesh.tets);
  p.source = mesh.positions;
  p.boundary_vertices = b.vertices;
  p.boundary_positions = b.positions;
  return p;
}

void map_and_verify(const fs::path& domain, const fs::path& boundary, bool codomain = false) {
  CAPTURE(domain.string());
  const MapProblem p = load(domain, boundary, codomain);
  if (p.tets.size() > max_tets) {
    MESSAGE("skipped under the sanitizers: " << p.tets.size() << " tets");
    return;
  }
  const MapResult r = map_to_domain(p);
  REQUIRE_MESSAGE(r.outcome == MapOutcome::success, r.message);
  CHECK_MESSAGE(r.verification.ok(), r.verification.first_failure);
}

}  // namespace

TEST_CASE("the Shrink-and-Expand examples map and verify") {
  if (!have_data()) return;
  const fs::path d = data() / "shrink-and-expand";
  map_and_verify(d / "prism_domain.ovm", d / "prism_ball_boundary.txt");
  map_and_verify(d / "notch_domain.ovm", d / "notch_stiff_tet_boundary.txt");
  map_and_verify(d / "thingi10k_83715_domain.ovm", d / "thingi10k_83715_tet_boundary.txt");
  map_and_verify(d / "thingi10k_81152_domain.ovm", d / "thingi10k_81152_random_star_boundary.txt");
}

TEST_CASE("the Galaxy Maps pairs map and verify through their parameter meshes") {
  if (!have_data()) return;
  const fs::path d = data() / "galaxy-maps";
  for (const char* name : {"example", "cub_rockerarm291", "tgs_100349", "tlc_polycube_bird"}) {
    if (std::string(name) == "tlc_polycube_bird" && !std::getenv("CMX_LONG_TESTS")) {
      MESSAGE("skipped tlc_polycube_bird (minutes): set CMX_LONG_TESTS=1");
      continue;
    }
    map_and_verify(d / (std::string(name) + "_object.vtk"), d / (std::string(name) + "_parameter.vtk"), true);
  }
}

TEST_CASE("the public cases map and verify, and P10 is refused as not star-shaped") {
  if (!have_data()) return;
  for (const char* id : {"P01", "P02", "P03", "P04", "P05", "P06", "P07", "P09"}) {
    const fs::path dir = data() / "public" / id;
    fs::path domain;
    for (const auto& f : fs::directory_iterator(dir))
      if (f.path().stem() == "domain") domain = f.path();
    map_and_verify(domain, dir / "boundary.txt");
  }
  const fs::path p10 = data() / "public" / "P10";
  try {
    (void)map_to_domain(load(p10 / "domain.ovm", p10 / "boundary.txt", false));
    FAIL("P10 was mapped");
  } catch (const MapError& e) {
    CHECK(e.kind() == MapErrorKind::not_star_shaped);
  }
}
