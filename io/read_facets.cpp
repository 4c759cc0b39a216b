#include "io/read_facets.hpp"

#include <algorithm>
#include <cctype>
#include <limits>

#include "io/io_error.hpp"
#include "io/scanner.hpp"
#include "io/tet_mesh_data.hpp"

namespace cmx::io {
namespace {

using Ids = std::array<std::uint64_t, 4>;

struct ListedTet {
  Ids ids;
  std::size_t line;
};

// A cursor over the characters, counting lines (LF, CRLF and a lone CR end one).
class Cursor {
 public:
  Cursor(std::string_view data, const std::string& file) : data_(data), file_(file) {}

  [[nodiscard]] bool at_end() const { return pos_ >= data_.size(); }
  [[nodiscard]] char peek() const { return at_end() ? '\0' : data_[pos_]; }
  [[nodiscard]] std::size_t line() const { return line_; }
  [[nodiscard]] const std::string& file() const { return file_; }

  void advance() {
    const char c = data_[pos_++];
    if (c == '\n' || (c == '\r' && peek() != '\n')) ++line_;
  }
  // Blanks and, with `comments`, '#' to the end of the line; line ends too unless `in_line`.
  void skip_blanks(bool comments, bool in_line) {
    while (!at_end()) {
      const char c = peek();
      if (comments && c == '#') {
        while (!at_end() && peek() != '\n' && peek() != '\r') advance();
      } else if (c == ' ' || c == '\t' || c == '\f' || c == '\v' || (!in_line && (c == '\n' || c == '\r'))) {
        advance();
      } else {
        return;
      }
    }
  }
  // A whole number ending at a separator: "3.5" or "4x" is one bad token, not an id and more.
  std::uint64_t id() {
    const std::size_t start = pos_;
    if (!std::isdigit(static_cast<unsigned char>(peek())))
      fail(ErrorKind::syntax, "a vertex id was expected, found " + found());
    std::uint64_t value = 0;
    while (std::isdigit(static_cast<unsigned char>(peek()))) {
      value = value * 10 + std::uint64_t(peek() - '0');
      if (value > max_vertices) fail(ErrorKind::too_large, "vertex id beyond " + std::to_string(max_vertices));
      advance();
    }
    if (!at_end() && !ends_token(peek()))
      fail(ErrorKind::syntax, "a vertex id (a whole number) was expected, found " + token_from(start));
    return value;
  }
  void expect(char c, const char* what) {
    if (peek() != c) fail(ErrorKind::syntax, std::string(what) + " was expected, found " + found());
    advance();
  }
  [[nodiscard]] std::string found() const {
    if (at_end()) return "the end of the file";
    if (peek() == '\n' || peek() == '\r') return "the end of the line";
    return token_from(pos_);
  }
  [[noreturn]] void fail(ErrorKind kind, const std::string& message) const {
    throw IoError(kind, file_, line_, message);
  }
  // The text from `start` to the next blank or line end (at most 16 characters), quoted.
  [[nodiscard]] std::string token_from(std::size_t start) const {
    std::size_t end = start;
    while (end < data_.size() && end - start < 16 && !std::isspace(static_cast<unsigned char>(data_[end])))
      ++end;
    return quoted(data_.substr(start, std::max<std::size_t>(end - start, 1)));
  }
  [[nodiscard]] static bool ends_token(char c) {
    return std::isspace(static_cast<unsigned char>(c)) || c == ',' || c == ']' || c == '#';
  }

