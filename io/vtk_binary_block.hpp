#pragma once
// The binary payload of one VTK XML DataArray, as VTK and meshio write it:
//   uncompressed:  [nbytes] data
//   zlib:          [nblocks][blocksize][last block size (0: full)][compressed size of each block]
//                  then the zlib streams of the blocks, one after the other
// Header words are `header_type` (UInt32 or UInt64) in the file's byte order. The bytes come either
// raw (appended raw data) or base64-encoded (inline format="binary", appended base64).
//
// Sizes are checked before anything is allocated: the decoded size must be exactly what the
// Piece's counts ask for, every size must fit in what the file has left, and no block may claim to
// inflate by more than max_inflate_ratio (deflate cannot expand data further), so a header
// claiming gigabytes in a small file is an error, not an allocation.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "io/base64.hpp"
#include "io/io_error.hpp"

namespace cmx::io {

// Deflate's largest compression ratio (258-byte matches in 2-bit codes, plus block overhead).
inline constexpr std::uint64_t max_inflate_ratio = 1032;

// The stored bytes of one array, raw or base64, read front to back.
class EncodedBytes {
 public:
  static EncodedBytes raw(std::string_view bytes) { return EncodedBytes(bytes, false); }
  static EncodedBytes base64(std::string_view text) { return EncodedBytes(text, true); }

  // Appends the next n bytes to `out`; false (with `out` partly filled) when fewer are left or
  // the base64 text is malformed (malformed() tells which).
  bool read(std::size_t n, std::string& out);
  // An upper bound of the bytes still to come.
  std::size_t remaining_bound() const { return encoded_ ? decoder_.remaining_bound() : bytes_.size() - pos_; }
  bool malformed() const { return malformed_; }

 private:
  EncodedBytes(std::string_view bytes, bool encoded) : bytes_(bytes), encoded_(encoded), decoder_(bytes) {}

  std::string_view bytes_;
  bool encoded_;
  Base64Reader decoder_;
  std::size_t pos_ = 0;
  bool malformed_ = false;
};

struct BlockLayout {
  int header_size = 4;  // bytes per header word: 4 (UInt32) or 8 (UInt64)
  bool big_endian = false;
  bool zlib = false;  // compressor="vtkZLibDataCompressor"
};

// Where an array is, for messages: "file:line: DataArray "name": ...".
struct ArrayPlace {
  std::string file;
  std::size_t line = 0;
  std::string array;
};

// Decodes one array's payload, which must hold exactly `expected` bytes. Throws IoError
// (count_mismatch: the header's size differs from `expected`; truncated: the data ends early;
// too_large: a size the file cannot hold; syntax: malformed base64 or zlib data).
std::string decode_vtk_block(EncodedBytes& in, const BlockLayout& layout, std::uint64_t expected, const ArrayPlace& place);

}  // namespace cmx::io
