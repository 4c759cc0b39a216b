#pragma once
// Builds VTU files of a mesh in the binary dialects VTK and meshio write (inline base64 or
// appended raw/base64 data, uncompressed or zlib in blocks, UInt32/UInt64 headers, either byte
// order), so that the reader is tested on files whose every byte the test controls.
#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "io/write_mesh.hpp"

namespace cmx::io::test {

inline std::string base64_encode(const std::string& bytes) {
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t bits = 0;
    const std::size_t n = bytes.size() - i < 3 ? bytes.size() - i : 3;
    for (std::size_t k = 0; k < 3; ++k) bits = (bits << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) out += k <= n ? alphabet[(bits >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

inline std::string zlib_compress(const std::string& bytes) {
  uLongf size = compressBound(uLong(bytes.size()));
  std::string out(size, '\0');
  compress2(reinterpret_cast<Bytef*>(out.data()), &size, reinterpret_cast<const Bytef*>(bytes.data()), uLong(bytes.size()), 6);
  out.resize(size);
  return out;
}

struct VtuDialect {
  bool appended = false;     // appended data instead of inline format="binary"
  bool base64 = true;        // appended data as base64 (inline data always is)
  bool zlib = false;         // compressor="vtkZLibDataCompressor"
  bool header64 = false;     // header_type="UInt64"
  bool big_endian = false;
  bool joint_encoding = false;  // header and data base64-encoded as one stream (meshio, uncompressed)
  std::size_t block_size = 32768;
};

class VtuBuilder {
 public:
  explicit VtuBuilder(VtuDialect d) : d_(d) {}

  std::string number(std::uint64_t v, int size) const {
    std::string out;
    for (int i = 0; i < size; ++i) out += char((v >> (8 * (d_.big_endian ? size - 1 - i : i))) & 0xFF);
    return out;
  }
  std::string header_word(std::uint64_t v) const { return number(v, d_.header64 ? 8 : 4); }

  // The stored form of one array's bytes: header(s) + data, compressed and encoded as asked.
  std::string block(const std::string& data) const {
    if (!d_.zlib) {
      const std::string header = header_word(data.size());
      if (!d_.appended || d_.base64)
        return d_.joint_encoding ? base64_encode(header + data) : base64_encode(header) + base64_encode(data);
      return header + data;
    }
    std::vector<std::string> blocks;
    for (std::size_t i = 0; i < data.size(); i += d_.block_size) blocks.push_back(zlib_compress(data.substr(i, d_.block_size)));
    const std::size_t last = blocks.empty() ? 0 : data.size() - (blocks.size() - 1) * d_.block_size;
    std::string header = header_word(blocks.size()) + header_word(d_.block_size) + header_word(last == d_.block_size ? 0 : last);
    std::string body;
    for (const auto& b : blocks) {
      header += header_word(b.size());
      body += b;
    }
    if (!d_.appended || d_.base64) return base64_encode(header) + base64_encode(body);
    return header + body;
  }

  // A DataArray element; the data goes inline or to the appended section.
  std::string array(const std::string& type, const std::string& name, int components, const std::string& data) {
    std::string tag = "<DataArray type=\"" + type + "\" Name=\"" + name + "\" NumberOfComponents=\"" + std::to_string(components) + "\"";
    const std::string stored = block(data);
    if (!d_.appended) return tag + " format=\"binary\">\n  " + stored + "\n</DataArray>\n";
    tag += " format=\"appended\" offset=\"" + std::to_string(appended_.size()) + "\"/>\n";
    appended_ += stored;
    return tag;
  }

  std::string file(const std::vector<DoublePoint>& points, const std::vector<std::vector<std::uint32_t>>& cells,
                   const std::vector<int>& types, const std::string& extra_point_data = "") {
    std::string coords, connectivity, offsets, type_bytes;
    for (const auto& p : points)
      for (double c : p) {
        std::uint64_t u;
        std::memcpy(&u, &c, 8);
        coords += number(u, 8);
      }
    std::uint64_t end = 0;
    for (const auto& c : cells) {
      for (auto v : c) connectivity += number(v, 8);
      offsets += number(end += c.size(), 8);
    }
    for (int t : types) type_bytes += number(std::uint64_t(t), 1);
    std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"" +
                      std::string(d_.big_endian ? "BigEndian" : "LittleEndian") + "\" header_type=\"" + (d_.header64 ? "UInt64" : "UInt32") +
                      "\"" + (d_.zlib ? " compressor=\"vtkZLibDataCompressor\"" : "") + ">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"" +
                      std::to_string(points.size()) + "\" NumberOfCells=\"" + std::to_string(cells.size()) + "\">\n";
    // One statement per array: the appended data must follow the order of the tags.
    if (!extra_point_data.empty()) xml += "<PointData>\n" + array("Float64", "extra", 1, extra_point_data) + "</PointData>\n";
    xml += "<Points>\n" + array("Float64", "Points", 3, coords);
    xml += "</Points>\n<Cells>\n" + array("Int64", "connectivity", 1, connectivity);
    xml += array("Int64", "offsets", 1, offsets);
    xml += array("UInt8", "types", 1, type_bytes);
    xml += "</Cells>\n</Piece>\n</UnstructuredGrid>\n";
    if (d_.appended)
      xml += "<AppendedData encoding=\"" + std::string(d_.base64 ? "base64" : "raw") + "\">\n   _" + appended_ + "\n</AppendedData>\n";
    return xml + "</VTKFile>\n";
  }

 private:
  VtuDialect d_;
  std::string appended_;
};

}  // namespace cmx::io::test
