// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#include "files.h"
#include "numbers.h"

#include <unistd.h>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace cgal_subdiv {

std::vector<Data_line> read_data_lines(const std::string& path)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  if(fs::is_directory(path, ec))
    throw Input_error("cannot read '" + path + "': it is a directory");
  std::ifstream in(path);
  if(!in)
    throw Input_error("cannot read '" + path + "': " + std::strerror(errno));
  std::vector<Data_line> lines;
  std::string line;
  for(int number = 1; std::getline(in, line); ++number) {
    line = line.substr(0, line.find('#'));
    for(char& c : line)
      if(c == ',' || c == '\t' || c == '\r')
        c = ' ';
    std::istringstream words(line);
    Data_line data{number, {}, {}};
    for(std::string word; words >> word;)
      data.tokens.push_back(word);
    if(data.tokens.empty())
      continue;
    data.text = line.substr(line.find_first_not_of(' '));
    data.text = data.text.substr(0, data.text.find_last_not_of(' ') + 1);
    lines.push_back(data);
  }
  if(in.bad())
    throw Input_error("cannot read '" + path + "': read error");
  return lines;
}

namespace {

struct Token
{
  std::string text;
  int line;
};

bool is_count(const std::string& s)
{
  return !s.empty() && s.size() <= 9 && s.find_first_not_of("0123456789") == std::string::npos;
}

Exact parse_coordinate(const std::string& path, int line, const std::string& token, const std::string& context)
{
  try {
    return parse_number(token);
  } catch(const std::invalid_argument& e) {
    throw Input_error(path + ":" + std::to_string(line) + ": cannot parse \"" + context + "\": \"" + token +
                      "\": " + e.what());
  }
}

// plain text: one point per line
Input_polyline read_plain(const std::string& path, const std::vector<Data_line>& lines)
{
  Input_polyline result;
  result.dimension = static_cast<int>(lines.front().tokens.size());
  for(const Data_line& line : lines) {
    const int n = static_cast<int>(line.tokens.size());
    if(n != 2 && n != 3)
      throw Input_error(path + ":" + std::to_string(line.number) + ": cannot parse \"" + line.text +
                        "\": a point has 2 or 3 coordinates, this line has " + std::to_string(n));
    if(n != result.dimension)
      throw Input_error(path + ":" + std::to_string(line.number) + ": cannot parse \"" + line.text +
                        "\": " + std::to_string(n) + " coordinates, but the first point has " +
                        std::to_string(result.dimension));
    std::array<Exact, 3> p{Exact(0), Exact(0), Exact(0)};
    for(int d = 0; d < n; ++d)
      p[static_cast<std::size_t>(d)] =
        parse_coordinate(path, line.number, line.tokens[static_cast<std::size_t>(d)], line.text);
    result.points.push_back(p);
  }
  return result;
}

// Reads polygons (a count m, then 2m values) from `pos`, `how_many` of them
// or (how_many < 0) until the end; false unless the tokens are used up exactly.
bool read_polygon_sizes(const std::vector<Token>& tokens, std::size_t pos, long how_many,
                        std::vector<std::size_t>& sizes)
{
  while(pos < tokens.size() && (how_many < 0 || static_cast<long>(sizes.size()) < how_many)) {
    if(!is_count(tokens[pos].text))
      return false;
    const std::size_t m = std::stoul(tokens[pos].text);
    pos += 1 + 2 * m;
    sizes.push_back(m);
  }
  return pos == tokens.size() && (how_many < 0 || static_cast<long>(sizes.size()) == how_many);
}

std::string list_sizes(const std::vector<std::size_t>& sizes)
{
  std::string list;
  for(std::size_t i = 0; i < sizes.size() && i < 8; ++i)
    list += (i ? ", " : "") + std::to_string(sizes[i]);
  return list + (sizes.size() > 8 ? ", ..." : "");
}

// what follows the first polygon, for the note on stderr
std::string describe_rest(const std::vector<Token>& tokens, std::size_t pos)
{
  std::vector<std::size_t> sizes;
  if(is_count(tokens[pos].text) && read_polygon_sizes(tokens, pos + 1, std::stol(tokens[pos].text), sizes))
    return "ignored " + std::to_string(sizes.size()) + " hole(s) after the outer boundary (" + list_sizes(sizes) +
           " vertices)";
  sizes.clear();
  if(read_polygon_sizes(tokens, pos, -1, sizes))
    return "ignored " + std::to_string(sizes.size()) + " further polygon(s) after the first (" + list_sizes(sizes) +
           " vertices)";
  return "ignored " + std::to_string(tokens.size() - pos) + " values after the first polygon (from line " +
         std::to_string(tokens[pos].line) + " on)";
}

// CGAL's polygon format: n, then 2n coordinates
Input_polyline read_polygon(const std::string& path, const std::vector<Data_line>& lines)
{
  std::vector<Token> tokens;
  for(std::size_t i = 1; i < lines.size(); ++i)
    for(const std::string& word : lines[i].tokens)
      tokens.push_back(Token{word, lines[i].number});
  const std::size_t n = std::stoul(lines.front().tokens.front());
  if(n == 0)
    throw Input_error("'" + path + "' holds a polygon of 0 points");
  if(tokens.size() < 2 * n)
    throw Input_error("'" + path + "': the polygon announces " + std::to_string(n) + " points, but only " +
                      std::to_string(tokens.size()) + " coordinates follow");
  Input_polyline result;
  result.dimension = 2;
  for(std::size_t i = 0; i < n; ++i) {
    std::array<Exact, 3> p{Exact(0), Exact(0), Exact(0)};
    for(std::size_t d = 0; d < 2; ++d) {
      const Token& t = tokens[2 * i + d];
      p[d] = parse_coordinate(path, t.line, t.text, t.text);
    }
    result.points.push_back(p);
  }
  if(tokens.size() > 2 * n)
    result.notes.push_back("read the first polygon (" + std::to_string(n) + " points) of '" + path + "'; " +
                           describe_rest(tokens, 2 * n));
  return result;
}

} // namespace

