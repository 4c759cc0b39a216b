#include "io/vtk_binary_block.hpp"

#include <zlib.h>

#include <vector>

#include "io/binary_numbers.hpp"
#include "io/scanner.hpp"

namespace cmx::io {

bool EncodedBytes::read(std::size_t n, std::string& out) {
  if (encoded_) {
    const auto status = decoder_.read(n, out);
    malformed_ = status == Base64Reader::Status::invalid;
    return status == Base64Reader::Status::ok;
  }
  const std::size_t left = bytes_.size() - pos_;
  const std::size_t take = n < left ? n : left;
  out.append(bytes_.substr(pos_, take));
  pos_ += take;
  return take == n;
}

namespace {

[[noreturn]] void fail(const ArrayPlace& place, ErrorKind kind, const std::string& message) {
  throw IoError(kind, place.file, place.line, "DataArray " + quoted(place.array) + ": " + message);
}

void read_or_fail(EncodedBytes& in, std::size_t n, std::string& out, const ArrayPlace& place, const std::string& what) {
  if (in.read(n, out)) return;
  if (in.malformed()) fail(place, ErrorKind::syntax, "malformed base64 text in " + what);
  fail(place, ErrorKind::truncated, "the data ends in " + what);
}

std::uint64_t header_word(EncodedBytes& in, const BlockLayout& layout, const ArrayPlace& place, const std::string& what) {
  std::string bytes;
  read_or_fail(in, std::size_t(layout.header_size), bytes, place, what);
  return load_unsigned(bytes.data(), layout.header_size, layout.big_endian);
}

std::string decode_plain(EncodedBytes& in, const BlockLayout& layout, std::uint64_t expected, const ArrayPlace& place) {
  const auto nbytes = header_word(in, layout, place, "the block header");
  if (nbytes != expected)
    fail(place, ErrorKind::count_mismatch,
         "the block header announces " + std::to_string(nbytes) + " bytes, the Piece's counts need " + std::to_string(expected));
  if (nbytes > in.remaining_bound())
    fail(place, ErrorKind::truncated, "the block of " + std::to_string(nbytes) + " bytes runs past the end of the file");
  std::string out;
  out.reserve(std::size_t(nbytes));
  read_or_fail(in, std::size_t(nbytes), out, place, "the block");
  return out;
}

// The uncompressed size that a compression header declares, or an error when it overflows.
std::uint64_t declared_size(std::uint64_t blocks, std::uint64_t block_size, std::uint64_t last, const ArrayPlace& place) {
  if (blocks == 0) return 0;
  if (last > block_size)
    fail(place, ErrorKind::syntax, "the last block (" + std::to_string(last) + " bytes) is larger than the block size " + std::to_string(block_size));
  std::uint64_t total = 0;
  if (__builtin_mul_overflow(blocks - (last ? 1 : 0), block_size, &total) || __builtin_add_overflow(total, last, &total))
    fail(place, ErrorKind::too_large, "the compression header declares more than 2^64 bytes");
  return total;
}

// Reads the compressed sizes and checks every one against what the file and deflate allow.
std::vector<std::uint64_t> compressed_sizes(EncodedBytes& in, const BlockLayout& layout, std::uint64_t blocks,
                                            std::uint64_t block_size, std::uint64_t last, const ArrayPlace& place) {
  if (blocks > in.remaining_bound() / std::size_t(layout.header_size))
    fail(place, ErrorKind::too_large, "the compression header declares " + std::to_string(blocks) + " blocks, more than the file holds");
  std::vector<std::uint64_t> sizes(static_cast<std::size_t>(blocks));
  for (auto& size : sizes) size = header_word(in, layout, place, "the compression header");
  std::uint64_t sum = 0;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const std::uint64_t inflated = (i + 1 < sizes.size() || last == 0) ? block_size : last;
    if (__builtin_add_overflow(sum, sizes[i], &sum) || sum > in.remaining_bound())
      fail(place, ErrorKind::truncated, "the compressed blocks run past the end of the file");
    if (sizes[i] > UINT64_MAX / max_inflate_ratio || inflated > max_inflate_ratio * sizes[i])
      fail(place, ErrorKind::too_large,
           "block " + std::to_string(i) + " claims to inflate " + std::to_string(sizes[i]) + " bytes to " + std::to_string(inflated) +
               ", more than zlib can");
  }
  return sizes;
}

std::string decode_zlib(EncodedBytes& in, const BlockLayout& layout, std::uint64_t expected, const ArrayPlace& place) {
  const auto blocks = header_word(in, layout, place, "the compression header");
  const auto block_size = header_word(in, layout, place, "the compression header");
  const auto last = header_word(in, layout, place, "the compression header");
  const auto total = declared_size(blocks, block_size, last, place);
  if (total != expected)
    fail(place, ErrorKind::count_mismatch,
         "the compression header declares " + std::to_string(total) + " bytes, the Piece's counts need " + std::to_string(expected));
  const auto sizes = compressed_sizes(in, layout, blocks, block_size, last, place);
  std::string out(std::size_t(total), '\0');
  std::string compressed;
  std::size_t at = 0;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const std::uint64_t inflated = (i + 1 < sizes.size() || last == 0) ? block_size : last;
    compressed.clear();
    read_or_fail(in, std::size_t(sizes[i]), compressed, place, "compressed block " + std::to_string(i));
    uLongf length = uLongf(inflated);
    const int status = inflated == 0 ? Z_OK
                                     : uncompress(reinterpret_cast<Bytef*>(out.data() + at), &length,
                                                  reinterpret_cast<const Bytef*>(compressed.data()), uLong(compressed.size()));
    if (status != Z_OK || length != uLongf(inflated))
      fail(place, ErrorKind::syntax,
           "compressed block " + std::to_string(i) + " is not a zlib stream of " + std::to_string(inflated) + " bytes (zlib: " +
               (status == Z_OK ? std::string("it holds ") + std::to_string(length) + " bytes" : std::string(zError(status))) + ")");
    at += std::size_t(inflated);
  }
  return out;
}

}  // namespace

std::string decode_vtk_block(EncodedBytes& in, const BlockLayout& layout, std::uint64_t expected, const ArrayPlace& place) {
  return layout.zlib ? decode_zlib(in, layout, expected, place) : decode_plain(in, layout, expected, place);
}

}  // namespace cmx::io
