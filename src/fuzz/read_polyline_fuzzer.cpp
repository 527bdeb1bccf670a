// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// libFuzzer target: the curve reader of the command-line tool
// (`read_polyline` of src/cli/files.h) on any bytes. It reads a path, so the
// input is written to a temporary file in /tmp (removed afterwards). A refusal
// (Input_error) is a fine answer; a polyline of another dimension than 2 or 3,
// or a 2D one with a third coordinate other than 0, traps; any other exception
// escapes, which libFuzzer reports. Built and run by src/scripts/fuzz.sh.
#include "files.h"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

/// a temporary file holding the input, removed when it goes
class Temporary_file
{
public:
  Temporary_file(const std::uint8_t* data, std::size_t size)
  {
    char name[] = "/tmp/read_polyline_fuzzer.XXXXXX";
    const int fd = mkstemp(name);
    if(fd < 0)
      std::abort();
    m_path = name;
    std::size_t written = 0;
    while(written < size) {
      const ssize_t n = write(fd, data + written, size - written);
      if(n <= 0)
        std::abort();
      written += static_cast<std::size_t>(n);
    }
    if(close(fd) != 0)
      std::abort();
  }
  ~Temporary_file() { std::remove(m_path.c_str()); }
  Temporary_file(const Temporary_file&) = delete;
  Temporary_file& operator=(const Temporary_file&) = delete;

  const std::string& path() const { return m_path; }

private:
  std::string m_path;
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const Temporary_file file(data, size);
  try {
    const cgal_subdiv::Input_polyline polyline = cgal_subdiv::read_polyline(file.path());
    if(polyline.dimension != 2 && polyline.dimension != 3)
      __builtin_trap();
    if(polyline.dimension == 2)
      for(const auto& p : polyline.points)
        if(p[2] != 0)
          __builtin_trap();
  } catch(const cgal_subdiv::Input_error&) {
  }
  return 0;
}
