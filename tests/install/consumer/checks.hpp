#pragma once
// The consumer's run-time checks. Each prints what it checked and returns its number of failures.

// Orientation of near-degenerate tetrahedra and triangles: the header-only kernel (inline
// floating-point code compiled here, with the consumer's flags) and the compiled cmx::orient3d,
// against the compiled exact-only arithmetic.
int check_orient();
// A small cmx::map_to_domain call (a cube split into tets around one interior vertex), checked
// exact-valid.
int check_map();
