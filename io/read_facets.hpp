#pragma once
// A ball given only combinatorially: its tetrahedra as four vertex ids each, no coordinates (the
// form of the Library of Triangulations' facet lists, in which Furch's knotted hole, Bing's house,
// Rudin's and Ziegler's balls are published). Two spellings are read (docs/formats.md):
//
//   plain       one tet per line, four ids separated by blanks and/or commas; '#' starts a comment
//   bracketed   `[[a,b,c,d],[a,b,c,d],...]`, over any number of lines, optionally preceded by a
//               label `NAME =` (kept) and followed by `;`
//
// Ids number from 0 or from 1 (the smallest id decides; any other start is refused), every id up
// to the largest must occur in some tet, a tet's four ids are distinct and no tet is listed twice.
// The vertex order within a tet carries no orientation here: topology::orient_coherently gives
// the tets one. Errors: IoError naming the file and the line.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace cmx::io {

struct FacetList {
  std::size_t vertex_count = 0;
  std::vector<std::array<std::uint32_t, 4>> tets;  // ids from 0, in the order listed
  bool one_based = false;                          // the file numbered its vertices from 1
  std::string label;                               // the bracketed form's `NAME =`, or ""
};

FacetList read_facet_list(std::string_view bytes, const std::string& name);
// Reads the file at `path` (IoError open_failed when it cannot be read).
FacetList read_facet_list_file(const std::string& path);
// True for a path ending in .facets (any case): the extension cmx reads as a facet list.
bool is_facet_list_path(const std::string& path);

}  // namespace cmx::io
