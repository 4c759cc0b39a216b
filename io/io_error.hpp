#pragma once
// The one error type of the io layer. Every reader and writer reports failures as an IoError that
// names the file and, for text input, the 1-based line (0 when no line applies, e.g. binary data
// or a failed open). what() is "file:line: message" (or "file: message" when line is 0), the form
// editors and CI logs jump to.
#include <cstddef>
#include <stdexcept>
#include <string>

namespace cmx::io {

enum class ErrorKind {
  open_failed,        // the file cannot be opened or read
  unsupported,        // a valid file of a dialect/feature cmx does not read (e.g. OVM BINARY, LZMA-compressed VTU)
  syntax,             // a token or keyword that does not belong there
  truncated,          // the data ends before what the header promised
  count_mismatch,     // a count contradicts the data (e.g. a cell with 5 vertices in CELLS)
  index_out_of_range, // a vertex index outside the vertex list
  non_tet_cell,       // a 3D cell that is not a linear tetrahedron
  not_finite,         // NaN or infinity where a coordinate was expected
  duplicate,          // a tetrahedron listed twice, a boundary index given twice, ...
  degenerate_tet,     // a tetrahedron with a repeated vertex or zero volume
  inconsistent_orientation,  // tets of both signs
  too_large,          // a count beyond what the file size or the index type allows
  mismatch,           // two inputs that must agree do not (codomain connectivity, ...)
  write_failed,       // a writer could not create, write or rename its output
};

// Short stable name of a kind ("syntax", "index_out_of_range", ...), for JSON and tests.
const char* kind_name(ErrorKind kind);

class IoError : public std::runtime_error {
 public:
  IoError(ErrorKind kind, std::string file, std::size_t line, std::string message);
  ErrorKind kind() const { return kind_; }
  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }  // 1-based; 0 = no line
  const std::string& message() const { return message_; }

 private:
  ErrorKind kind_;
  std::string file_;
  std::size_t line_;
  std::string message_;
};

}  // namespace cmx::io
