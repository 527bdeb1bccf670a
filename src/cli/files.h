// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// Reading polylines, and writing files so that a failure leaves none behind.
#ifndef CGAL_SUBDIV_CLI_FILES_H
#define CGAL_SUBDIV_CLI_FILES_H

#include "common.h"

#include <cstddef>
#include <fstream>
#include <string>
#include <vector>

namespace cgal_subdiv {

/// A line of a text file with its comment (from `#`) removed, split at
/// blanks, tabs and commas.
struct Data_line
{
  int number;                      // from 1
  std::string text;                // without the comment and the outer blanks
  std::vector<std::string> tokens; // never empty
};

/// the lines of `path` that hold more than blanks and a comment;
/// \throws Input_error if it cannot be read (missing, a directory)
std::vector<Data_line> read_data_lines(const std::string& path);

/*
 * reads the points of `path`, in one of two formats (found from the first line
 * that is not blank or a comment):
 *  - plain text: one point per line, 2 or 3 coordinates, `#` comments;
 *  - CGAL's polygon format: a count n, then 2n coordinates in any line layout.
 *    Only the first polygon is read; what follows (holes, further polygons) is
 *    described in `notes`.
 * Coordinates are decimals or fractions, read exactly.
 * \throws Input_error naming the file, the line and the text that is wrong
 */
Input_polyline read_polyline(const std::string& path);

/*
 * A file written under a temporary name in the same directory and renamed to
 * its final name by `commit()`; destroyed without `commit()`, it removes the
 * temporary file, so that a failed run leaves no partial output. A run that
 * writes several files `finish()`es them all (written, flushed, checked)
 * before it commits any, so that it writes all of them or none.
 */
class Atomic_file
{
public:
  explicit Atomic_file(const std::string& path);
  ~Atomic_file();
  Atomic_file(const Atomic_file&) = delete;
  Atomic_file& operator=(const Atomic_file&) = delete;

  std::ostream& stream() { return m_out; }
  /// closes the temporary file; \throws Input_error if writing failed
  void finish();
  /// `finish()`, then the rename; \throws Input_error if either failed
  void commit();

private:
  std::string m_path;
  std::string m_temporary;
  std::ofstream m_out;
  std::size_t m_slot; // in the list of temporary files that signals remove
  bool m_finished = false;
  bool m_committed = false;
};

/// installs handlers of SIGINT, SIGTERM and SIGHUP that remove the temporary
/// files of the live `Atomic_file`s, then end the program as the signal would
void remove_temporary_files_on_signals();

} // namespace cgal_subdiv

#endif // CGAL_SUBDIV_CLI_FILES_H
