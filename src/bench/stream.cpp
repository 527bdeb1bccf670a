// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: the bandwidth baseline (see stream.h).
#include "stream.h"

#include "bench.h"

#include <algorithm>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace subdiv_bench {
namespace {

// runs body(first, last) on `threads` equal parts of [0, n), one std::thread each
void split(int threads, std::size_t n, const std::function<void(std::size_t, std::size_t)>& body)
{
  std::vector<std::thread> others;
  const std::size_t part = n / static_cast<std::size_t>(threads);
  for(int t = 1; t < threads; ++t) {
    const std::size_t first = part * static_cast<std::size_t>(t);
    const std::size_t last = t + 1 == threads ? n : first + part;
    others.emplace_back([&body, first, last] { body(first, last); });
  }
  body(0, threads == 1 ? n : part);
  for(std::thread& t : others)
    t.join();
}

} // namespace

Bandwidth measure_bandwidth(int threads, std::size_t n, int runs)
{
  std::unique_ptr<double[]> a(new double[n]), b(new double[n]), c(new double[n]);
  double* const pa = a.get();
  double* const pb = b.get();
  double* const pc = c.get();
  split(threads, n, [=](std::size_t first, std::size_t last) {
    for(std::size_t i = first; i < last; ++i) {
      pa[i] = 0;
      pb[i] = 1;
      pc[i] = 2;
    }
  });
  const double scalar = 3;
  double copy = 1e300, triad = 1e300;
  for(int r = -1; r < runs; ++r) {
    double start = now();
    split(threads, n, [=](std::size_t first, std::size_t last) {
      for(std::size_t i = first; i < last; ++i)
        pa[i] = pb[i];
    });
    if(r >= 0)
      copy = std::min(copy, now() - start);
    start = now();
    split(threads, n, [=](std::size_t first, std::size_t last) {
      for(std::size_t i = first; i < last; ++i)
        pa[i] = pb[i] + scalar * pc[i];
    });
    if(r >= 0)
      triad = std::min(triad, now() - start);
  }
  const double bytes = static_cast<double>(n) * 8;
  return Bandwidth{2 * bytes / copy / 1e9, 3 * bytes / triad / 1e9};
}

std::size_t last_level_cache_bytes()
{
  std::size_t best = 0;
  for(int index = 0; index < 8; ++index) {
    std::ifstream file("/sys/devices/system/cpu/cpu0/cache/index" + std::to_string(index) + "/size");
    std::string text;
    if(!(file >> text) || text.empty())
      continue;
    std::size_t value = std::stoul(text);
    const char unit = text.back();
    value *= unit == 'K' ? 1024 : unit == 'M' ? 1024 * 1024 : 1;
    best = std::max(best, value);
  }
  return best == 0 ? std::size_t(32) << 20 : best;
}

} // namespace subdiv_bench
