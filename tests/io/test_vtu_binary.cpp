// The VTU reader on the binary dialects VTK and meshio write by default: inline base64
// (format="binary"), appended raw and base64, uncompressed and zlib-compressed in blocks, UInt32
// and UInt64 headers, both byte orders; and its refusals of malformed or oversized binary data.
#include <doctest/doctest.h>

#include "io/read_mesh.hpp"
#include "io/write_mesh.hpp"
#include "io_test_util.hpp"
#include "vtu_builder.hpp"

using namespace cmx;
using namespace cmx::io;
using namespace cmx::io::test;

namespace {

struct Cells {
  std::vector<std::vector<std::uint32_t>> connectivity;
  std::vector<int> types;
};

// grid_mesh(2) as VTK cells, with one boundary triangle (type 5) that the reader must skip.
Cells cells_of(const TetMeshData& mesh) {
  Cells c;
  for (const auto& t : mesh.tets) {
    c.connectivity.push_back({t[0], t[1], t[2], t[3]});
    c.types.push_back(10);
  }
  c.connectivity.push_back({0, 1, 2});
  c.types.push_back(5);
  return c;
}

void check_reads_back(const std::string& text, const TetMeshData& mesh, const std::vector<DoublePoint>& points) {
  const auto back = read_vtu(text, "variant.vtu");
  CHECK(back.tets == mesh.tets);
  CHECK_FALSE(back.orientation_flipped);
  REQUIRE(back.positions.size() == points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t k = 0; k < 3; ++k) CHECK(back.positions[i][k] == rational_from_double(points[i][k]));
}

// The unit tet in a dialect, for the malformed-input tests.
std::string unit_tet(const VtuDialect& d) {
  return VtuBuilder(d).file({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 1, 2, 3}}, {10});
}

}  // namespace

TEST_CASE("VTU binary dialects: inline and appended, raw and base64, zlib, header types, byte orders") {
  const auto mesh = grid_mesh(2);
  const auto points = nearest_doubles(mesh.positions);
  const auto cells = cells_of(mesh);
  const std::string extra(points.size() * 8, '\x7f');  // point data the reader must ignore
  int variants = 0;
  for (bool appended : {false, true})
    for (bool base64 : {true, false})
      for (bool zlib : {false, true})
        for (bool header64 : {false, true})
          for (bool big_endian : {false, true}) {
            if (!appended && !base64) continue;  // inline data is always base64
            VtuDialect d{appended, base64, zlib, header64, big_endian, false, 100};
            CAPTURE(appended);
            CAPTURE(base64);
            CAPTURE(zlib);
            CAPTURE(header64);
            CAPTURE(big_endian);
            check_reads_back(VtuBuilder(d).file(points, cells.connectivity, cells.types, extra), mesh, points);
            ++variants;
          }
  CHECK(variants == 24);
  // meshio's uncompressed inline arrays encode header and data as one base64 stream.
  VtuDialect joint;
  joint.joint_encoding = true;
  check_reads_back(VtuBuilder(joint).file(points, cells.connectivity, cells.types), mesh, points);
}

TEST_CASE("VTU zlib: a full last block is declared as 0, blocks of any size, an empty array") {
  const auto mesh = grid_mesh(1);  // 8 points: 192 bytes of coordinates
  const auto points = nearest_doubles(mesh.positions);
  const auto cells = cells_of(mesh);
  for (std::size_t block : {std::size_t(1), std::size_t(64), std::size_t(96), std::size_t(192), std::size_t(1 << 16)}) {
    CAPTURE(block);
    VtuDialect d;
    d.zlib = true;
    d.block_size = block;
    check_reads_back(VtuBuilder(d).file(points, cells.connectivity, cells.types), mesh, points);
  }
  VtuDialect d;
  d.zlib = true;
  const auto empty = read_vtu(VtuBuilder(d).file({{0, 0, 0}}, {}, {}), "empty.vtu");
  CHECK(empty.positions.size() == 1);
  CHECK(empty.tets.empty());
}

