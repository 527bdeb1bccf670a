// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: timing, memory, the bytes model (see bench.h).
#include "bench.h"

#include <malloc.h>
#include <algorithm>
#include <chrono>
#include <fstream>
#include <sstream>

namespace subdiv_bench {

std::string scheme_name(Scheme scheme)
{
  switch(scheme) {
    case Scheme::loop:
      return "Loop";
    case Scheme::catmull_clark:
      return "Catmull-Clark";
    case Scheme::doo_sabin:
      return "Doo-Sabin";
    case Scheme::sqrt3:
      return "sqrt3";
  }
  return "?";
}

void set_heap(Heap heap)
{
  if(heap == Heap::warm) {
    mallopt(M_MMAP_MAX, 0);             // no block is mmapped: all come from the heap
    mallopt(M_TRIM_THRESHOLD, 1 << 30); // and freed memory stays mapped
  } else {
    mallopt(M_MMAP_MAX, 65536);            // glibc's default count
    mallopt(M_MMAP_THRESHOLD, 128 * 1024); // a fixed threshold: no dynamic raise
    mallopt(M_TRIM_THRESHOLD, 128 * 1024); // freed heap memory is given back
    malloc_trim(0);
  }
}

std::string heap_name(Heap heap)
{
  return heap == Heap::warm ? "warm" : "fresh";
}

double now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::vector<double> time_jobs(const std::vector<Job*>& jobs, int runs)
{
  std::vector<double> best(jobs.size(), 1e300);
  for(int round = -1; round < runs; ++round) // round -1: the warm-up
    for(std::size_t i = 0; i < jobs.size(); ++i) {
      if(jobs[i] == nullptr)
        continue;
      jobs[i]->prepare();
      const double start = now();
      jobs[i]->run();
      const double seconds = now() - start;
      if(round >= 0)
        best[i] = std::min(best[i], seconds);
    }
  return best;
}

namespace {

// a "VmRSS:   1234 kB" line of /proc/self/status, in bytes
std::size_t status_field(const std::string& field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while(std::getline(status, line))
    if(line.compare(0, field.size(), field) == 0) {
      std::istringstream value(line.substr(field.size() + 1));
      std::size_t kilobytes = 0;
      value >> kilobytes;
      return kilobytes * 1024;
    }
  return 0;
}

} // namespace

std::size_t resident_bytes()
{
  return status_field("VmRSS");
}
std::size_t peak_resident_bytes()
{
  return status_field("VmHWM");
}

bool reset_peak()
{
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.close();
  return static_cast<bool>(clear) && peak_resident_bytes() <= resident_bytes() + (1u << 20);
}

double apply_bytes(std::size_t stencils, std::size_t terms, std::size_t sources)
{
  return 12.0 * static_cast<double>(terms) + 32.0 * static_cast<double>(stencils) + 24.0 * static_cast<double>(sources);
}

double Apply_job::bytes() const
{
  return apply_bytes(stencils(), terms(), sources());
}

} // namespace subdiv_bench
