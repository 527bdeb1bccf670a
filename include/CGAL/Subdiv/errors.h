// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_ERRORS_H
#define CGAL_SUBDIV_ERRORS_H

#include <cstdio>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Subdiv {

/*!
 * \ingroup PkgSubdivErrors
 * Thrown by every entry point of the package when its input cannot be
 * processed: too few points, a parameter out of its range, a level count whose
 * output would not fit in memory, a mesh the scheme does not apply to.
 * `what()` names the problem (and the offending element where it helps).
 * The caller's data is left unchanged when this is thrown.
 *
 * These checks stay on in release builds: they guard user errors, not
 * internal invariants.
 */
class Bad_input : public std::invalid_argument
{
public:
  explicit Bad_input(const std::string& what) : std::invalid_argument(what) {}
};

namespace internal {

/*
 * An error message appended piece by piece into one string,
 * `Message() << scheme << ": face " << index << " has " << size << " vertices"`:
 * no temporary strings, so each refusal adds little code to a user's program.
 * A chain of operator+ and std::to_string makes g++ emit a cleanup for every
 * temporary; in a plain refinement program those made the checks the largest
 * functions compiled (compile time is part of the API, doc/compile_time.md).
 */
class Message
{
public:
  Message& operator<<(const std::string& piece)
  {
    m_text += piece;
    return *this;
  }
  Message& operator<<(const char* piece)
  {
    m_text += piece;
    return *this;
  }
  Message& operator<<(int number) { return signed_number(number); }
  Message& operator<<(long number) { return signed_number(number); }
  Message& operator<<(long long number) { return signed_number(number); }
  Message& operator<<(unsigned number) { return unsigned_number(number); }
  Message& operator<<(unsigned long number) { return unsigned_number(number); }
  Message& operator<<(unsigned long long number) { return unsigned_number(number); }

  const std::string& str() const { return m_text; }

private:
  Message& signed_number(long long number)
  {
    char digits[24];
    std::snprintf(digits, sizeof digits, "%lld", number);
    m_text += digits;
    return *this;
  }
  Message& unsigned_number(unsigned long long number)
  {
    char digits[24];
    std::snprintf(digits, sizeof digits, "%llu", number);
    m_text += digits;
    return *this;
  }

  std::string m_text;
};

/// throws `Bad_input` with the message
[[noreturn]] inline void refuse(const Message& message)
{
  throw Bad_input(message.str());
}

inline void require(bool condition, const std::string& message)
{
  if(!condition)
    throw Bad_input(message);
}

// Refuse before allocating: the output of `levels` levels on n points has at most n 2^levels points.
inline void check_output_size(std::size_t n, int levels, std::size_t limit)
{
  if(levels < 0)
    refuse(Message() << "the number of levels must not be negative, got " << levels);
  double estimate = static_cast<double>(n);
  for(int l = 0; l < levels && estimate <= static_cast<double>(limit); ++l)
    estimate *= 2;
  if(estimate > static_cast<double>(limit))
    refuse(Message() << levels << " levels on " << n << " points would make more than " << limit
                     << " points (the max_output_points limit)");
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_ERRORS_H
