#pragma once
// Boundary-condition generators: prescribed positions for the boundary vertices of a ball-topology
// tet mesh on a tetrahedron, a "stiff" tetrahedron, the unit sphere or a random star shape, all
// star-shaped with respect to the origin (the construction of the Shrink-and-Expand program's
// generators, reimplemented; departures are listed below).
//
// Construction (generate_boundary), for each attempt until one validates (at most 100):
//  1. Four corners: distinct boundary vertices drawn with a seeded std::mt19937_64 and a
//     rejection draw of our own (so the choice is the same on every platform). stiff-tet: corners
//     0, 1, 2 are the vertices of a random boundary triangle, corner 3 another boundary vertex.
//     Corner j goes to vertex j of the regular tetrahedron inscribed in the unit sphere,
//     (sqrt(8)/3, 0, -1/3), (-sqrt(2)/3, sqrt(2/3), -1/3), (-sqrt(2)/3, -sqrt(2/3), -1/3), (0, 0, 1).
//  2. Six corner-to-corner paths over boundary edges, in the order (1,0), (2,0), (2,1), (3,0),
//     (3,1), (3,2): Dijkstra with Euclidean edge lengths of the source geometry; vertices already
//     on a path (or corners) are forbidden except the target, so the paths are disjoint and cut the
//     boundary sphere into four discs (the faces of K4). Boundary-adjacent corners are joined by
//     their edge. The m inner vertices of a path go to the straight tet edge at k/(m+1).
//  3. Every other boundary vertex: a Tutte embedding with uniform weights over boundary edges,
//     one sparse Laplacian system per connected group of free vertices (inside one face region),
//     solved by Jacobi-preconditioned conjugate gradients.
//  4. Orientation: the K4 cut fixes the cyclic order of the corners only up to a reflection. When
//     the surface comes out inside-out (negative enclosed volume), y is negated everywhere: this
//     reflection maps the tetrahedron onto itself (it swaps corners 1 and 2) and is exact in
//     doubles. (Departure: the predecessor discarded such attempts and tried another seed.)
//  5. sphere: every position divided by its norm. star: the sphere positions scaled per boundary
//     vertex, in ascending index order, by factors 1 + 9 k / 2^20 (k uniform below 2^20), i.e. in
//     [1, 10), drawn from a generator seeded with the spec's seed (independent of the attempt).
//  6. check_star_shaped_about_origin (exact predicates on the doubles); a failure starts the next
//     attempt with new corners.
//  With BoundaryShapeSpec::spread > 0, steps 3 to 6 are repeated up to `spread` times with the
//  Tutte weights divided by the stretch of the previous embedding (below), and the last valid
//  result is kept; the repetition stops once the worst vertex's stretch is within 20 times the
//  median, or at the first invalid result after a valid one.
// Path spacing is uniform (the predecessor used k/(m+2), leaving a double gap at the end). The
// source geometry enters only through Dijkstra's edge lengths, so it is not translated (lengths
// do not depend on where the boundary centroid is). The result depends only on the mesh, the
// source positions, the shape and the seed: the same input gives the same doubles, bit for bit.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "topology/tet_mesh.hpp"

