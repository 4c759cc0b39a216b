#pragma once
// The consumer's run-time checks. Each prints what it checked and returns its number of failures.

// Two-Product (arith/expansion.hpp, inline) against the exact product computed with GMP.
int check_two_product();
// Orientation of near-degenerate tetrahedra against orient3d_exact: the inline semi-static
// filter, an exact determinant built here from the inline expansion arithmetic, and the
// library's cascade.
int check_orient3d();
// A small map_to_domain call (a cube split into tets around one interior vertex) that verifies.
int check_map();