TEST_CASE("VTU binary bad input: malformed zlib and base64 name the file and the DataArray") {
  VtuDialect raw_zlib;
  raw_zlib.appended = true;
  raw_zlib.base64 = false;
  raw_zlib.zlib = true;
  std::string text = unit_tet(raw_zlib);
  // Corrupt the first compressed stream (points): after 4 header words of 4 bytes, the zlib header.
  const auto underscore = text.find('_', text.find("<AppendedData"));
  text[underscore + 1 + 16] = '\x55';
  text[underscore + 1 + 17] = '\x55';
  auto e = expect_io_error([&] { read_vtu(text, "corrupt.vtu"); }, ErrorKind::syntax);
  CHECK(std::string(e.what()).find("corrupt.vtu:") == 0);
  CHECK(std::string(e.what()).find("DataArray 'Points'") != std::string::npos);
  CHECK(std::string(e.what()).find("zlib") != std::string::npos);

  std::string inline_text = unit_tet(VtuDialect{});
  const auto at = inline_text.find("format=\"binary\">") + 20;
  inline_text[at] = '*';
  e = expect_io_error([&] { read_vtu(inline_text, "b64.vtu"); }, ErrorKind::syntax);
  CHECK(std::string(e.what()).find("base64") != std::string::npos);
}

// A unit-tet VTU whose four arrays all point at the same appended bytes `blocks`.
static std::string appended_file(bool zlib, const std::string& blocks) {
  return "<VTKFile type=\"UnstructuredGrid\" header_type=\"UInt32\"" + std::string(zlib ? " compressor=\"vtkZLibDataCompressor\"" : "") +
         "><UnstructuredGrid><Piece NumberOfPoints=\"4\" NumberOfCells=\"1\"><Points><DataArray type=\"Float64\" Name=\"P\" "
         "NumberOfComponents=\"3\" format=\"appended\" offset=\"0\"/></Points><Cells><DataArray type=\"Int64\" Name=\"connectivity\" "
         "format=\"appended\" offset=\"0\"/><DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\" offset=\"0\"/>"
         "<DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" offset=\"0\"/></Cells></Piece></UnstructuredGrid>"
         "<AppendedData encoding=\"raw\">_" + blocks + "</AppendedData></VTKFile>";
}

TEST_CASE("VTU binary bad input: sizes are checked before anything is allocated") {
  const VtuBuilder b(VtuDialect{});
  const auto words = [&](std::initializer_list<std::uint64_t> values) {
    std::string out;
    for (auto v : values) out += b.header_word(v);
    return out;
  };
  const auto read = [](const std::string& text) { return [text] { read_vtu(text, "sizes.vtu"); }; };
  // A compression header declaring 3 GB when the Piece needs 96 bytes of points.
  expect_io_error(read(appended_file(true, words({100000, 32768, 0}))), ErrorKind::count_mismatch);
  // The right total in 96 blocks of one byte: their 96 compressed sizes are more than the file holds.
  expect_io_error(read(appended_file(true, words({96, 1, 0}))), ErrorKind::too_large);
  // 96 bytes said to inflate from 0 compressed bytes: beyond deflate's largest ratio.
  expect_io_error(read(appended_file(true, words({1, 96, 0, 0}))), ErrorKind::too_large);
  // Compressed sizes running past the end of the file.
  expect_io_error(read(appended_file(true, words({1, 96, 0, 4000000}))), ErrorKind::truncated);
  // A last block larger than the block size.
  expect_io_error(read(appended_file(true, words({2, 48, 60, 10, 10}))), ErrorKind::syntax);
  // An uncompressed header claiming 3 GB.
  expect_io_error(read(appended_file(false, words({3000000000u}))), ErrorKind::count_mismatch);
  // The Piece's counts are bounded by what a compressed file can inflate to.
  expect_io_error(read("<VTKFile type=\"UnstructuredGrid\" compressor=\"vtkZLibDataCompressor\"><UnstructuredGrid>"
                       "<Piece NumberOfPoints=\"99999999999\" NumberOfCells=\"1\">"),
                  ErrorKind::too_large);
}

TEST_CASE("VTU refusals: other compressors and encodings are named") {
  auto e = expect_io_error([] { read_vtu("<VTKFile type=\"UnstructuredGrid\" compressor=\"vtkLZMADataCompressor\">", "lzma.vtu"); },
                           ErrorKind::unsupported, 1);
  CHECK(std::string(e.what()).find("vtkLZMADataCompressor") != std::string::npos);
  expect_io_error([] { read_vtu("<VTKFile type=\"UnstructuredGrid\" header_type=\"Int8\">", "h.vtu"); }, ErrorKind::unsupported, 1);
  std::string text = unit_tet(VtuDialect{true, true, false, false, false, false, 100});
  text.replace(text.find("encoding=\"base64\""), 17, "encoding=\"hex\"");
  expect_io_error([&] { read_vtu(text, "enc.vtu"); }, ErrorKind::unsupported);
}