namespace cmx::generators {

enum class BoundaryShape { tet, stiff_tet, sphere, star };

// How step 1 picks the four corners. random: drawn (the construction above). farthest, for
// shapes with a long tunnel or protrusion (Furch's knotted hole, fingers): on even attempts, the
// two ends of the surface's longest stretch (from a drawn vertex, the vertex farthest from it
// over the surface, then the one farthest from that; every other time with the two swapped)
// become corners 0 and 1, and corners 2 and 3 are taken far out of the stretch (at least 3/4 as
// far from corner 0 as corner 1, and over the surface less than 3/2 times as far from corner 1 as
// in space); the three paths from corner 0 are found together, as vertex-disjoint paths of least
// total length (generators/disjoint_paths.hpp), so they run side by side down the stretch and
// space its vertices along three edges of the tetrahedron, where uniform Tutte weights would
// crowd it exponentially into one face. Odd attempts draw the corners (and still find the paths
// from corner 0 together). stiff-tet keeps its triangle of corners 0, 1, 2: with farthest, on
// even attempts that triangle is one at the outer end of the stretch and corner 3 its inner end,
// and on every attempt the three paths from corner 3 are found together.
enum class CornerChoice { random, farthest };

struct BoundaryShapeSpec {
  BoundaryShape shape = BoundaryShape::tet;
  std::uint64_t seed = 1234;
  // Spreading steps after the Tutte embedding (0: none, the construction above unchanged). Each
  // step reweights the Tutte system to undo its crowding (Yoshizawa, Belyaev and Seidel's stretch
  // minimisation) and solves it again; the last step that validates is kept. Uniform weights crowd
  // a long protrusion (a finger, a tunnel) exponentially along its length, to below what doubles
  // resolve; a few steps spread it over a fair share of the shape.
  int spread = 0;
  CornerChoice corners = CornerChoice::random;
  // Attempts run this many at once (0: the cores), each on its own data; their results are taken
  // in attempt order, so the boundary and the failure message are the same for every count.
  unsigned threads = 1;
};

// Reads "tet", "stiff-tet", "sphere" or "star", each optionally followed by ":SEED" (a decimal
// integer below 2^64; the documented forms are the four names and "star:SEED"). nullopt otherwise.
std::optional<BoundaryShapeSpec> parse_boundary_shape(std::string_view text);
// The name, with ":SEED" when the seed is not the default 1234 or the shape is star;
// parse_boundary_shape reads it back.
std::string to_string(const BoundaryShapeSpec& spec);
// "tet", "stiff-tet", "sphere", "star".
const char* shape_name(BoundaryShape shape);
// "random" or "farthest" (cmx boundary --corners); nullopt otherwise.
std::optional<CornerChoice> parse_corner_choice(std::string_view text);

struct GeneratedBoundary {
  bool ok = false;
  std::vector<std::uint32_t> vertices;           // boundary vertices, ascending
  std::vector<std::array<double, 3>> positions;  // one per entry of vertices
  int attempts = 0;                              // attempts made (the successful one included)
  std::string message;                           // why it failed (when !ok)
};

// Maximum number of corner choices tried by generate_boundary.
inline constexpr int max_boundary_attempts = 100;

// mesh: a ball-topology TetMesh; source: one position per vertex (the domain geometry), or empty for
// a mesh given by its tets alone (then the paths are shortest in edges, and spreading measures
// stretch against equilateral faces). Returns
// ok = false with a message when `source` does not match the mesh or has a non-finite coordinate,
// when the boundary is not a closed surface (an edge not in exactly two boundary faces) or has
// fewer than 4 vertices, or when no attempt validates.
GeneratedBoundary generate_boundary(const topology::TetMesh& mesh,
                                    const std::vector<std::array<double, 3>>& source,
                                    const BoundaryShapeSpec& spec);

// Exact validity of generated (or any) boundary positions: every vertex of `boundary.vertices`
// is a boundary vertex and every boundary vertex has a finite position; every outward boundary
// face (topology::boundary_faces) maps to a triangle with orient3d(a, b, c, origin) < 0 in exact
// arithmetic on the doubles (non-degenerate, the origin strictly on its inner side); and the
// faces around each boundary vertex wind exactly once around the ray through it (their angles,
// summed in doubles, are 2*pi rather than 4*pi, 6*pi...: the sum is a multiple of 2*pi, so the
// rounding cannot matter). Together these say that the surface is star-shaped about the origin
// (its central projection onto the unit sphere is a bijection). Returns "" when valid, else a
// message naming the first offending face or vertex. `boundary.ok` is not consulted.
std::string check_star_shaped_about_origin(const topology::TetMesh& mesh, const GeneratedBoundary& boundary);

}  // namespace cmx::generators
