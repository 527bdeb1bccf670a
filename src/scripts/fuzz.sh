#!/usr/bin/env bash
# Fuzzes the parts of cgal-subdiv that read untrusted files: builds every
# libFuzzer target src/fuzz/*_fuzzer.cpp with clang++, ASan and UBSan, gives
# each a seed corpus, runs each for a while and fails if one crashes.
#
#   bash src/scripts/fuzz.sh [--seconds N] [--build DIR] [-- LIBFUZZER_FLAGS...]
#   nice -n 19 bash src/scripts/fuzz.sh --seconds 120
#
#   --seconds N  how long each target runs (default 60)
#   --build DIR  binaries, corpora, logs and crash inputs (default build-fuzz/
#                in the checkout); each target gets DIR/TARGET/ with seeds/
#                (rebuilt each run), corpus/ (kept: what libFuzzer found),
#                crashes/ and fuzz.log
#   after --      further flags for libFuzzer, e.g. -jobs=2 -workers=2
#
# Seeds: every .off .obj .ply .stl file under 64 KiB in ../shared/data/meshes
# (skipped if absent) and test/cli/, prefixed by the byte that selects its
# format in the fuzzers (0 OFF, 1 OBJ, 2 PLY, 3 STL: the byte modulo 4).
# Prints, per target, libFuzzer's final "#N DONE" line (N inputs run).
# Exit codes: 0 no crash, 1 a build failed or a target crashed (the input is
# in DIR/TARGET/crashes/, the report in DIR/TARGET/fuzz.log), 2 usage.
# Needs clang++ with libFuzzer (Debian: clang, libclang-rt-dev).
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd -P)
seconds=60
build="$root/build-fuzz"
extra_flags=()

usage() {
  sed -n '2,23p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
  exit 2
}

while [[ $# -gt 0 ]]; do
  case $1 in
    --seconds)
      [[ $# -ge 2 && $2 =~ ^[1-9][0-9]*$ ]] || usage
      seconds=$2
      shift 2
      ;;
    --build)
      [[ $# -ge 2 ]] || usage
      build=$2
      shift 2
      ;;
    --)
      shift
      extra_flags=("$@")
      break
      ;;
    *) usage ;;
  esac
done

# What every fuzzer is built with; the table below adds per-fuzzer needs.
readonly CXX=${CXX_FUZZ:-clang++}
readonly COMMON_FLAGS=(-std=c++17 -g -O1 "-fsanitize=fuzzer,address,undefined" -fno-sanitize-recover=all
  -Wall -Wextra -I"$root/src/cli")
readonly COMMON_SOURCES=("$root/src/cli/mesh_soup.cpp")
readonly LIBFUZZER_FLAGS=(-max_len=65536 -timeout=10 -rss_limit_mb=2048)

# Per fuzzer, what it needs beyond the above: "NAME | extra sources | extra
# flags", paths relative to the checkout. A fuzzer of the library would say
# e.g. "subdivide_fuzzer | | -Iinclude -I/usr/include/eigen3 -lgmp -lmpfr".
# A fuzzer missing from the table gets nothing extra.
readonly FUZZER_TABLE=(
  "read_mesh_soup_fuzzer | | "
)

# sets `sources` and `flags` to the extras of fuzzer $1
extras_of() {
  sources=()
  flags=()
  local row name row_sources row_flags
  for row in "${FUZZER_TABLE[@]}"; do
    IFS='|' read -r name row_sources row_flags <<<"$row"
    name=${name// /}
    [[ $name == "$1" ]] || continue
    local word
    for word in $row_sources; do sources+=("$root/$word"); done
    for word in $row_flags; do flags+=("$word"); done
  done
}

# the seeds of every target: the meshes, each prefixed by its format byte
make_seeds() {
  local seeds=$1 file extension byte count=0
  rm -rf "$seeds"
  mkdir -p "$seeds"
  local dirs=("$root/test/cli")
  if [[ -d $root/../shared/data/meshes ]]; then
    dirs+=("$root/../shared/data/meshes")
  else
    echo "fuzz.sh: no ../shared/data/meshes, seeds from test/cli only" >&2
  fi
  while IFS= read -r -d '' file; do
    extension=${file##*.}
    case ${extension,,} in
      off) byte='\x00' ;;
      obj) byte='\x01' ;;
      ply) byte='\x02' ;;
      stl) byte='\x03' ;;
      *) continue ;;
    esac
    count=$((count + 1))
    { printf '%b' "$byte"; cat "$file"; } >"$seeds/$count.${extension,,}"
  done < <(find "${dirs[@]}" -type f \( -iname '*.off' -o -iname '*.obj' -o -iname '*.ply' -o -iname '*.stl' \) \
    -size -64k -print0 | sort -z)
  echo "$count"
}

shopt -s nullglob
fuzzers=("$root"/src/fuzz/*_fuzzer.cpp)
[[ ${#fuzzers[@]} -gt 0 ]] || { echo "fuzz.sh: no src/fuzz/*_fuzzer.cpp" >&2; exit 1; }
command -v "$CXX" >/dev/null || { echo "fuzz.sh: $CXX not found" >&2; exit 1; }
mkdir -p "$build"
build=$(cd "$build" && pwd -P)

failed=()
summary=()
for source in "${fuzzers[@]}"; do
  name=$(basename "$source" .cpp)
  work="$build/$name"
  mkdir -p "$work/corpus" "$work/crashes"
  extras_of "$name"
  echo "== $name: building"
  if ! "$CXX" "${COMMON_FLAGS[@]}" "$source" "${COMMON_SOURCES[@]}" "${sources[@]}" "${flags[@]}" -o "$work/$name"; then
    failed+=("$name (build)")
    continue
  fi
  seed_count=$(make_seeds "$work/seeds")
  echo "== $name: $seed_count seeds, fuzzing for $seconds s (log: $work/fuzz.log)"
  status=0
  "$work/$name" "$work/corpus" "$work/seeds" "${LIBFUZZER_FLAGS[@]}" -max_total_time="$seconds" \
    -artifact_prefix="$work/crashes/" -print_final_stats=1 "${extra_flags[@]}" >"$work/fuzz.log" 2>&1 || status=$?
  done_line=$(grep -E '^#[0-9]+[[:space:]]+DONE' "$work/fuzz.log" | tail -1 || true)
  runs=$(grep -E '^Done [0-9]+ runs' "$work/fuzz.log" | tail -1 || true)
  if [[ $status -ne 0 ]]; then
    failed+=("$name")
    echo "== $name: FAILED (exit $status); the report:"
    grep -E 'ERROR|SUMMARY|Test unit written|panic|deadly signal|Timeout|out-of-memory' "$work/fuzz.log" | head -20 || true
    summary+=("$name: FAILED after ${done_line:-an unknown number of inputs}")
  else
    summary+=("$name: ${done_line:-no DONE line} ${runs:+($runs)}")
  fi
done

echo "== summary"
printf '%s\n' "${summary[@]}"
if [[ ${#failed[@]} -gt 0 ]]; then
  echo "fuzz.sh: failed: ${failed[*]}" >&2
  exit 1
fi