Input_polyline read_polyline(const std::string& path)
{
  const std::vector<Data_line> lines = read_data_lines(path);
  if(lines.empty())
    throw Input_error("'" + path + "' contains no points");
  const Data_line& first = lines.front();
  if(first.tokens.size() == 1 && is_count(first.tokens.front()))
    return read_polygon(path, lines);
  return read_plain(path, lines);
}

namespace {

// The temporary files that a signal must not leave behind: plain arrays, so
// that the handler reads them without allocating or locking (it may run in
// the middle of anything); a slot is claimed before the file is created.
constexpr std::size_t max_temporaries = 16;
constexpr std::size_t max_path = 4096;
char temporary_paths[max_temporaries][max_path];
volatile std::sig_atomic_t temporary_in_use[max_temporaries];

std::size_t claim_temporary_slot(const std::string& path)
{
  for(std::size_t i = 0; i < max_temporaries; ++i)
    if(!temporary_in_use[i] && path.size() < max_path) {
      std::memcpy(temporary_paths[i], path.c_str(), path.size() + 1);
      temporary_in_use[i] = 1;
      return i;
    }
  return max_temporaries; // not tracked: only a signal would leave it behind
}

void release_temporary_slot(std::size_t slot)
{
  if(slot < max_temporaries)
    temporary_in_use[slot] = 0;
}

extern "C" void remove_temporaries_and_die(int signal_number)
{
  for(std::size_t i = 0; i < max_temporaries; ++i)
    if(temporary_in_use[i])
      ::unlink(temporary_paths[i]);
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

} // namespace

void remove_temporary_files_on_signals()
{
  for(int signal_number : {SIGINT, SIGTERM, SIGHUP})
    std::signal(signal_number, remove_temporaries_and_die);
}

Atomic_file::Atomic_file(const std::string& path)
  : m_path(path), m_temporary(path + ".tmp" + std::to_string(::getpid()))
{
  m_slot = claim_temporary_slot(m_temporary);
  m_out.open(m_temporary);
  if(!m_out) {
    release_temporary_slot(m_slot);
    throw Input_error("cannot write '" + path + "': " + std::strerror(errno));
  }
}

Atomic_file::~Atomic_file()
{
  if(!m_committed) {
    m_out.close();
    std::remove(m_temporary.c_str());
  }
  release_temporary_slot(m_slot);
}

void Atomic_file::finish()
{
  if(m_finished)
    return;
  m_out.flush();
  if(!m_out)
    throw Input_error("cannot write '" + m_path + "': write failed");
  m_out.close();
  if(m_out.fail())
    throw Input_error("cannot write '" + m_path + "': write failed");
  m_finished = true;
}

void Atomic_file::commit()
{
  finish();
  if(std::rename(m_temporary.c_str(), m_path.c_str()) != 0)
    throw Input_error("cannot write '" + m_path + "': " + std::strerror(errno));
  m_committed = true;
  release_temporary_slot(m_slot);
}

} // namespace cgal_subdiv
