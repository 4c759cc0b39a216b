#pragma once
// The minimal XML tag scanner behind the VTU reader: tags with their attributes, comments and
// declarations skipped, text between tags left to the caller. Not a general XML parser: CDATA and
// entities are not needed by the VTK arrays read here.
#include <cstddef>
#include <map>
#include <string>
#include <string_view>

#include "io/io_error.hpp"

namespace cmx::io {

struct XmlTag {
  std::string name;  // "DataArray", "/Cells", ...
  std::map<std::string, std::string> attributes;
  std::size_t begin = 0, end = 0;  // offsets of '<' and one past '>'
  bool self_closing = false;

  // The attribute's value, "" when absent.
  const std::string& attribute(const std::string& key) const;
  bool has(const std::string& key) const { return attributes.count(key) != 0; }
};

class XmlTags {
 public:
  XmlTags(std::string_view data, std::string file) : data_(data), file_(std::move(file)) {}

  // The next tag at or after `pos` (skipping comments, declarations and text); false at the end.
  // Throws IoError (truncated, syntax) for an unterminated or malformed tag.
  bool next(std::size_t pos, XmlTag& tag) const;

  // 1-based line of an offset (for messages).
  std::size_t line_at(std::size_t offset) const;
  [[noreturn]] void fail(std::size_t offset, ErrorKind kind, const std::string& message) const;

  std::string_view data() const { return data_; }
  const std::string& file() const { return file_; }

 private:
  std::size_t read_attributes(std::size_t i, XmlTag& tag) const;

  std::string_view data_;
  std::string file_;
};

}  // namespace cmx::io
