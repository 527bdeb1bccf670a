// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
#ifndef CGAL_SUBDIV_INTERNAL_MEMORY_H
#define CGAL_SUBDIV_INTERNAL_MEMORY_H

// The one query of the machine's memory, used to refuse a level count whose
// output cannot fit before anything is allocated. POSIX systems answer with
// sysconf, Windows with GlobalMemoryStatusEx; anywhere else (or when the query
// fails) the answer is a fixed 16 GiB, so the check still refuses the absurd.
#if defined(_WIN32)
#ifndef WIN32_LEAN_AND_MEAN
#define WIN32_LEAN_AND_MEAN
#define CGAL_SUBDIV_UNDEF_WIN32_LEAN_AND_MEAN
#endif
#ifndef NOMINMAX
#define NOMINMAX
#define CGAL_SUBDIV_UNDEF_NOMINMAX
#endif
#include <windows.h>
#ifdef CGAL_SUBDIV_UNDEF_WIN32_LEAN_AND_MEAN
#undef WIN32_LEAN_AND_MEAN
#undef CGAL_SUBDIV_UNDEF_WIN32_LEAN_AND_MEAN
#endif
#ifdef CGAL_SUBDIV_UNDEF_NOMINMAX
#undef NOMINMAX
#undef CGAL_SUBDIV_UNDEF_NOMINMAX
#endif
#elif defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#endif

namespace CGAL {
namespace Subdiv {
namespace internal {

// What is assumed when the machine cannot be asked.
constexpr double fallback_memory_bytes = 16.0 * 1024 * 1024 * 1024;

inline double physical_memory_bytes()
{
#if defined(_WIN32)
  MEMORYSTATUSEX status;
  status.dwLength = sizeof status;
  if(GlobalMemoryStatusEx(&status) && status.ullTotalPhys > 0)
    return static_cast<double>(status.ullTotalPhys);
#elif defined(__unix__) || defined(__APPLE__)
#if defined(_SC_PHYS_PAGES) && defined(_SC_PAGE_SIZE)
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  if(pages > 0 && page_size > 0)
    return static_cast<double>(pages) * static_cast<double>(page_size);
#endif
#endif
  return fallback_memory_bytes;
}

} // namespace internal
} // namespace Subdiv
} // namespace CGAL

#endif // CGAL_SUBDIV_INTERNAL_MEMORY_H
