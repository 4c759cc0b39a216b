#include "io/xml_tags.hpp"

#include <cctype>

namespace cmx::io {
namespace {

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

}  // namespace

const std::string& XmlTag::attribute(const std::string& key) const {
  static const std::string none;
  const auto it = attributes.find(key);
  return it == attributes.end() ? none : it->second;
}

std::size_t XmlTags::line_at(std::size_t offset) const {
  std::size_t line = 1;
  for (std::size_t i = 0; i < offset && i < data_.size(); ++i) line += data_[i] == '\n';
  return line;
}

void XmlTags::fail(std::size_t offset, ErrorKind kind, const std::string& message) const {
  throw IoError(kind, file_, line_at(offset), message);
}

bool XmlTags::next(std::size_t pos, XmlTag& tag) const {
  while (true) {
    const auto lt = data_.find('<', pos);
    if (lt == std::string_view::npos) return false;
    if (data_.substr(lt, 4) == "<!--") {
      const auto close = data_.find("-->", lt);
      if (close == std::string_view::npos) fail(lt, ErrorKind::truncated, "unterminated XML comment");
      pos = close + 3;
      continue;
    }
    if (data_.substr(lt, 2) == "<?" || data_.substr(lt, 2) == "<!") {
      const auto close = data_.find('>', lt);
      if (close == std::string_view::npos) fail(lt, ErrorKind::truncated, "unterminated XML declaration");
      pos = close + 1;
      continue;
    }
    tag = XmlTag{};
    tag.begin = lt;
    std::size_t i = lt + 1;
    if (i < data_.size() && data_[i] == '/') ++i;  // a closing tag
    while (i < data_.size() && !is_space(data_[i]) && data_[i] != '>' && data_[i] != '/') ++i;
    tag.name = std::string(data_.substr(lt + 1, i - lt - 1));
    tag.end = read_attributes(i, tag);
    return true;
  }
}

// Reads `key="value"` pairs up to '>' or '/>'; returns the offset one past the tag.
std::size_t XmlTags::read_attributes(std::size_t i, XmlTag& tag) const {
  while (true) {
    while (i < data_.size() && is_space(data_[i])) ++i;
    if (i >= data_.size()) fail(tag.begin, ErrorKind::truncated, "unterminated XML tag <" + tag.name);
    if (data_[i] == '>') return i + 1;
    if (data_[i] == '/' && i + 1 < data_.size() && data_[i + 1] == '>') {
      tag.self_closing = true;
      return i + 2;
    }
    const auto eq = data_.find('=', i);
    if (eq == std::string_view::npos || eq + 1 >= data_.size() || (data_[eq + 1] != '"' && data_[eq + 1] != '\''))
      fail(i, ErrorKind::syntax, "malformed attribute in XML tag <" + tag.name + ">");
    std::string key(data_.substr(i, eq - i));
    while (!key.empty() && is_space(key.back())) key.pop_back();
    const auto close = data_.find(data_[eq + 1], eq + 2);
    if (close == std::string_view::npos) fail(i, ErrorKind::truncated, "unterminated attribute value in <" + tag.name + ">");
    tag.attributes[key] = std::string(data_.substr(eq + 2, close - eq - 2));
    i = close + 1;
  }
}

}  // namespace cmx::io
