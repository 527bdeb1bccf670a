// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: a STREAM-like measure of the memory bandwidth, in the same run
// as the rest, so that the apply rows can say what fraction of it they reach.
#ifndef SUBDIV_BENCH_STREAM_H
#define SUBDIV_BENCH_STREAM_H

#include <cstddef>

namespace subdiv_bench {

struct Bandwidth
{
  double copy = 0;  // GB/s of a[i] = b[i]: 16 B per element
  double triad = 0; // GB/s of a[i] = b[i] + s * c[i]: 24 B per element
};

/// best of `runs` passes over arrays of `elements` doubles each, with
/// `threads` std::threads on equal contiguous parts (each thread first
/// touches its own part); bytes counted as in STREAM (no write-allocate)
Bandwidth measure_bandwidth(int threads, std::size_t elements, int runs);

/// the size of the last-level cache in bytes (sysfs), 32 MiB if unknown
std::size_t last_level_cache_bytes();

} // namespace subdiv_bench

#endif // SUBDIV_BENCH_STREAM_H