 private:
  std::string_view data_;
  const std::string& file_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
};

// One tet per line: four ids separated by blanks and/or one comma.
std::vector<ListedTet> read_plain(Cursor& c) {
  std::vector<ListedTet> tets;
  for (c.skip_blanks(true, false); !c.at_end(); c.skip_blanks(true, false)) {
    ListedTet t{{}, c.line()};
    for (std::size_t k = 0; k < 4; ++k) {
      if (k > 0) {
        c.skip_blanks(true, true);
        if (c.peek() == ',') c.advance();
        c.skip_blanks(true, true);
      }
      t.ids[k] = c.id();
    }
    c.skip_blanks(true, true);
    if (c.peek() == ',') c.advance();  // a trailing separator
    c.skip_blanks(true, true);
    if (!c.at_end() && c.peek() != '\n' && c.peek() != '\r')
      c.fail(ErrorKind::count_mismatch, "a tet has four vertex ids; more were found on this line");
    tets.push_back(t);
  }
  return tets;
}

// `[[a,b,c,d],...]` after an optional label `NAME =`.
std::vector<ListedTet> read_bracketed(Cursor& c, std::string& label) {
  c.skip_blanks(false, false);
  while (!c.at_end() && c.peek() != '=' && c.peek() != '[') {
    label += c.peek();
    c.advance();
  }
  while (!label.empty() && std::isspace(static_cast<unsigned char>(label.back()))) label.pop_back();
  if (c.peek() == '=') c.advance();
  c.skip_blanks(false, false);
  c.expect('[', "'[' (the list of tets)");
  std::vector<ListedTet> tets;
  c.skip_blanks(false, false);
  while (c.peek() != ']') {
    if (!tets.empty()) {
      c.expect(',', "',' or ']' after a tet");
      c.skip_blanks(false, false);
    }
    ListedTet t{{}, c.line()};
    c.expect('[', "'[' (a tet)");
    for (std::size_t k = 0; k < 4; ++k) {
      c.skip_blanks(false, false);
      if (k > 0) {
        c.expect(',', "',' (a tet has four vertex ids)");
        c.skip_blanks(false, false);
      }
      t.ids[k] = c.id();
    }
    c.skip_blanks(false, false);
    c.expect(']', "']' (a tet has four vertex ids)");
    tets.push_back(t);
    c.skip_blanks(false, false);
  }
  c.advance();
  c.skip_blanks(false, false);
  if (c.peek() == ';') c.advance();
  c.skip_blanks(false, false);
  if (!c.at_end()) c.fail(ErrorKind::syntax, "nothing may follow the list of tets, found " + c.found());
  return tets;
}

// Ids from 0 or 1 without gaps, distinct within a tet, no tet twice; fills `out`.
void check_and_number(const std::vector<ListedTet>& listed, const std::string& file, FacetList& out) {
  if (listed.empty()) throw IoError(ErrorKind::truncated, file, 0, "no tets");
  std::uint64_t lo = std::numeric_limits<std::uint64_t>::max(), hi = 0;
  for (const ListedTet& t : listed)
    for (std::uint64_t v : t.ids) lo = std::min(lo, v), hi = std::max(hi, v);
  if (lo > 1)
    throw IoError(ErrorKind::index_out_of_range, file, 0,
                  "the smallest vertex id is " + std::to_string(lo) + "; ids number from 0 or from 1");
  out.one_based = lo == 1;
  // Every id must occur: more ids than the tets list means a gap, found before anything is
  // allocated per id (a single large id must not cost memory).
  if (hi - lo + 1 > 4 * std::uint64_t(listed.size()))
    throw IoError(ErrorKind::count_mismatch, file, 0,
                  "ids run to " + std::to_string(hi) + " but the " + std::to_string(listed.size()) +
                      " tets name at most " + std::to_string(4 * listed.size()) + " vertices: some id is in no tet");
  out.vertex_count = std::size_t(hi - lo + 1);
  std::vector<char> used(out.vertex_count, 0);
  std::vector<std::pair<Ids, std::size_t>> sorted;
  sorted.reserve(listed.size());
  for (const ListedTet& t : listed) {
    Ids s = t.ids;
    std::sort(s.begin(), s.end());
    if (std::adjacent_find(s.begin(), s.end()) != s.end())
      throw IoError(ErrorKind::degenerate_tet, file, t.line, "a tet lists vertex " + std::to_string(*std::adjacent_find(s.begin(), s.end())) + " twice");
    sorted.emplace_back(s, t.line);
    std::array<std::uint32_t, 4> tet{};
    for (std::size_t k = 0; k < 4; ++k) {
      tet[k] = static_cast<std::uint32_t>(t.ids[k] - lo);
      used[tet[k]] = 1;
    }
    out.tets.push_back(tet);
  }
  for (std::size_t v = 0; v < used.size(); ++v)
    if (!used[v])
      throw IoError(ErrorKind::count_mismatch, file, 0,
                    "vertex " + std::to_string(v + lo) + " is in no tet (ids must run from " + std::to_string(lo) +
                        " to the largest, " + std::to_string(hi) + ", without gaps)");
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 1; i < sorted.size(); ++i)
    if (sorted[i].first == sorted[i - 1].first)
      throw IoError(ErrorKind::duplicate, file, std::max(sorted[i].second, sorted[i - 1].second),
                    "the tet of line " + std::to_string(std::min(sorted[i].second, sorted[i - 1].second)) +
                        " is listed again");
}

}  // namespace

FacetList read_facet_list(std::string_view bytes, const std::string& name) {
  Cursor c(bytes, name);
  FacetList out;
  const bool bracketed = bytes.find('[') != std::string_view::npos;
  const std::vector<ListedTet> listed = bracketed ? read_bracketed(c, out.label) : read_plain(c);
  check_and_number(listed, name, out);
  return out;
}

FacetList read_facet_list_file(const std::string& path) { return read_facet_list(read_file_bytes(path), path); }

bool is_facet_list_path(const std::string& path) { return extension_of(path) == "facets"; }

}  // namespace cmx::io
