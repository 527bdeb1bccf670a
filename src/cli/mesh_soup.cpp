// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// The readers of mesh_soup.h, written from the format descriptions (Geomview's
// OFF, Wavefront OBJ, Greg Turk's PLY, STL). Two cursors serve every format:
// Text_cursor (the tokens of a text, with the line number) and Byte_reader
// (the values of a binary body, in either byte order, with the offset). The
// rule that keeps hostile files harmless: no count from a file reaches
// reserve() or a loop before it was checked against the bytes left.
#include "mesh_soup.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <new>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <utility>

namespace cgal_subdiv {
namespace {

/// the meshes built from a soup use 32-bit indices
constexpr unsigned long long max_vertices = 0xFFFFFFFFull;

// ---------------------------------------------------------------------------
// The text of the messages

/// `text` as a message can show it: at most 40 characters, control and
/// non-ASCII bytes as \xNN (a hostile file may hold anything)
std::string clipped(std::string_view text)
{
  constexpr std::size_t max_shown = 40;
  std::string out;
  for(std::size_t i = 0; i < text.size() && i < max_shown; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if(c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", static_cast<unsigned>(c));
      out += hex;
    }
  }
  if(text.size() > max_shown)
    out += "...";
  return out;
}

/// a token of the file, quoted: 'abc'
std::string shown(std::string_view text)
{
  return "'" + clipped(text) + "'";
}

/// the name of the file, quoted
std::string quoted(const std::string& name)
{
  return "'" + name + "'";
}

/// "1 vertex", "2 vertices"
std::string count_of(unsigned long long n, const char* one, const char* many)
{
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

/// "vertex 3", "face 0": what the messages are about
std::string numbered(const char* what, unsigned long long number)
{
  return what + (" " + std::to_string(number));
}

/// a binary value as the message shows it: "nan", "inf", "1.5"
std::string written(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

std::string not_finite(const std::string& item, const std::string& value)
{
  return item + " has the coordinate " + value + ", which is not a finite number";
}

std::string too_few_vertices(std::size_t face, const std::string& count)
{
  return "face " + std::to_string(face) + " has " + count + (count == "1" ? " vertex" : " vertices") +
         " (a face needs at least 3)";
}

/// what the index of a face corner refers to, as the messages name it
struct Index_kind
{
  const char *one, *many, *keyword; // the keyword of the lines listing them in OBJ
};
const Index_kind vertex_kind{"vertex", "vertices", "v"};
const Index_kind texture_kind{"texture coordinate", "texture coordinates", "vt"};
const Index_kind normal_kind{"normal", "normals", "vn"};

/// `index` as the file wrote it; `count` counted as the file does, from 0 or 1
std::string index_out_of_range(std::size_t face, const std::string& index, std::size_t count, bool from_one,
                               const Index_kind& kind = vertex_kind)
{
  const std::string range =
    count == 0 ? "no " + std::string(kind.many)
               : count_of(count, kind.one, kind.many) + " (" +
                   (from_one ? "1 to " + std::to_string(count) : "0 to " + std::to_string(count - 1)) + ")";
  return "face " + std::to_string(face) + " has " + kind.one + " index " + index + ", but the file has " + range;
}

std::string count_too_large(const std::string& counts, std::size_t bytes_left)
{
  return "header says " + counts + ", but the file has only " + count_of(bytes_left, "byte", "bytes") +
         " after the header (truncated, or the counts are wrong)";
}

std::string too_many_vertices(unsigned long long count)
{
  return "header says " + std::to_string(count) + " vertices: more than " + std::to_string(max_vertices) +
         " are not supported (the meshes use 32-bit indices)";
}

/// the end of a message refusing a count in the body
std::string but_only_left(std::size_t bytes_left)
{
  return ", but only " + count_of(bytes_left, "byte is", "bytes are") + " left (truncated, or the count is wrong)";
}

// ---------------------------------------------------------------------------
// Numbers: std::from_chars (no locale, no exceptions), the whole token

/// true if `text`, a decimal that std::from_chars found out of range, is
/// tiny (an underflow, read as 0) rather than huge (an overflow)
bool underflows(std::string_view text)
{
  std::size_t i = (!text.empty() && (text[0] == '-' || text[0] == '+')) ? 1 : 0;
  long long integer_digits = 0, digits = 0, first_nonzero = -1;
  bool after_point = false;
  for(; i < text.size(); ++i) {
    const char c = text[i];
    if(c == '.') {
      after_point = true;
      continue;
    }
    if(c < '0' || c > '9')
      break;
    if(first_nonzero < 0 && c != '0')
      first_nonzero = digits;
    ++digits;
    if(!after_point)
      ++integer_digits;
  }
  long long exponent = 0;
  if(i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    const bool negative = i < text.size() && text[i] == '-';
    if(i < text.size() && (text[i] == '-' || text[i] == '+'))
      ++i;
    for(; i < text.size() && exponent < 1000000000; ++i)
      exponent = 10 * exponent + (text[i] - '0');
    if(negative)
      exponent = -exponent;
  }
  // the decimal exponent of the first nonzero digit
  const long long magnitude = integer_digits - 1 - first_nonzero + exponent;
  return first_nonzero < 0 || magnitude < 0;
}

/// a leading '+' is fine in the files, not for std::from_chars
std::string_view without_plus(std::string_view text)
{
  if(text.size() > 1 && text[0] == '+' && text[1] != '+' && text[1] != '-')
    text.remove_prefix(1);
  return text;
}

/// parses all of `text` as a decimal; a value too large for a double becomes
/// an infinity (which the callers refuse), one too small becomes 0
bool parse_real(std::string_view text, double& value)
{
  text = without_plus(text);
  if(text.empty())
    return false;
  const char* end = text.data() + text.size();
  const std::from_chars_result result = std::from_chars(text.data(), end, value);
  if(result.ptr != end)
    return false;
  if(result.ec == std::errc::result_out_of_range) {
    value = underflows(text) ? 0.0 : std::numeric_limits<double>::infinity();
    if(text[0] == '-')
      value = -value;
    return true;
  }
  return result.ec == std::errc();
}

enum class Integer { ok, invalid, too_large };

/// parses all of `text` as a decimal integer; one beyond long long is
/// `too_large`, `value` then the extreme of its sign
Integer parse_integer(std::string_view text, long long& value)
{
  text = without_plus(text);
  if(text.empty())
    return Integer::invalid;
  const char* end = text.data() + text.size();
  const std::from_chars_result result = std::from_chars(text.data(), end, value);
  if(result.ptr != end)
    return Integer::invalid;
  if(result.ec == std::errc::result_out_of_range) {
    value = text[0] == '-' ? std::numeric_limits<long long>::min() : std::numeric_limits<long long>::max();
    return Integer::too_large;
  }
  return result.ec == std::errc() ? Integer::ok : Integer::invalid;
}

/// ASCII letters compared without case: the keywords of ASCII STL
bool same_word(std::string_view text, std::string_view word)
{
  if(text.size() != word.size())
    return false;
  for(std::size_t i = 0; i < text.size(); ++i) {
    const char a = text[i] >= 'A' && text[i] <= 'Z' ? static_cast<char>(text[i] - 'A' + 'a') : text[i];
    if(a != word[i])
      return false;
  }
  return true;
}

// ---------------------------------------------------------------------------
// Text_cursor: the tokens of a text file, with the line number

bool is_blank(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/*
 * Walks a text from a start offset: tokens are separated by blanks (a '\r'
 * is one, so that Windows line endings need nothing special); a comment
 * character (none: '\0') starts a comment to the end of the line. The cursor
 * stays on its line until next_line() or token(), which cross newlines, so
 * that line() is the line of the token last read. Copying it is cheap: a
 * copy looks ahead.
 */
class Text_cursor
{
public:
  Text_cursor(const char* data, std::size_t size, const std::string& name, char comment)
    : m_data(data), m_size(size), m_name(&name), m_comment(comment)
  {}

  std::size_t line() const { return m_line; }
  std::size_t offset() const { return m_pos; }
  std::size_t bytes_left() const { return m_size - m_pos; }
  const std::string& name() const { return *m_name; }

  /// the next token of the current line; empty at its end or at a comment
  std::string_view token_on_line()
  {
    skip_blanks_and_comment();
    const std::size_t begin = m_pos;
    while(m_pos < m_size && !ends_token(m_data[m_pos]))
      ++m_pos;
    return std::string_view(m_data + begin, m_pos - begin);
  }

  /// true if only blanks or a comment are left on the current line
  bool line_done()
  {
    skip_blanks_and_comment();
    return m_pos == m_size || m_data[m_pos] == '\n';
  }

  /// the number of tokens left on the current line (the cursor does not move)
  std::size_t tokens_left_on_line() const
  {
    Text_cursor probe = *this;
    std::size_t count = 0;
    while(!probe.token_on_line().empty())
      ++count;
    return count;
  }

  /// the text left on the current line before a comment, without the blanks
  /// around it (the cursor does not move)
  std::string_view rest_of_line() const
  {
    Text_cursor probe = *this;
    probe.skip_blanks_and_comment();
    const std::size_t begin = probe.m_pos;
    std::size_t end = begin;
    while(end < m_size && m_data[end] != '\n' && !is_comment(m_data[end]))
      ++end;
    while(end > begin && is_blank(m_data[end - 1]))
      --end;
    return std::string_view(m_data + begin, end - begin);
  }

  /// moves past the end of the current line (a newline that ends the text
  /// starts no line: the end of the text is then on the last line)
  void next_line()
  {
    const void* newline = std::memchr(m_data + m_pos, '\n', m_size - m_pos);
    if(newline == nullptr) {
      m_pos = m_size;
      return;
    }
    m_pos = static_cast<std::size_t>(static_cast<const char*>(newline) - m_data) + 1;
    if(m_pos < m_size)
      ++m_line;
  }

  /// moves to the next token, across blank lines and comments; false at the
  /// end of the text
  bool skip_to_token()
  {
    while(line_done()) {
      if(m_pos == m_size)
        return false;
      next_line();
    }
    return true;
  }

  /// the next token, across lines; empty at the end of the text
  std::string_view token()
  {
    if(!skip_to_token())
      return std::string_view();
    return token_on_line();
  }

  [[noreturn]] void fail(const std::string& what) const { fail_at_line(m_line, what); }
  [[noreturn]] void fail_at_line(std::size_t line, const std::string& what) const
  {
    throw Input_error(quoted(*m_name) + " line " + std::to_string(line) + ": " + what);
  }

private:
  bool is_comment(char c) const { return m_comment != '\0' && c == m_comment; }
  bool ends_token(char c) const { return is_blank(c) || c == '\n' || is_comment(c); }

  void skip_blanks_and_comment()
  {
    while(m_pos < m_size && is_blank(m_data[m_pos]))
      ++m_pos;
    if(m_pos < m_size && is_comment(m_data[m_pos]))
      while(m_pos < m_size && m_data[m_pos] != '\n')
        ++m_pos;
  }

  const char* m_data;
  std::size_t m_size;
  const std::string* m_name;
  char m_comment;
  std::size_t m_pos = 0;
  std::size_t m_line = 1;
};

// ---------------------------------------------------------------------------
// Byte_reader: the values of a binary body, with the byte offset

class Byte_reader
{
public:
  Byte_reader(const char* data, std::size_t size, std::size_t start, bool big_endian, const std::string& name)
    : m_data(data), m_size(size), m_pos(start < size ? start : size), m_big_endian(big_endian), m_name(&name)
  {}

  std::size_t offset() const { return m_pos; }
  std::size_t bytes_left() const { return m_size - m_pos; }

  /// refuses the file as truncated inside `describe()` (called only then)
  /// if fewer than `n` bytes are left
  template <class Describe>
  void need(std::size_t n, Describe describe) const
  {
    if(n > bytes_left())
      fail("the file ends inside " + describe() + " (truncated)");
  }

  /// the next `n` bytes (1 to 8) as an unsigned integer in the file's byte order
  std::uint64_t take_unsigned(std::size_t n)
  {
    need_some(n);
    std::uint64_t value = 0;
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t at = m_pos + (m_big_endian ? i : n - 1 - i);
      value = (value << 8) | static_cast<unsigned char>(m_data[at]);
    }
    m_pos += n;
    return value;
  }

  /// the next `n` bytes (1 to 4) as a two's complement integer
  std::int64_t take_signed(std::size_t n)
  {
    const std::uint64_t sign = std::uint64_t(1) << (8 * n - 1);
    return static_cast<std::int64_t>(take_unsigned(n) ^ sign) - static_cast<std::int64_t>(sign);
  }

  std::int32_t take_int32() { return static_cast<std::int32_t>(take_signed(4)); }

  float take_float32()
  {
    const std::uint32_t bits = static_cast<std::uint32_t>(take_unsigned(4));
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }

  double take_float64()
  {
    const std::uint64_t bits = take_unsigned(8);
    double value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }

  void skip(std::size_t n)
  {
    need_some(n);
    m_pos += n;
  }

  [[noreturn]] void fail(const std::string& what) const { fail_at(m_pos, what); }
  [[noreturn]] void fail_at(std::size_t offset, const std::string& what) const
  {
    throw Input_error(quoted(*m_name) + " byte " + std::to_string(offset) + ": " + what);
  }

private:
  void need_some(std::size_t n) const
  {
    if(n > bytes_left())
      fail("the file ends here (truncated)");
  }

  const char* m_data;
  std::size_t m_size;
  std::size_t m_pos;
  bool m_big_endian;
  const std::string* m_name;
};

/// the soup's face whose indices were pushed since the last one ends here
void end_face(Mesh_soup& soup)
{
  soup.face_starts.push_back(soup.indices.size());
}

/// a colour component as a file writes it, an integer from 0 to 255 or a
/// real from 0 to 1 (scaled to 0 to 255 and rounded); false if it is out of
/// that range
bool colour_component(double value, bool integer, unsigned char& component)
{
  if(!(value >= 0 && value <= (integer ? 255 : 1)))
    return false;
  component = static_cast<unsigned char>(std::lround(integer ? value : value * 255));
  return true;
}

const char* const colour_range = "integers from 0 to 255, or reals from 0 to 1";

// ---------------------------------------------------------------------------
// OFF (Geomview): [ST][C][N][4][n]OFF [BINARY], counts, vertices, faces

/*
 * x y z of vertex `number` from the current line of `text` (OFF and OBJ
 * vertex lines); what follows on the line is left for the caller to ignore,
 * and `extra_values_line` gets the first line that has some (0: none yet).
 */
std::array<double, 3> read_point_on_line(Text_cursor& text, std::size_t number, std::size_t& extra_values_line)
{
  std::array<double, 3> p{};
  for(int axis = 0; axis < 3; ++axis) {
    const std::string_view token = text.token_on_line();
    if(token.empty())
      text.fail(numbered("vertex", number) + " has only " + count_of(axis, "coordinate", "coordinates") +
                " (expected x y z)");
    if(!parse_real(token, p[axis]))
      text.fail(numbered("vertex", number) + ": expected a coordinate, found " + shown(token));
    if(!std::isfinite(p[axis]))
      text.fail(not_finite(numbered("vertex", number), clipped(token)));
  }
  if(!text.line_done() && extra_values_line == 0)
    extra_values_line = text.line();
  return p;
}

/// what the keyword of an OFF file says
struct Off_keyword
{
  bool texture = false, colour = false, normal = false, four = false, dimension = false, binary = false;
};

/// reads "[ST][C][N][4][n]OFF" (ST, C and N in any order); false if `word` is
/// no OFF keyword
bool parse_off_keyword(std::string_view word, Off_keyword& keyword)
{
  if(word.size() < 3 || word.substr(word.size() - 3) != "OFF")
    return false;
  std::string_view prefix = word.substr(0, word.size() - 3);
  auto take = [&prefix](std::string_view flag, bool& seen) {
    if(seen || prefix.substr(0, flag.size()) != flag)
      return false;
    prefix.remove_prefix(flag.size());
    return seen = true;
  };
  while(take("ST", keyword.texture) || take("C", keyword.colour) || take("N", keyword.normal)) {
  }
  take("4", keyword.four);
  take("n", keyword.dimension);
  return prefix.empty();
}

class Off_reader
{
public:
  Off_reader(const char* data, std::size_t size, const std::string& name)
    : m_data(data), m_size(size), m_text(data, size, name, '#')
  {}

  Mesh_soup read()
  {
    read_keyword();
    if(m_keyword.binary) {
      read_binary();
    } else {
      read_ascii_counts();
      read_ascii_vertices();
      read_ascii_faces();
      note_ascii_trailer();
    }
    note_ignored_values();
    if(!m_trailer.empty())
      m_soup.notes.push_back(m_trailer);
    return std::move(m_soup);
  }

private:
  const std::string& name() const { return m_text.name(); }

  void read_keyword()
  {
    const std::string_view word = m_text.token();
    if(word.empty())
      m_text.fail("the file is empty (no OFF keyword)");
    if(!parse_off_keyword(word, m_keyword))
      m_text.fail("expected the keyword OFF (or COFF, NOFF, STOFF, nOFF, OFF BINARY, ...), found " + shown(word));
    if(m_keyword.four)
      m_text.fail("4D points are not supported (the keyword " + shown(word) + " says 4 coordinates)");
    Text_cursor probe = m_text;
    if(probe.token_on_line() == "BINARY") {
      m_keyword.binary = true;
      m_text = probe;
    }
  }

  /// a count of the header, on the keyword line or the next lines
  unsigned long long read_ascii_count(const char* what)
  {
    const std::string_view token = m_text.token();
    if(token.empty())
      m_text.fail(std::string("the file ends before the ") + what + " (truncated)");
    long long value = 0;
    const Integer status = parse_integer(token, value);
    if(status == Integer::invalid)
      m_text.fail(std::string("expected the ") + what + ", found " + shown(token));
    if(value < 0)
      m_text.fail(std::string("the ") + what + " " + clipped(token) + " is negative");
    if(status == Integer::too_large)
      m_text.fail(std::string("the ") + what + " " + clipped(token) + " is too large");
    return static_cast<unsigned long long>(value);
  }

  void read_ascii_counts()
  {
    if(m_keyword.dimension) {
      const unsigned long long dimension = read_ascii_count("dimension of nOFF");
      if(dimension != 3)
        m_text.fail("nOFF points of dimension " + std::to_string(dimension) + " are not supported (only 3)");
    }
    m_vertices = read_ascii_count("vertex count");
    m_faces = read_ascii_count("face count");
    if(!m_text.line_done()) // the edge count: optional, ignored
      read_ascii_count("edge count");
    if(!m_text.line_done())
      m_text.fail("unexpected " + shown(m_text.token_on_line()) + " after the counts");
    // at least "\n0 0 0" per vertex and "\n3 0 0 0" per face
    check_counts(m_text.bytes_left(), 6, 8, [this](const std::string& what) { m_text.fail(what); });
  }

  /// refuses counts that `bytes_left` cannot hold with at least the given
  /// bytes per vertex and per face, then reserves the soup
  template <class Fail>
  void check_counts(std::size_t bytes_left, std::size_t vertex_bytes, std::size_t face_bytes, Fail fail)
  {
    if(m_vertices > max_vertices)
      fail(too_many_vertices(m_vertices));
    if(m_vertices > bytes_left / vertex_bytes)
      fail(count_too_large(count_of(m_vertices, "vertex", "vertices"), bytes_left));
    const std::size_t after_vertices = bytes_left - m_vertices * vertex_bytes;
    if(m_faces > after_vertices / face_bytes)
      fail(count_too_large(count_of(m_vertices, "vertex", "vertices") + " and " + count_of(m_faces, "face", "faces"),
                           bytes_left));
    m_soup.points.reserve(m_vertices);
    m_soup.face_starts.reserve(m_faces + 1);
    m_soup.indices.reserve(3 * m_faces);
  }

  void read_ascii_vertices()
  {
    for(std::size_t v = 0; v < m_vertices; ++v) {
      m_text.next_line();
      if(!m_text.skip_to_token())
        m_text.fail("the file ends after " + std::to_string(v) + " of the " + std::to_string(m_vertices) +
                    " vertices (truncated)");
      read_ascii_vertex(v);
    }
  }

  /// one vertex line: x y z, then whatever the keyword announced (the
  /// colour is kept, the rest ignored)
  void read_ascii_vertex(std::size_t v)
  {
    m_soup.points.push_back(read_point_on_line(m_text, v, m_extra_vertex_values_line));
    if(m_keyword.colour && m_colours_missing.empty())
      read_ascii_colour(v);
  }

  /// COFF: the colour of vertex `v`, after x y z and the normal (N), before
  /// the texture coordinates (ST): red green blue [alpha]. A line without
  /// one (as Geomview's optional values allow) makes the file's colours
  /// ignored, with a note; a component that is not one is an error.
  void read_ascii_colour(std::size_t v)
  {
    constexpr std::size_t most = 9; // the normal, the colour and the texture coordinates
    std::array<std::string_view, most> tokens;
    std::size_t count = 0;
    for(std::string_view token = m_text.token_on_line(); !token.empty(); token = m_text.token_on_line())
      if(count++ < most)
        tokens[count - 1] = token;
    const std::size_t first = m_keyword.normal ? 3 : 0;
    const std::size_t last = count - (m_keyword.texture ? std::min<std::size_t>(count, 2) : 0);
    if(last < first + 3 || last > first + 4) {
      m_colours_missing = numbered("vertex", v) + " (line " + std::to_string(m_text.line()) + ") has " +
                          count_of(last > first ? last - first : 0, "colour component", "colour components") +
                          " (expected red green blue [alpha])";
      m_soup.colours.clear();
      return;
    }
    // reals from 0 to 1 if any component is written as one, else integers
    // from 0 to 255
    bool integers = true;
    for(std::size_t k = first; k < last; ++k)
      integers = integers && tokens[k].find_first_of(".eE") == std::string_view::npos;
    std::array<unsigned char, 4> colour = {0, 0, 0, 255};
    for(std::size_t k = first; k < last; ++k) {
      double value = 0;
      if(!parse_real(tokens[k], value))
        m_text.fail(numbered("vertex", v) + ": expected a colour component, found " + shown(tokens[k]));
      if(!colour_component(value, integers, colour[k - first]))
        m_text.fail(numbered("vertex", v) + ": the colour component " + shown(tokens[k]) + " is out of range (" +
                    colour_range + ")");
    }
    m_soup.colours.push_back(colour);
  }

  void read_ascii_faces()
  {
    for(std::size_t f = 0; f < m_faces; ++f) {
      m_text.next_line();
      if(!m_text.skip_to_token())
        m_text.fail("the file ends after " + std::to_string(f) + " of the " + std::to_string(m_faces) +
                    " faces (truncated)");
      read_ascii_face(f);
    }
  }

  /// one face line: n i1 ... in, then colour values (ignored)
  void read_ascii_face(std::size_t f)
  {
    const std::string_view count = m_text.token_on_line();
    long long n = 0;
    if(parse_integer(count, n) == Integer::invalid)
      m_text.fail(numbered("face", f) + ": expected its number of vertices, found " + shown(count));
    if(n < 3)
      m_text.fail(too_few_vertices(f, clipped(count)));
    for(long long i = 0; i < n; ++i) {
      const std::string_view token = m_text.token_on_line();
      if(token.empty())
        m_text.fail(numbered("face", f) + " has only " + std::to_string(i) + " of its " + clipped(count) +
                    " vertex indices on its line");
      long long index = 0;
      if(parse_integer(token, index) == Integer::invalid)
        m_text.fail(numbered("face", f) + ": expected a vertex index, found " + shown(token));
      if(index < 0 || static_cast<unsigned long long>(index) >= m_vertices)
        m_text.fail(index_out_of_range(f, clipped(token), m_vertices, false));
      m_soup.indices.push_back(static_cast<std::size_t>(index));
    }
    if(!m_text.line_done())
      m_face_colours = true;
    end_face(m_soup);
  }

  void note_ascii_trailer()
  {
    m_text.next_line();
    if(m_text.skip_to_token())
      m_trailer = "ignored the text after the last face of " + quoted(name()) + " (from line " +
                  std::to_string(m_text.line()) + ")";
  }

  /// Geomview's binary OFF: big-endian int32 counts, float32 coordinates
  void read_binary()
  {
    if(!m_text.line_done())
      m_text.fail("unexpected " + shown(m_text.token_on_line()) + " after BINARY");
    m_text.next_line(); // the binary body starts right after the newline
    Byte_reader in(m_data, m_size, m_text.offset(), true, name());
    if(m_keyword.dimension) {
      const std::size_t at = in.offset();
      in.need(4, [] { return std::string("the dimension of nOFF"); });
      const std::int32_t dimension = in.take_int32();
      if(dimension != 3)
        in.fail_at(at, "nOFF points of dimension " + std::to_string(dimension) + " are not supported (only 3)");
    }
    m_vertices = read_binary_count(in, "vertex count");
    m_faces = read_binary_count(in, "face count");
    read_binary_count(in, "edge count");
    const std::size_t vertex_bytes =
      4 * (3 + (m_keyword.normal ? 3 : 0) + (m_keyword.colour ? 4 : 0) + (m_keyword.texture ? 2 : 0));
    // a face: its count, 3 indices, its number of colour components
    check_counts(in.bytes_left(), vertex_bytes, 20, [&in](const std::string& what) { in.fail(what); });
    for(std::size_t v = 0; v < m_vertices; ++v)
      read_binary_vertex(in, v, vertex_bytes);
    for(std::size_t f = 0; f < m_faces; ++f)
      read_binary_face(in, f);
    if(in.bytes_left() > 0)
      m_trailer = "ignored " + count_of(in.bytes_left(), "byte", "bytes") + " after the last face of " + quoted(name());
    if(m_vertices > 0 && vertex_bytes > 12)
      m_extra_vertex_values_line = 1;
  }

  unsigned long long read_binary_count(Byte_reader& in, const char* what)
  {
    in.need(4, [what] { return std::string("the ") + what + " of the header"; });
    const std::size_t at = in.offset();
    const std::int32_t count = in.take_int32();
    if(count < 0)
      in.fail_at(at, std::string("the ") + what + " " + std::to_string(count) + " is negative");
    return static_cast<unsigned long long>(count);
  }

  void read_binary_vertex(Byte_reader& in, std::size_t v, std::size_t vertex_bytes)
  {
    std::array<double, 3> p{};
    for(int axis = 0; axis < 3; ++axis) {
      const std::size_t at = in.offset();
      p[axis] = in.take_float32();
      if(!std::isfinite(p[axis]))
        in.fail_at(at, not_finite(numbered("vertex", v), written(p[axis])));
    }
    in.skip(vertex_bytes - 12);
    m_soup.points.push_back(p);
  }

  void read_binary_face(Byte_reader& in, std::size_t f)
  {
    const std::size_t at = in.offset();
    in.need(4, [f] { return numbered("face", f); });
    const std::int32_t n = in.take_int32();
    if(n < 3)
      in.fail_at(at, too_few_vertices(f, std::to_string(n)));
    if(static_cast<std::size_t>(n) > in.bytes_left() / 4)
      in.fail_at(
        at, numbered("face", f) + " says it has " + std::to_string(n) + " vertices" + but_only_left(in.bytes_left()));
    for(std::int32_t i = 0; i < n; ++i) {
      const std::size_t index_at = in.offset();
      const std::int32_t index = in.take_int32();
      if(index < 0 || static_cast<unsigned long long>(index) >= m_vertices)
        in.fail_at(index_at, index_out_of_range(f, std::to_string(index), m_vertices, false));
      m_soup.indices.push_back(static_cast<std::size_t>(index));
    }
    const std::size_t colours_at = in.offset();
    in.need(4, [f] { return numbered("face", f) + " (its number of colour components)"; });
    const std::int32_t colours = in.take_int32();
    if(colours < 0 || colours > 4)
      in.fail_at(colours_at,
                 numbered("face", f) + " has " + std::to_string(colours) + " colour components (expected 0 to 4)");
    in.need(4 * static_cast<std::size_t>(colours), [f] { return numbered("face", f) + " (its colour)"; });
    in.skip(4 * static_cast<std::size_t>(colours));
    if(colours > 0)
      m_face_colours = true;
    end_face(m_soup);
  }

  void note_ignored_values()
  {
    const std::string of = " of " + quoted(name());
    if(m_extra_vertex_values_line != 0) {
      if(m_keyword.normal)
        m_soup.notes.push_back("ignored the vertex normals" + of);
      if(m_keyword.colour && m_keyword.binary)
        m_soup.notes.push_back("ignored the vertex colours" + of);
      if(m_keyword.texture)
        m_soup.notes.push_back("ignored the vertex texture coordinates" + of);
      if(!m_keyword.normal && !m_keyword.colour && !m_keyword.texture)
        m_soup.notes.push_back("ignored the values after x y z on the vertex lines" + of + " (from line " +
                               std::to_string(m_extra_vertex_values_line) + ")");
    }
    if(!m_colours_missing.empty())
      m_soup.notes.push_back("ignored the vertex colours" + of + ": " + m_colours_missing);
    if(m_face_colours)
      m_soup.notes.push_back("ignored the face colours" + of);
  }

  const char* m_data;
  std::size_t m_size;
  Text_cursor m_text;
  Off_keyword m_keyword;
  unsigned long long m_vertices = 0, m_faces = 0;
  std::size_t m_extra_vertex_values_line = 0; // the first line with values after x y z
  std::string m_colours_missing;              // why the vertex colours are ignored (COFF)
  bool m_face_colours = false;
  std::string m_trailer; // the note on what follows the last face, if anything
  Mesh_soup m_soup;
};

// ---------------------------------------------------------------------------
// OBJ (Wavefront): one statement per line, indices from 1 or negative

class Obj_reader
{
public:
  Obj_reader(const char* data, std::size_t size, const std::string& name)
    : m_data(data), m_size(size), m_text(data, size, name, '#')
  {}

  Mesh_soup read()
  {
    m_soup.tags.reserve(possible_tags());
    while(m_text.skip_to_token()) {
      refuse_continuation();
      read_statement(m_text.token_on_line());
      m_text.next_line();
    }
    check_forward_references();
    note_ignored();
    return std::move(m_soup);
  }

private:
  /// An upper bound of the number of tags: the lines of 10 bytes or more
  /// that start with "t ". A tag takes some 112 bytes, for a line of 10 bytes
  /// at least ("t a 0/0/0\n"): reserved exactly, the tags do not take the
  /// memory above 16 times the size of the file, as vector growth would.
  std::size_t possible_tags() const
  {
    std::size_t count = 0;
    for(std::size_t begin = 0; begin < m_size;) {
      const void* newline = std::memchr(m_data + begin, '\n', m_size - begin);
      const std::size_t end = newline ? static_cast<std::size_t>(static_cast<const char*>(newline) - m_data) : m_size;
      std::size_t i = begin;
      while(i < end && is_blank(m_data[i]))
        ++i;
      if(end - i >= 9 && m_data[i] == 't' && is_blank(m_data[i + 1]))
        ++count;
      begin = end + 1;
    }
    return count;
  }

  /// a face that refers to a vertex (or a texture coordinate) defined after it
  /// (positive index): the largest such index, checked against the count at
  /// the end
  struct Forward_reference
  {
    std::size_t face, line;
    unsigned long long index;
  };

  /// The forward references of the faces, in the order of the file, kept only
  /// when larger than every one before: a face whose index is not would never
  /// be the first out of range, an earlier face being so too. Many faces
  /// referring forward then take memory only if their indices keep growing.
  class Forward_references
  {
  public:
    void add(std::size_t face, std::size_t line, unsigned long long index)
    {
      if(m_kept.empty() || index > m_kept.back().index)
        m_kept.push_back(Forward_reference{face, line, index});
    }

    /// the first reference past `count`, or nullptr
    const Forward_reference* first_past(std::size_t count) const
    {
      for(const Forward_reference& reference : m_kept)
        if(reference.index > count)
          return &reference;
      return nullptr;
    }

  private:
    std::vector<Forward_reference> m_kept; // indices increasing
  };

  /// the lines of a statement that the soup does not keep
  struct Ignored
  {
    std::string keyword;
    std::size_t lines;
  };

  void refuse_continuation()
  {
    const std::string_view line = m_text.rest_of_line();
    if(!line.empty() && line.back() == '\\')
      m_text.fail("the line ends with '\\' (line continuations are not supported)");
  }

  void read_statement(std::string_view keyword)
  {
    if(keyword == "v")
      read_vertex();
    else if(keyword == "vt")
      read_texture_point();
    else if(keyword == "vn")
      read_normal();
    else if(keyword == "f")
      read_face();
    else if(keyword == "t")
      read_tag();
    else if(keyword == "o" || keyword == "g" || keyword == "s")
      return; // objects, groups, smoothing groups: nothing a soup keeps
    else
      count_ignored(keyword);
  }

  void read_vertex()
  {
    const std::size_t number = m_soup.points.size() + 1;
    if(m_soup.points.size() == max_vertices)
      m_text.fail("more than " + std::to_string(max_vertices) +
                  " vertices are not supported (the meshes use 32-bit indices)");
    m_soup.points.push_back(read_point_on_line(m_text, number, m_extra_vertex_values_line));
  }

  /// `vt u [v [w]]`: v is 0 if missing, w (a depth, for 3D textures) is dropped
  void read_texture_point()
  {
    refuse_more_than_max(m_soup.texture_points.size(), texture_kind);
    const std::string item = numbered(texture_kind.one, m_soup.texture_points.size() + 1);
    m_soup.texture_points.push_back(read_values<2>(item, 1, 3, "u, u v or u v w"));
  }

  /// `vn x y z`, kept as written: a reference normalises it
  void read_normal()
  {
    refuse_more_than_max(m_soup.normals.size(), normal_kind);
    const std::string item = numbered(normal_kind.one, m_soup.normals.size() + 1);
    m_soup.normals.push_back(read_values<3>(item, 3, 3, "x y z"));
  }

  void refuse_more_than_max(std::size_t so_far, const Index_kind& kind)
  {
    if(so_far == max_vertices)
      m_text.fail("more than " + std::to_string(max_vertices) + " " + kind.many + " (" + kind.keyword +
                  ") are not supported (the meshes use 32-bit indices)");
  }

  /// the values on the rest of the line of `item`: from `fewest` to `most`
  /// finite numbers (`expected` names them), the first `kept` of them returned
  /// (the missing ones 0)
  template <std::size_t kept>
  std::array<double, kept> read_values(const std::string& item, std::size_t fewest, std::size_t most,
                                       const char* expected)
  {
    std::array<double, kept> values{};
    std::size_t count = 0;
    for(std::string_view token = m_text.token_on_line(); !token.empty(); token = m_text.token_on_line(), ++count) {
      if(count == most)
        m_text.fail(item + " has " + std::to_string(most + 1 + m_text.tokens_left_on_line()) + " values (expected " +
                    expected + ")");
      double value = 0;
      if(!parse_real(token, value))
        m_text.fail(item + ": expected a number, found " + shown(token));
      if(!std::isfinite(value))
        m_text.fail(item + " has the value " + clipped(token) + ", which is not a finite number");
      if(count < kept)
        values[count] = value;
    }
    if(count < fewest)
      m_text.fail(item + " has " + (count == 0 ? std::string("no value") : count_of(count, "value", "values")) +
                  " (expected " + expected + ")");
    return values;
  }

  /// a face corner: its vertex, texture coordinate and normal (0: none), from 1
  struct Corner
  {
    unsigned long long vertex, texture, normal;
  };

  /// The references of the faces to one list besides the vertices (vt, vn):
  /// every corner of a face has one, or none has; the soup keeps them (in
  /// `kept`) only if every face has them.
  struct Corner_references
  {
    const Index_kind& kind;
    std::vector<std::size_t>& kept; // the soup's indices of this list
    Forward_references forward;
    bool face_0_has = false;  // whether face 0 has them
    std::size_t mismatch = 0; // the first face that differs from face 0 there (0: none)
  };

  /// what a face being read refers to in one list
  struct Face_references
  {
    bool has = false;
    unsigned long long forward = 0; // the largest index past the list so far
  };

  /// A face: its vertex indices, and those of the lists its corners refer to,
  /// pushed with them as long as every face has them: never more of them than
  /// of those.
  void read_face()
  {
    const std::size_t face = m_soup.number_of_faces();
    std::size_t corners = 0;
    std::string_view first_corner;
    Face_references texture, normal;
    unsigned long long forward = 0; // the largest vertex index past the vertices so far
    for(std::string_view token = m_text.token_on_line(); !token.empty(); token = m_text.token_on_line()) {
      const Corner corner = corner_of(token, face);
      if(corners == 0)
        first_corner = token;
      add_reference(m_texture, texture, face, corners, corner.texture, m_soup.texture_points.size(),
                    {first_corner, token});
      add_reference(m_normal, normal, face, corners, corner.normal, m_soup.normals.size(), {first_corner, token});
      if(corner.vertex > m_soup.points.size() && corner.vertex > forward)
        forward = corner.vertex;
      m_soup.indices.push_back(static_cast<std::size_t>(corner.vertex - 1));
      ++corners;
    }
    if(corners < 3)
      m_text.fail(too_few_vertices(face, std::to_string(corners)));
    if(forward != 0)
      m_forward.add(face, m_text.line(), forward);
    end_references(m_texture, texture, face);
    end_references(m_normal, normal, face);
    end_face(m_soup);
  }

  /// the reference `index` (0: none) of corner `corner` of `face` to a list
  /// of `so_far` values; `tokens`: the face's first corner and this one
  void add_reference(Corner_references& references, Face_references& in_face, std::size_t face, std::size_t corner,
                     unsigned long long index, std::size_t so_far, const std::array<std::string_view, 2>& tokens)
  {
    if(corner == 0) {
      in_face.has = index != 0;
    } else if((index != 0) != in_face.has) {
      const std::string_view without = in_face.has ? tokens[1] : tokens[0], with = in_face.has ? tokens[0] : tokens[1];
      m_text.fail("face " + std::to_string(face) + ": corner " + shown(without) + " has no " + references.kind.one +
                  " (" + references.kind.keyword + "), but corner " + shown(with) + " has one");
    }
    if(index > so_far && index > in_face.forward)
      in_face.forward = index;
    if(in_face.has && references.mismatch == 0 && (face == 0 || references.face_0_has))
      references.kept.push_back(static_cast<std::size_t>(index - 1));
  }

  /// the soup keeps the indices of a list only if every face has them: the
  /// first face that differs from face 0 drops them
  void end_references(Corner_references& references, const Face_references& in_face, std::size_t face)
  {
    if(in_face.forward != 0)
      references.forward.add(face, m_text.line(), in_face.forward);
    if(face == 0) {
      references.face_0_has = in_face.has;
    } else if(in_face.has != references.face_0_has && references.mismatch == 0) {
      references.mismatch = face;
      std::vector<std::size_t>().swap(references.kept);
    }
  }

  /// the corner `v`, `v/vt`, `v//vn` or `v/vt/vn` (an empty vt or vn is none)
  Corner corner_of(std::string_view corner, std::size_t face)
  {
    std::string_view parts[3];
    long long vertex = 0, texture = 0, normal = 0;
    if(!split_corner(corner, parts) || parse_integer(parts[0], vertex) == Integer::invalid ||
       (!parts[1].empty() && parse_integer(parts[1], texture) == Integer::invalid) ||
       (!parts[2].empty() && parse_integer(parts[2], normal) == Integer::invalid))
      m_text.fail("face " + std::to_string(face) + ": " + shown(corner) +
                  " is not a vertex reference (expected v, v/vt, v//vn or v/vt/vn)");
    Corner result{index_from(vertex, parts[0], face, m_soup.points.size(), vertex_kind), 0, 0};
    if(!parts[1].empty())
      result.texture = index_from(texture, parts[1], face, m_soup.texture_points.size(), texture_kind);
    if(!parts[2].empty())
      result.normal = index_from(normal, parts[2], face, m_soup.normals.size(), normal_kind);
    return result;
  }

  /// `parts` = v, vt, vn of `corner` (the missing ones empty); false if it
  /// has a fourth part
  static bool split_corner(std::string_view corner, std::string_view (&parts)[3])
  {
    for(std::string_view& part : parts) {
      const std::size_t slash = corner.find('/');
      part = corner.substr(0, slash);
      if(slash == std::string_view::npos)
        return true;
      corner.remove_prefix(slash + 1);
    }
    return false;
  }

  /// `index`, written `text` in the file, from 1 whether it counts from the
  /// first (1) or from the last (-1) of the `so_far` vertices or texture
  /// coordinates read so far; a larger one is a forward reference
  unsigned long long index_from(long long index, std::string_view text, std::size_t face, std::size_t so_far,
                                const Index_kind& kind)
  {
    if(index == 0)
      m_text.fail("face " + std::to_string(face) + " has " + kind.one + " index 0 (OBJ counts " + kind.many +
                  " from 1, or from -1 backwards)");
    if(index < 0)
      return relative_index(index, text, face, so_far, kind);
    if(static_cast<unsigned long long>(index) > max_vertices)
      m_text.fail("face " + std::to_string(face) + " has " + kind.one + " index " + clipped(text) +
                  ", but a mesh has at most " + std::to_string(max_vertices) + " " + kind.many);
    return static_cast<unsigned long long>(index);
  }

  /// -1 is the last of the `so_far` read
  unsigned long long relative_index(long long index, std::string_view text, std::size_t face, std::size_t so_far,
                                    const Index_kind& kind)
  {
    const unsigned long long back = static_cast<unsigned long long>(-(index + 1)) + 1;
    if(back > so_far)
      m_text.fail("face " + std::to_string(face) + " has " + kind.one + " index " + clipped(text) + ", but " +
                  (so_far == 0
                     ? "no " + std::string(kind.one) + " precedes it"
                     : "only " + count_of(so_far, kind.one, kind.many) + (so_far == 1 ? " precedes" : " precede") +
                         " it (-1 to -" + std::to_string(so_far) + ")"));
    return so_far - back + 1;
  }

  /// `t NAME ints/floats/strings values...`: OpenSubdiv's tags
  void read_tag()
  {
    Obj_tag tag;
    tag.line = m_text.line();
    tag.name = std::string(m_text.token_on_line());
    if(tag.name.empty())
      m_text.fail("a tag line (t) needs a name and the counts INTS/FLOATS/STRINGS");
    const std::string item = "tag " + shown(tag.name);
    const std::string_view counts_text = m_text.token_on_line();
    unsigned long long counts[3] = {0, 0, 0};
    if(!parse_tag_counts(counts_text, counts))
      m_text.fail(item + ": expected the counts INTS/FLOATS/STRINGS (e.g. 2/1/0), found " +
                  (counts_text.empty() ? std::string("nothing") : shown(counts_text)));
    const std::size_t values = m_text.tokens_left_on_line();
    if(counts[0] > values || counts[1] > values || counts[2] > values || counts[0] + counts[1] + counts[2] != values)
      m_text.fail(item + " announces " + clipped(counts_text) + ", but " +
                  count_of(values, "value follows", "values follow"));
    read_tag_values(tag, counts, item);
    m_soup.tags.push_back(std::move(tag));
  }

  static bool parse_tag_counts(std::string_view text, unsigned long long (&counts)[3])
  {
    for(int i = 0; i < 3; ++i) {
      const std::size_t slash = text.find('/');
      if((i < 2) == (slash == std::string_view::npos))
        return false;
      long long count = 0;
      if(parse_integer(text.substr(0, slash), count) != Integer::ok || count < 0)
        return false;
      counts[i] = static_cast<unsigned long long>(count);
      if(i < 2)
        text = text.substr(slash + 1);
    }
    return true;
  }

  void read_tag_values(Obj_tag& tag, const unsigned long long (&counts)[3], const std::string& item)
  {
    tag.ints.reserve(counts[0]);
    tag.floats.reserve(counts[1]);
    tag.strings.reserve(counts[2]);
    for(unsigned long long i = 0; i < counts[0]; ++i) {
      const std::string_view token = m_text.token_on_line();
      long long value = 0;
      if(parse_integer(token, value) != Integer::ok)
        m_text.fail(item + ": expected an integer, found " + shown(token));
      tag.ints.push_back(value);
    }
    for(unsigned long long i = 0; i < counts[1]; ++i) {
      const std::string_view token = m_text.token_on_line();
      double value = 0;
      if(!parse_real(token, value))
        m_text.fail(item + ": expected a number, found " + shown(token));
      if(!std::isfinite(value))
        m_text.fail(item + " has the value " + clipped(token) + ", which is not a finite number");
      tag.floats.push_back(value);
    }
    for(unsigned long long i = 0; i < counts[2]; ++i)
      tag.strings.emplace_back(m_text.token_on_line());
  }

  /// counts the statements that a soup does not keep, for the notes
  void count_ignored(std::string_view keyword)
  {
    for(Ignored& ignored : m_ignored)
      if(ignored.keyword == keyword) {
        ++ignored.lines;
        return;
      }
    constexpr std::size_t max_keywords = 16; // a hostile file may invent many
    if(m_ignored.size() < max_keywords)
      m_ignored.push_back(Ignored{std::string(keyword), 1});
    else
      ++m_other_ignored_lines;
  }

  /// the notes of what was read but not kept
  void note_ignored()
  {
    const std::string of = " of " + quoted(m_text.name());
    if(m_extra_vertex_values_line != 0)
      m_soup.notes.push_back("ignored the values after x y z (w, colours) of the vertices" + of + " (from line " +
                             std::to_string(m_extra_vertex_values_line) + ")");
    note_unused(m_texture, m_soup.texture_points.size(), of);
    note_unused(m_normal, m_soup.normals.size(), of);
    for(const Ignored& ignored : m_ignored)
      m_soup.notes.push_back("ignored " + describe_ignored(ignored) + of);
    if(m_other_ignored_lines > 0)
      m_soup.notes.push_back("ignored " + count_of(m_other_ignored_lines, "line", "lines") +
                             " with further unknown keywords" + of);
  }

  /// a note when the `count` values of a list are not kept
  void note_unused(const Corner_references& references, std::size_t count, const std::string& of)
  {
    const std::string keyword = std::string(" (") + references.kind.keyword + ")";
    if(references.mismatch != 0)
      m_soup.notes.push_back(std::string("ignored the ") + references.kind.many + keyword + of + ": face 0 has " +
                             (references.face_0_has ? "them" : "none") + ", but " +
                             numbered("face", references.mismatch) + (references.face_0_has ? " has none" : " has"));
    else if(!references.face_0_has && count != 0)
      m_soup.notes.push_back(
        "no face refers to the " +
        count_of(count, (references.kind.one + keyword).c_str(), (references.kind.many + keyword).c_str()) + of);
  }

  static std::string describe_ignored(const Ignored& ignored)
  {
    struct Known
    {
      const char *keyword, *one, *many;
    };
    static const Known known[] = {
      {"vp", "parameter-space vertex (vp)", "parameter-space vertices (vp)"},
      {"l", "polyline (l)", "polylines (l)"},
      {"p", "point element (p)", "point elements (p)"},
      {"usemtl", "material assignment (usemtl)", "material assignments (usemtl)"},
      {"mtllib", "material library (mtllib)", "material libraries (mtllib)"},
    };
    for(const Known& k : known)
      if(ignored.keyword == k.keyword)
        return count_of(ignored.lines, k.one, k.many);
    static const char* const unsupported[] = {
      "cstype",   "deg",    "bmat",   "step",       "curv",      "curv2", "surf", "parm",  "trim",
      "hole",     "scrv",   "sp",     "end",        "con",       "mg",    "lod",  "bevel", "c_interp",
      "d_interp", "usemap", "maplib", "shadow_obj", "trace_obj", "ctech", "stech"};
    for(const char* keyword : unsupported)
      if(ignored.keyword == keyword)
        return count_of(ignored.lines, (shown(ignored.keyword) + " line").c_str(),
                        (shown(ignored.keyword) + " lines").c_str());
    return count_of(ignored.lines, "line", "lines") + " with the unknown keyword " + shown(ignored.keyword);
  }

  /// the first face, in the order of the file, with an index past the end
  /// (of the vertices first, on one line)
  void check_forward_references() const
  {
    struct Past
    {
      const Forward_reference* reference;
      std::size_t count;
      const Index_kind& kind;
    };
    const Past lists[] = {
      {m_forward.first_past(m_soup.points.size()), m_soup.points.size(), vertex_kind},
      {m_texture.forward.first_past(m_soup.texture_points.size()), m_soup.texture_points.size(), texture_kind},
      {m_normal.forward.first_past(m_soup.normals.size()), m_soup.normals.size(), normal_kind}};
    const Past* first = nullptr;
    for(const Past& list : lists)
      if(list.reference != nullptr && (first == nullptr || list.reference->line < first->reference->line))
        first = &list;
    if(first != nullptr)
      m_text.fail_at_line(first->reference->line,
                          index_out_of_range(first->reference->face, std::to_string(first->reference->index),
                                             first->count, true, first->kind));
  }

  const char* m_data;
  std::size_t m_size;
  Text_cursor m_text;
  Mesh_soup m_soup;
  Forward_references m_forward; // to vertices
  Corner_references m_texture{texture_kind, m_soup.texture_indices, {}};
  Corner_references m_normal{normal_kind, m_soup.normal_indices, {}};
  std::vector<Ignored> m_ignored;
  std::size_t m_other_ignored_lines = 0;
  std::size_t m_extra_vertex_values_line = 0;
};

// ---------------------------------------------------------------------------
// PLY: a text header declaring elements and their properties, then the
// elements' values, as ASCII tokens or binary in either byte order

enum class Ply_type { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

bool parse_ply_type(std::string_view word, Ply_type& type)
{
  struct Name
  {
    const char* word;
    Ply_type type;
  };
  static const Name names[] = {
    {"char", Ply_type::int8},      {"int8", Ply_type::int8},       {"uchar", Ply_type::uint8},
    {"uint8", Ply_type::uint8},    {"short", Ply_type::int16},     {"int16", Ply_type::int16},
    {"ushort", Ply_type::uint16},  {"uint16", Ply_type::uint16},   {"int", Ply_type::int32},
    {"int32", Ply_type::int32},    {"uint", Ply_type::uint32},     {"uint32", Ply_type::uint32},
    {"float", Ply_type::float32},  {"float32", Ply_type::float32}, {"double", Ply_type::float64},
    {"float64", Ply_type::float64}};
  for(const Name& name : names)
    if(word == name.word) {
      type = name.type;
      return true;
    }
  return false;
}

std::size_t size_of(Ply_type type)
{
  switch(type) {
    case Ply_type::int8:
    case Ply_type::uint8:
      return 1;
    case Ply_type::int16:
    case Ply_type::uint16:
      return 2;
    case Ply_type::int32:
    case Ply_type::uint32:
    case Ply_type::float32:
      return 4;
    case Ply_type::float64:
      return 8;
  }
  return 8;
}

bool is_integer(Ply_type type)
{
  return type != Ply_type::float32 && type != Ply_type::float64;
}
bool is_signed(Ply_type type)
{
  return type == Ply_type::int8 || type == Ply_type::int16 || type == Ply_type::int32;
}

struct Ply_property
{
  std::string name;
  bool list = false;
  Ply_type count_type = Ply_type::uint8; // lists only
  Ply_type type = Ply_type::float32;     // of the value, or of a list's items
  std::size_t line = 0;
};

enum class Ply_role { vertex, face, other };

constexpr std::size_t no_property = std::numeric_limits<std::size_t>::max();

struct Ply_element
{
  std::string name;
  unsigned long long count = 0;
  std::vector<Ply_property> properties;
  std::size_t line = 0;
  Ply_role role = Ply_role::other;
  std::size_t axes[3] = {no_property, no_property, no_property}; // vertex: the properties x, y, z
  /// vertex: the properties red, green, blue, alpha (all no_property unless the first three are there)
  std::size_t colour_channels[4] = {no_property, no_property, no_property, no_property};
  std::size_t corners = no_property; // face: the list of vertex indices

  int axis_of(std::size_t property) const { return position_of(axes, property); }
  int colour_channel_of(std::size_t property) const { return position_of(colour_channels, property); }
  bool has_colours() const { return colour_channels[0] != no_property; }

private:
  template <std::size_t N>
  static int position_of(const std::size_t (&properties)[N], std::size_t property)
  {
    for(std::size_t k = 0; k < N; ++k)
      if(properties[k] == property)
        return static_cast<int>(k);
    return -1;
  }
};

/// "vertex 3", "face 0", "item 2 of the element 'edge'": where the body is
struct Ply_item
{
  const Ply_element* element = nullptr;
  unsigned long long index = 0;

  std::string describe() const
  {
    if(element == nullptr)
      return "the body";
    const std::string number = std::to_string(index);
    switch(element->role) {
      case Ply_role::vertex:
        return "vertex " + number;
      case Ply_role::face:
        return "face " + number;
      case Ply_role::other:
        break;
    }
    return "item " + number + " of the element " + shown(element->name);
  }
};

/*
 * The values of an ASCII body: tokens in any line layout (the format does
 * not promise one item per line); messages name the line of the token.
 */
class Ply_ascii_values
{
public:
  explicit Ply_ascii_values(Text_cursor& text) : m_text(text) {}

  void start(const Ply_item& item) { m_item = item; }

  double real(Ply_type)
  {
    next();
    double value = 0;
    if(!parse_real(m_token, value))
      fail("expected a number in " + m_item.describe() + ", found " + shown(m_token));
    return value;
  }

  /// an integer, the extreme of its sign if it does not fit
  long long integer(Ply_type)
  {
    next();
    long long value = 0;
    if(parse_integer(m_token, value) == Integer::invalid)
      fail("expected an integer in " + m_item.describe() + ", found " + shown(m_token));
    return value;
  }

  void skip(Ply_type type) { real(type); }

  void skip_values(Ply_type type, unsigned long long count)
  {
    for(unsigned long long i = 0; i < count; ++i)
      real(type);
  }

  /// the most values the rest of the body can hold: each is at least one
  /// character after a separator
  unsigned long long capacity(Ply_type) const { return m_text.bytes_left() / 2; }
  std::size_t bytes_left() const { return m_text.bytes_left(); }

  /// the value last read as the file wrote it
  std::string written() const { return clipped(m_token); }

  [[noreturn]] void fail(const std::string& what) const { m_text.fail(what); }

  void note_trailer(Mesh_soup& soup)
  {
    if(m_text.skip_to_token())
      soup.notes.push_back("ignored the text after the last element of " + quoted(m_text.name()) + " (from line " +
                           std::to_string(m_text.line()) + ")");
  }

private:
  void next()
  {
    m_token = m_text.token();
    if(m_token.empty())
      m_text.fail("the file ends inside " + m_item.describe() + " (truncated)");
  }

  Text_cursor& m_text;
  Ply_item m_item;
  std::string_view m_token;
};

/// The values of a binary body; messages name the offset of the value.
class Ply_binary_values
{
public:
  Ply_binary_values(const char* data, std::size_t size, std::size_t start, bool big_endian, const std::string& name)
    : m_in(data, size, start, big_endian, name), m_name(&name)
  {}

  void start(const Ply_item& item) { m_item = item; }

  double real(Ply_type type)
  {
    begin(type);
    switch(type) {
      case Ply_type::float32:
        m_value = m_in.take_float32();
        break;
      case Ply_type::float64:
        m_value = m_in.take_float64();
        break;
      default:
        m_value = static_cast<double>(take_integer(type));
    }
    m_value_is_integer = false;
    return m_value;
  }

  long long integer(Ply_type type)
  {
    begin(type);
    if(!is_integer(type)) // the header refuses float list counts and indices
      fail("expected an integer type in " + m_item.describe());
    m_integer = take_integer(type);
    m_value_is_integer = true;
    return m_integer;
  }

  void skip(Ply_type type)
  {
    begin(type);
    m_in.skip(size_of(type));
  }

  /// `count` is at most capacity(type)
  void skip_values(Ply_type type, unsigned long long count)
  {
    m_value_at = m_in.offset();
    m_in.skip(static_cast<std::size_t>(count) * size_of(type));
  }

  unsigned long long capacity(Ply_type type) const { return m_in.bytes_left() / size_of(type); }
  std::size_t bytes_left() const { return m_in.bytes_left(); }

  std::string written() const { return m_value_is_integer ? std::to_string(m_integer) : cgal_subdiv::written(m_value); }

  [[noreturn]] void fail(const std::string& what) const { m_in.fail_at(m_value_at, what); }

  void note_trailer(Mesh_soup& soup)
  {
    if(m_in.bytes_left() > 0)
      soup.notes.push_back("ignored " + count_of(m_in.bytes_left(), "byte", "bytes") + " after the last element of " +
                           quoted(*m_name));
  }

private:
  void begin(Ply_type type)
  {
    m_value_at = m_in.offset();
    if(size_of(type) > m_in.bytes_left())
      m_in.fail("the file ends inside " + m_item.describe() + " (truncated)");
  }

  long long take_integer(Ply_type type)
  {
    if(is_signed(type))
      return m_in.take_signed(size_of(type));
    return static_cast<long long>(m_in.take_unsigned(size_of(type)));
  }

  Byte_reader m_in;
  const std::string* m_name;
  Ply_item m_item;
  std::size_t m_value_at = 0;
  double m_value = 0;
  long long m_integer = 0;
  bool m_value_is_integer = false;
};

enum class Ply_encoding { ascii, little_endian, big_endian };

class Ply_reader
{
public:
  Ply_reader(const char* data, std::size_t size, const std::string& name)
    : m_data(data), m_size(size), m_text(data, size, name, '\0')
  {}

  Mesh_soup read()
  {
    read_header();
    find_vertex_and_face();
    check_counts();
    note_ignored();
    if(m_encoding == Ply_encoding::ascii) {
      Ply_ascii_values values(m_text);
      read_body(values);
      values.note_trailer(m_soup);
    } else {
      Ply_binary_values values(m_data, m_size, m_text.offset(), m_encoding == Ply_encoding::big_endian, name());
      read_body(values);
      values.note_trailer(m_soup);
    }
    return std::move(m_soup);
  }

private:
  const std::string& name() const { return m_text.name(); }

  void read_header()
  {
    if(m_text.token_on_line() != "ply" || !m_text.line_done())
      m_text.fail("the file does not start with the line 'ply' (not a PLY file)");
    bool has_format = false;
    for(;;) {
      m_text.next_line();
      if(m_text.bytes_left() == 0)
        m_text.fail("the header has no end_header line (truncated?)");
      const std::string_view keyword = m_text.token_on_line();
      if(keyword == "end_header")
        break;
      if(keyword.empty() || keyword == "comment" || keyword == "obj_info")
        continue;
      if(keyword == "format") {
        if(has_format)
          m_text.fail("a second format line");
        read_format();
        has_format = true;
      } else if(keyword == "element") {
        read_element();
      } else if(keyword == "property") {
        read_property();
      } else {
        m_text.fail("unexpected " + shown(keyword) + " in the header (expected format, element, property, comment, " +
                    "obj_info or end_header)");
      }
    }
    refuse_rest_of_line("end_header");
    if(!has_format)
      m_text.fail("the header has no format line");
    m_end_header_line = m_text.line();
    m_text.next_line(); // the body starts right after the newline
  }

  void refuse_rest_of_line(const char* after)
  {
    if(!m_text.line_done())
      m_text.fail("unexpected " + shown(m_text.token_on_line()) + " after " + after);
  }

  void read_format()
  {
    const std::string_view encoding = m_text.token_on_line();
    const std::string_view version = m_text.token_on_line();
    if(encoding == "ascii")
      m_encoding = Ply_encoding::ascii;
    else if(encoding == "binary_little_endian")
      m_encoding = Ply_encoding::little_endian;
    else if(encoding == "binary_big_endian")
      m_encoding = Ply_encoding::big_endian;
    else
      m_text.fail("unknown PLY format " + shown(encoding) +
                  " (expected ascii, binary_little_endian or binary_big_endian)");
    double number = 0;
    if(!parse_real(version, number) || number != 1.0)
      m_text.fail("unsupported PLY version " + shown(version) + " (expected 1.0)");
    refuse_rest_of_line("the format");
  }

  void read_element()
  {
    Ply_element element;
    element.line = m_text.line();
    element.name = std::string(m_text.token_on_line());
    const std::string_view count = m_text.token_on_line();
    if(count.empty())
      m_text.fail("an element line needs a name and a count");
    long long value = 0;
    const Integer status = parse_integer(count, value);
    if(status == Integer::invalid)
      m_text.fail("element " + shown(element.name) + ": expected its count, found " + shown(count));
    if(value < 0)
      m_text.fail("element " + shown(element.name) + " has the count " + clipped(count) + " (negative)");
    if(status == Integer::too_large)
      m_text.fail("element " + shown(element.name) + " has the count " + clipped(count) + " (too large)");
    element.count = static_cast<unsigned long long>(value);
    refuse_rest_of_line("the element count");
    if(element.name == "vertex" || element.name == "face") {
      element.role = element.name == "vertex" ? Ply_role::vertex : Ply_role::face;
      for(const Ply_element& other : m_elements)
        if(other.name == element.name)
          m_text.fail("a second " + shown(element.name) + " element (the first is on line " +
                      std::to_string(other.line) + ")");
    }
    m_elements.push_back(std::move(element));
  }

  Ply_type read_type(std::string_view word)
  {
    Ply_type type = Ply_type::float32;
    if(!parse_ply_type(word, type))
      m_text.fail("unknown property type " + shown(word) +
                  " (expected char, uchar, short, ushort, int, uint, float, double, int8, uint8, int16, uint16, "
                  "int32, uint32, float32 or float64)");
    return type;
  }

  void read_property()
  {
    if(m_elements.empty())
      m_text.fail("a property line before any element line");
    Ply_property property;
    property.line = m_text.line();
    const std::string_view word = m_text.token_on_line();
    if(word == "list") {
      property.list = true;
      const std::string_view count_type = m_text.token_on_line();
      property.count_type = read_type(count_type);
      property.type = read_type(m_text.token_on_line());
      if(!is_integer(property.count_type))
        m_text.fail("a list with the count type " + shown(count_type) + " (expected an integer type)");
    } else {
      property.type = read_type(word);
    }
    property.name = std::string(m_text.token_on_line());
    if(property.name.empty())
      m_text.fail("a property line needs a type and a name");
    refuse_rest_of_line("the property name");
    m_elements.back().properties.push_back(std::move(property));
  }

  Ply_element* element_of(Ply_role role)
  {
    for(Ply_element& element : m_elements)
      if(element.role == role)
        return &element;
    return nullptr;
  }

  void find_vertex_and_face()
  {
    m_vertex = element_of(Ply_role::vertex);
    m_face = element_of(Ply_role::face);
    if(m_vertex == nullptr)
      m_text.fail_at_line(m_end_header_line, "the header declares no vertex element");
    if(m_face == nullptr)
      m_text.fail_at_line(m_end_header_line, "the header declares no face element");
    find_axes(*m_vertex);
    find_colour_channels(*m_vertex);
    find_corners(*m_face);
  }

  void find_axes(Ply_element& vertex)
  {
    static const char* const axis_names[] = {"x", "y", "z"};
    for(std::size_t i = 0; i < vertex.properties.size(); ++i)
      for(int axis = 0; axis < 3; ++axis)
        if(vertex.properties[i].name == axis_names[axis] && vertex.axes[axis] == no_property) {
          if(vertex.properties[i].list)
            m_text.fail_at_line(vertex.properties[i].line,
                                std::string("the vertex property ") + axis_names[axis] + " is a list");
          vertex.axes[axis] = i;
        }
    for(int axis = 0; axis < 3; ++axis)
      if(vertex.axes[axis] == no_property)
        m_text.fail_at_line(vertex.line, std::string("the vertex element has no property ") + axis_names[axis]);
  }

  // red, green and blue (and alpha, if there) when the first three are
  // scalar properties of the vertex; otherwise none (they are then noted as
  // ignored)
  static void find_colour_channels(Ply_element& vertex)
  {
    static const char* const channel_names[] = {"red", "green", "blue", "alpha"};
    for(std::size_t i = 0; i < vertex.properties.size(); ++i)
      for(int k = 0; k < 4; ++k)
        if(vertex.properties[i].name == channel_names[k] && !vertex.properties[i].list &&
           vertex.colour_channels[k] == no_property)
          vertex.colour_channels[k] = i;
    if(vertex.colour_channels[0] == no_property || vertex.colour_channels[1] == no_property ||
       vertex.colour_channels[2] == no_property)
      std::fill(std::begin(vertex.colour_channels), std::end(vertex.colour_channels), no_property);
  }

  void find_corners(Ply_element& face)
  {
    for(std::size_t i = 0; i < face.properties.size() && face.corners == no_property; ++i) {
      const Ply_property& property = face.properties[i];
      if(property.name != "vertex_indices" && property.name != "vertex_index")
        continue;
      if(!property.list)
        m_text.fail_at_line(property.line, "the face property " + property.name + " is not a list");
      if(!is_integer(property.type))
        m_text.fail_at_line(property.line, "the face list " + property.name +
                                             " has items of a floating-point type (expected an integer type)");
      face.corners = i;
    }
    if(face.corners == no_property)
      m_text.fail_at_line(face.line, "the face element has no list property vertex_indices (or vertex_index)");
  }

  /// the least number of bytes an item of `element` takes: in ASCII, each
  /// value is at least a character and a separator
  std::size_t least_bytes(const Ply_element& element) const
  {
    const bool ascii = m_encoding == Ply_encoding::ascii;
    std::size_t total = 0;
    for(std::size_t i = 0; i < element.properties.size(); ++i) {
      const Ply_property& property = element.properties[i];
      const std::size_t items = (element.role == Ply_role::face && i == element.corners) ? 3 : 0;
      if(!property.list)
        total += ascii ? 2 : size_of(property.type);
      else
        total += ascii ? 2 + 2 * items : size_of(property.count_type) + items * size_of(property.type);
    }
    return total;
  }

  static std::string describe_count(const Ply_element& element)
  {
    switch(element.role) {
      case Ply_role::vertex:
        return count_of(element.count, "vertex", "vertices");
      case Ply_role::face:
        return count_of(element.count, "face", "faces");
      case Ply_role::other:
        break;
    }
    return count_of(element.count, "item", "items") + " of the element " + shown(element.name);
  }

  /// refuses counts that the body cannot hold before anything is reserved
  void check_counts()
  {
    const std::size_t body = m_text.bytes_left();
    // in ASCII, the newline of end_header separates the first value
    const std::size_t room = body + (m_encoding == Ply_encoding::ascii ? 1 : 0);
    std::size_t needed = 0;
    for(const Ply_element& element : m_elements) {
      if(element.role == Ply_role::vertex && element.count > max_vertices)
        m_text.fail_at_line(element.line, too_many_vertices(element.count));
      const std::size_t each = least_bytes(element);
      if(each == 0)
        continue;
      if(element.count > (room - needed) / each)
        m_text.fail_at_line(
          element.line,
          count_too_large(describe_count(*m_vertex) + (&element == m_vertex ? "" : " and " + describe_count(element)),
                          body));
      needed += static_cast<std::size_t>(element.count) * each;
    }
    m_soup.points.reserve(m_vertex->count);
    m_soup.face_starts.reserve(m_face->count + 1);
    m_soup.indices.reserve(3 * m_face->count);
  }

  template <class Values>
  void read_body(Values& values)
  {
    for(const Ply_element& element : m_elements) {
      if(element.properties.empty())
        continue; // nothing to read, however many items
      for(unsigned long long i = 0; i < element.count; ++i) {
        values.start(Ply_item{&element, i});
        if(element.role == Ply_role::vertex)
          read_vertex(values, element, i);
        else if(element.role == Ply_role::face)
          read_face(values, element, i);
        else
          for(const Ply_property& property : element.properties)
            skip_property(values, property, Ply_item{&element, i});
      }
    }
  }

  template <class Values>
  void read_vertex(Values& values, const Ply_element& element, unsigned long long v)
  {
    std::array<double, 3> p{};
    std::array<unsigned char, 4> colour = {0, 0, 0, 255};
    for(std::size_t i = 0; i < element.properties.size(); ++i) {
      const Ply_property& property = element.properties[i];
      if(const int axis = element.axis_of(i); axis >= 0) {
        p[axis] = values.real(property.type);
        if(!std::isfinite(p[axis]))
          values.fail(not_finite("vertex " + std::to_string(v), values.written()));
      } else if(const int channel = element.colour_channel_of(i); channel >= 0) {
        if(!colour_component(values.real(property.type), is_integer(property.type), colour[channel]))
          values.fail("vertex " + std::to_string(v) + ": its " + property.name + " " + values.written() +
                      " is out of range (" + colour_range + ")");
      } else {
        skip_property(values, property, Ply_item{&element, v});
      }
    }
    m_soup.points.push_back(p);
    if(element.has_colours())
      m_soup.colours.push_back(colour);
  }

  template <class Values>
  void read_face(Values& values, const Ply_element& element, unsigned long long f)
  {
    for(std::size_t i = 0; i < element.properties.size(); ++i)
      if(i == element.corners)
        read_corners(values, element.properties[i], static_cast<std::size_t>(f));
      else
        skip_property(values, element.properties[i], Ply_item{&element, f});
    end_face(m_soup);
  }

  template <class Values>
  void read_corners(Values& values, const Ply_property& list, std::size_t f)
  {
    const long long count = values.integer(list.count_type);
    if(count < 3)
      values.fail(too_few_vertices(f, values.written()));
    if(static_cast<unsigned long long>(count) > values.capacity(list.type))
      values.fail("face " + std::to_string(f) + " says it has " + values.written() + " vertices" +
                  but_only_left(values.bytes_left()));
    const std::size_t vertices = static_cast<std::size_t>(m_vertex->count);
    for(long long i = 0; i < count; ++i) {
      const long long index = values.integer(list.type);
      if(index < 0 || static_cast<unsigned long long>(index) >= vertices)
        values.fail(index_out_of_range(f, values.written(), vertices, false));
      m_soup.indices.push_back(static_cast<std::size_t>(index));
    }
  }

  template <class Values>
  void skip_property(Values& values, const Ply_property& property, const Ply_item& item)
  {
    if(!property.list) {
      values.skip(property.type);
      return;
    }
    const long long count = values.integer(property.count_type);
    if(count < 0)
      values.fail(item.describe() + " has the list count " + values.written() + " (negative) for " +
                  shown(property.name));
    if(static_cast<unsigned long long>(count) > values.capacity(property.type))
      values.fail(item.describe() + " says its list " + shown(property.name) + " has " + values.written() + " values" +
                  but_only_left(values.bytes_left()));
    values.skip_values(property.type, static_cast<unsigned long long>(count));
  }

  /// "red, green, blue" (at most 10 names: a header may list thousands)
  static std::string names_except(const Ply_element& element, std::initializer_list<std::size_t> kept,
                                  std::size_t& count)
  {
    std::string names;
    count = 0;
    for(std::size_t i = 0; i < element.properties.size(); ++i) {
      if(std::find(kept.begin(), kept.end(), i) != kept.end())
        continue;
      if(count < 10)
        names += (count == 0 ? "" : ", ") + clipped(element.properties[i].name);
      ++count;
    }
    if(count > 10)
      names += " and " + std::to_string(count - 10) + " more";
    return names;
  }

  void note_ignored()
  {
    const std::string of = " of " + quoted(name());
    std::size_t count = 0;
    std::string names =
      names_except(*m_vertex,
                   {m_vertex->axes[0], m_vertex->axes[1], m_vertex->axes[2], m_vertex->colour_channels[0],
                    m_vertex->colour_channels[1], m_vertex->colour_channels[2], m_vertex->colour_channels[3]},
                   count);
    if(count > 0)
      m_soup.notes.push_back("ignored the vertex " + std::string(count == 1 ? "property " : "properties ") + names +
                             of);
    names = names_except(*m_face, {m_face->corners}, count);
    if(count > 0)
      m_soup.notes.push_back("ignored the face " + std::string(count == 1 ? "property " : "properties ") + names + of);
    for(const Ply_element& element : m_elements)
      if(element.role == Ply_role::other)
        m_soup.notes.push_back("ignored the element " + shown(element.name) + " (" +
                               count_of(element.count, "item", "items") + ")" + of);
  }

  const char* m_data;
  std::size_t m_size;
  Text_cursor m_text;
  Ply_encoding m_encoding = Ply_encoding::ascii;
  std::vector<Ply_element> m_elements;
  Ply_element* m_vertex = nullptr;
  Ply_element* m_face = nullptr;
  std::size_t m_end_header_line = 0;
  Mesh_soup m_soup;
};

// ---------------------------------------------------------------------------
// STL: triangles with their own corners, binary or ASCII; equal corners are
// merged into shared points

/// the point index of each distinct position, in the order of first appearance
class Point_merger
{
public:
  explicit Point_merger(Mesh_soup& soup) : m_soup(soup) {}

  /// false if a new point would be one too many for 32-bit indices
  bool has_room() const { return m_soup.points.size() < max_vertices; }

  std::size_t index_of(std::array<double, 3> p)
  {
    Key key;
    for(int axis = 0; axis < 3; ++axis) {
      if(p[axis] == 0)
        p[axis] = 0.0; // -0.0 and 0.0 are the same position
      std::memcpy(&key[axis], &p[axis], sizeof p[axis]);
    }
    const auto found = m_index.try_emplace(key, m_soup.points.size());
    if(found.second)
      m_soup.points.push_back(p);
    return found.first->second;
  }

private:
  using Key = std::array<std::uint64_t, 3>; // the bits of the coordinates

  struct Key_hash
  {
    std::size_t operator()(const Key& key) const
    {
      std::uint64_t h = 0x9E3779B97F4A7C15ull;
      for(std::uint64_t word : key) {
        h ^= word + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
        h = (h ^ (h >> 31)) * 0xBF58476D1CE4E5B9ull;
      }
      return static_cast<std::size_t>(h ^ (h >> 29));
    }
  };

  Mesh_soup& m_soup;
  std::unordered_map<Key, std::size_t, Key_hash> m_index;
};

constexpr std::size_t stl_header_bytes = 84; // 80 bytes of text, the triangle count
constexpr std::size_t stl_triangle_bytes = 50;

class Stl_reader
{
public:
  Stl_reader(const char* data, std::size_t size, const std::string& name)
    : m_data(data), m_size(size), m_name(name), m_merger(m_soup)
  {}

  Mesh_soup read()
  {
    if(is_binary())
      read_binary();
    else
      read_ascii_or_explain();
    return std::move(m_soup);
  }

private:
  /// the triangle count at byte 80 (0 if the file is shorter)
  std::uint64_t binary_count() const
  {
    if(m_size < stl_header_bytes)
      return 0;
    return Byte_reader(m_data, m_size, 80, false, m_name).take_unsigned(4);
  }

  bool is_binary() const
  {
    return m_size >= stl_header_bytes && m_size - stl_header_bytes == stl_triangle_bytes * binary_count();
  }

  /// why the file is no binary STL
  std::string not_binary() const
  {
    if(m_size < stl_header_bytes)
      return "it has only " + count_of(m_size, "byte", "bytes") + ", fewer than the 84 of a binary STL header";
    return "its size " + std::to_string(m_size) + " is not 84 + 50 x " + std::to_string(binary_count()) +
           ", the triangle count at byte 80";
  }

  void read_binary()
  {
    Byte_reader in(m_data, m_size, 80, false, m_name);
    const std::uint64_t triangles = in.take_unsigned(4);
    m_soup.face_starts.reserve(triangles + 1);
    m_soup.indices.reserve(3 * triangles);
    for(std::uint64_t t = 0; t < triangles; ++t) {
      in.skip(12); // the normal: redundant
      for(int corner = 0; corner < 3; ++corner) {
        std::array<double, 3> p{};
        for(int axis = 0; axis < 3; ++axis) {
          const std::size_t at = in.offset();
          p[axis] = in.take_float32();
          if(!std::isfinite(p[axis]))
            in.fail_at(at, not_finite(numbered("facet", t), written(p[axis])));
        }
        if(!m_merger.has_room())
          in.fail(too_many_points());
        m_soup.indices.push_back(m_merger.index_of(p));
      }
      in.skip(2); // the attribute bytes
      end_face(m_soup);
    }
  }

  std::string too_many_points() const
  {
    return "more than " + std::to_string(max_vertices) + " distinct points are not supported (32-bit indices)";
  }

  /// a file starting with "solid" may still be a binary STL of the wrong size:
  /// the message of a failed ASCII read says so
  void read_ascii_or_explain()
  {
    Text_cursor text(m_data, m_size, m_name, '\0');
    if(!same_word(text.token(), "solid"))
      throw Input_error(quoted(m_name) + ": neither ASCII STL (it does not start with 'solid') nor binary STL (" +
                        not_binary() + ")");
    try {
      read_ascii(text);
    } catch(const Input_error& error) {
      if(m_size < stl_header_bytes || !has_control_bytes())
        throw;
      throw Input_error(std::string(error.what()) + " (if it is a binary STL: " + not_binary() + ")");
    }
  }

  /// whether the file holds bytes that no text has (a binary STL almost surely does)
  bool has_control_bytes() const
  {
    for(std::size_t i = 0; i < m_size; ++i) {
      const unsigned char c = static_cast<unsigned char>(m_data[i]);
      if((c < 0x20 && !is_blank(static_cast<char>(c)) && c != '\n') || c == 0x7f)
        return true;
    }
    return false;
  }

  void read_ascii(Text_cursor& text)
  {
    text.next_line(); // the name of the solid
    read_facets(text);
    std::size_t solids = 1;
    while(text.skip_to_token()) {
      Text_cursor probe = text;
      if(!same_word(probe.token(), "solid")) {
        m_soup.notes.push_back("ignored the text after the last 'endsolid' of " + quoted(m_name) + " (from line " +
                               std::to_string(text.line()) + ")");
        break;
      }
      text = probe;
      text.next_line();
      read_facets(text);
      ++solids;
    }
    if(solids > 1)
      m_soup.notes.push_back("read the " + std::to_string(solids) + " solids of " + quoted(m_name) + " as one mesh");
  }

  /// the facets of a solid, up to its endsolid line
  void read_facets(Text_cursor& text)
  {
    for(;;) {
      const std::string_view word = text.token();
      if(word.empty())
        text.fail("the file ends before 'endsolid' (truncated)");
      if(same_word(word, "endsolid")) {
        text.next_line(); // the name again
        return;
      }
      if(!same_word(word, "facet"))
        text.fail("expected 'facet' or 'endsolid', found " + shown(word));
      read_facet(text);
    }
  }

  /// facet normal nx ny nz / outer loop / vertex x y z (3 times) / endloop / endfacet
  void read_facet(Text_cursor& text)
  {
    const std::size_t f = m_soup.number_of_faces();
    const std::size_t line = text.line();
    const std::string item = "facet " + std::to_string(f);
    expect(text, "normal", item);
    for(int axis = 0; axis < 3; ++axis)
      read_number(text, item); // the normal: redundant
    expect(text, "outer", item);
    expect(text, "loop", item);
    std::size_t corners = 0;
    for(std::string_view word = text.token(); !same_word(word, "endloop"); word = text.token()) {
      if(!same_word(word, "vertex"))
        fail_expected(text, "'vertex' or 'endloop'", word, item);
      std::array<double, 3> p{};
      for(int axis = 0; axis < 3; ++axis) {
        p[axis] = read_number(text, item);
        if(!std::isfinite(p[axis]))
          text.fail(not_finite(item, clipped(m_token)));
      }
      if(corners < 3) {
        if(!m_merger.has_room())
          text.fail(too_many_points());
        m_soup.indices.push_back(m_merger.index_of(p));
      }
      ++corners;
    }
    if(corners != 3)
      text.fail_at_line(line, item + " has " + count_of(corners, "vertex", "vertices") + " (STL facets are triangles)");
    expect(text, "endfacet", item);
    end_face(m_soup);
  }

  [[noreturn]] static void fail_expected(const Text_cursor& text, const std::string& expected, std::string_view word,
                                         const std::string& item)
  {
    if(word.empty())
      text.fail("the file ends inside " + item + " (truncated)");
    text.fail(item + ": expected " + expected + ", found " + shown(word));
  }

  static void expect(Text_cursor& text, const char* keyword, const std::string& item)
  {
    const std::string_view word = text.token();
    if(!same_word(word, keyword))
      fail_expected(text, "'" + std::string(keyword) + "'", word, item);
  }

  double read_number(Text_cursor& text, const std::string& item)
  {
    m_token = text.token();
    double value = 0;
    if(m_token.empty() || !parse_real(m_token, value))
      fail_expected(text, "a number", m_token, item);
    return value;
  }

  const char* m_data;
  std::size_t m_size;
  const std::string& m_name;
  Mesh_soup m_soup;
  Point_merger m_merger;
  std::string_view m_token; // the number last read, for messages
};

// ---------------------------------------------------------------------------
// The whole file

std::string read_whole_file(const std::string& path)
{
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if(status.type() == fs::file_type::not_found)
    throw Input_error("cannot read " + quoted(path) + ": no such file");
  if(error)
    throw Input_error("cannot read " + quoted(path) + ": " + error.message());
  if(fs::is_directory(status))
    throw Input_error("cannot read " + quoted(path) + ": it is a directory");
  std::ifstream in(path, std::ios::binary);
  if(!in)
    throw Input_error("cannot read " + quoted(path) + ": " + std::strerror(errno));
  std::string content;
  if(fs::is_regular_file(status)) {
    const std::uintmax_t size = fs::file_size(path, error);
    if(!error)
      content.reserve(static_cast<std::size_t>(size));
  }
  char buffer[1 << 16];
  while(in.read(buffer, sizeof buffer) || in.gcount() > 0)
    content.append(buffer, static_cast<std::size_t>(in.gcount()));
  if(in.bad())
    throw Input_error("cannot read " + quoted(path) + ": read error");
  return content;
}

} // namespace

const char* mesh_format_name(Mesh_format format)
{
  switch(format) {
    case Mesh_format::off:
      return "OFF";
    case Mesh_format::obj:
      return "OBJ";
    case Mesh_format::ply:
      return "PLY";
    case Mesh_format::stl:
      return "STL";
  }
  return "?";
}

Mesh_soup parse_mesh_soup(const char* data, std::size_t size, Mesh_format format, const std::string& name)
{
  static const char nothing = '\0';
  if(size == 0)
    data = &nothing; // the readers may call memchr on it
  switch(format) {
    case Mesh_format::off:
      return Off_reader(data, size, name).read();
    case Mesh_format::obj:
      return Obj_reader(data, size, name).read();
    case Mesh_format::ply:
      return Ply_reader(data, size, name).read();
    case Mesh_format::stl:
      return Stl_reader(data, size, name).read();
  }
  throw Input_error(quoted(name) + ": unknown mesh format");
}

Mesh_soup read_mesh_soup(const std::string& path, Mesh_format format)
{
  std::size_t size = 0;
  try {
    const std::string content = read_whole_file(path);
    size = content.size();
    return parse_mesh_soup(content.data(), content.size(), format, path);
  } catch(const std::bad_alloc&) {
    // a file too large for this machine (a lying count never gets this far)
    throw Input_error("cannot read " + quoted(path) + ": not enough memory" +
                      (size > 0 ? " for its " + count_of(size, "byte", "bytes") : std::string()));
  }
}

} // namespace cgal_subdiv
