// SPDX-License-Identifier: LGPL-3.0-or-later
// Copyright (c) 2026 CGAL Subdiv contributors
//
// subdiv-bench: what the parts of the benchmark share (src/bench/README.md).
//
// Every timed piece of work is a Job: prepare() runs outside the timer (it
// frees the previous result and copies the input), run() is timed, and the
// result of the last run stays in the job until the next prepare() or the
// job's end, so that it can be compared with the other libraries' results.
// The peers (OpenMesh, OpenSubdiv) see the inputs as a Soup (points and
// faces by index), converted into their own mesh types in prepare() or when
// the job is made, never inside the timer.
#ifndef SUBDIV_BENCH_BENCH_H
#define SUBDIV_BENCH_BENCH_H

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace subdiv_bench {

using P3 = std::array<double, 3>;

/// a polygon mesh as arrays: what every library is given
struct Soup
{
  std::vector<P3> points;
  std::vector<int> face_sizes;
  std::vector<int> indices; // the corners of face 0, then face 1, ...
  // the sharp edges (OpenSubdiv's creases): vertex pairs and sharpness values,
  // empty for the smooth inputs
  std::vector<int> crease_pairs;
  std::vector<float> crease_sharpness;
  // the texture coordinates (OpenSubdiv's face-varying channel): the values,
  // and the value of every corner, index for index with `indices`; empty for
  // the inputs without them
  std::vector<std::array<double, 2>> uvs;
  std::vector<int> uv_indices;
};

/// the soup as a mesh of any library whose `add_vertex(Point)` returns a
/// vertex handle and whose `add_face` takes a vector of them (Surface_mesh,
/// OpenMesh); `Point` is made from the three coordinates
template <class Mesh, class Point, class VertexHandle>
Mesh mesh_from_soup(const Soup& soup)
{
  Mesh mesh;
  std::vector<VertexHandle> v;
  v.reserve(soup.points.size());
  for(const P3& p : soup.points)
    v.push_back(mesh.add_vertex(Point(p[0], p[1], p[2])));
  std::vector<VertexHandle> face;
  std::size_t at = 0;
  for(const int size : soup.face_sizes) {
    face.clear();
    for(int i = 0; i < size; ++i)
      face.push_back(v[static_cast<std::size_t>(soup.indices[at++])]);
    mesh.add_face(face);
  }
  return mesh;
}

enum class Scheme { loop, catmull_clark, doo_sabin, sqrt3 };
std::string scheme_name(Scheme scheme);

/// a parameter of the limit surface: (u, v) in the quad (Catmull-Clark) or
/// triangle (Loop) `face`, the face's number in the Soup and the Surface_mesh,
/// its corner 0 at (0, 0), its corner 1 at (1, 0)
struct Limit_location
{
  int face;
  double u, v;
};

/// a timed piece of work (see the top of this file)
class Job
{
public:
  virtual ~Job() = default;
  /// outside the timer: frees the previous result, makes a fresh copy of the input
  virtual void prepare() {}
  /// the timed work
  virtual void run() = 0;
  /// the faces of the result of the last run (0 if the job makes no mesh)
  virtual std::size_t output_faces() const { return 0; }
  /// the points of the result of the last run (empty if the job makes none)
  virtual std::vector<P3> output_points() const { return {}; }
};

using Job_ptr = std::unique_ptr<Job>;

/// one warm-up run of each job, then `runs` rounds in which every job runs
/// once (interleaved); returns the minimum time of each job, in seconds
std::vector<double> time_jobs(const std::vector<Job*>& jobs, int runs);

/// How glibc's malloc treats large blocks, for every library alike.
/// warm: every block comes from the heap and freed memory is kept, so a
/// repeated run reuses pages already mapped (a program that refines again and
/// again); fresh: every block of 128 KiB or more is a new mmap and is unmapped
/// when freed, so each run pays the first touch of its memory (a program that
/// refines once). glibc's default lies in between and depends on the history:
/// blocks up to 32 MiB are reused after a first free, larger ones never.
enum class Heap { warm, fresh };
void set_heap(Heap heap);
std::string heap_name(Heap heap);

/// seconds since an arbitrary origin (steady clock)
double now();

/// the resident set size and its high-water mark of this process, in bytes
/// (from /proc/self/status); reset_peak() restarts the high-water mark at the
/// current size (writes 5 to /proc/self/clear_refs), false if it cannot
std::size_t resident_bytes();
std::size_t peak_resident_bytes();
bool reset_peak();

// --- the stencil tables of the libraries, for the apply rows ----------------------

/// a stencil table ready to be applied many times, and what it holds
class Apply_job : public Job
{
public:
  virtual std::size_t stencils() const = 0;
  virtual std::size_t terms() const = 0;
  virtual std::size_t sources() const = 0;
  virtual void set_threads(int threads) = 0;
  /// the bytes one apply moves at least (apply_bytes() below, unless the table
  /// holds floats)
  virtual double bytes() const;
};
using Apply_ptr = std::unique_ptr<Apply_job>;

/// the bytes one apply must move at least, the same model for every library:
/// each term reads its weight (8 B, double) and source index (4 B), each
/// stencil reads where it ends (8 B) and writes its point (24 B), each source
/// point is read once (24 B). Repeated reads of a source (served by the cache
/// or not) and the write-allocate read of the output are not counted, as in STREAM.
double apply_bytes(std::size_t stencils, std::size_t terms, std::size_t sources);

} // namespace subdiv_bench

#endif // SUBDIV_BENCH_BENCH_H
