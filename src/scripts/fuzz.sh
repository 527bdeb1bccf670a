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
# Seeds, as the table below says per target: mesh seeds are every .off .obj
# .ply .stl file under 64 KiB in ../shared/data/meshes (skipped if absent) and
# test/cli/, prefixed by the byte that selects its format in the fuzzers (0 OFF,
# 1 OBJ, 2 PLY, 3 STL: the byte modulo 4) and by any further selector bytes;
# curve seeds are the .txt and .dat files of test/cli/ and every file of
# ../shared/data/curves, under 16 KiB, as they are.
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
  sed -n '2,26p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
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
# flags | seeds", paths relative to the checkout (also in -I flags). Seeds:
#  - "mesh" (or empty): the meshes, each behind its format byte;
#  - "mesh R1 R2 ...": the meshes under 16 KiB, each behind its format byte and
#    one more selector byte per Ri, which the fuzzer reads modulo Ri; the bytes
#    are the mixed-radix digits of a counter that runs on over the files, so
#    that the seeds cover the R1*R2*... combinations; rounds over the files
#    (each with new selectors) until 400 seeds;
#  - "curve": the curve files, as they are.
# A fuzzer missing from the table gets nothing extra and mesh seeds.
readonly FUZZER_TABLE=(
  "read_mesh_soup_fuzzer | | | mesh"
  "subdivide_fuzzer | src/cli/surface_from_soup.cpp | -Iinclude -lgmp -lmpfr | mesh 9 3"
  "read_polyline_fuzzer | src/cli/files.cpp src/cli/numbers.cpp | -Iinclude -lgmp -lmpfr | curve"
)

# sets `sources`, `flags` and `seed_kind` (an array: "mesh" or "curve", then
# the radices of the selector bytes) to the extras of fuzzer $1
extras_of() {
  sources=()
  flags=()
  seed_kind=(mesh)
  local row name row_sources row_flags row_seeds
  for row in "${FUZZER_TABLE[@]}"; do
    IFS='|' read -r name row_sources row_flags row_seeds <<<"$row"
    name=${name// /}
    [[ $name == "$1" ]] || continue
    local word
    for word in $row_sources; do sources+=("$root/$word"); done
    for word in $row_flags; do
      if [[ $word == -I* && $word != -I/* ]]; then
        flags+=("-I$root/${word#-I}")
      else
        flags+=("$word")
      fi
    done
    read -r -a seed_kind <<<"$row_seeds"
    [[ ${#seed_kind[@]} -gt 0 ]] || seed_kind=(mesh)
  done
}

# the seeds of a target in $1, of kind "${@:2}" (see the table); prints their count
make_seeds() {
  local seeds=$1 file extension byte count=0
  shift
  local kind=$1
  shift
  local radices=("$@")
  rm -rf "$seeds"
  mkdir -p "$seeds"
  if [[ $kind == curve ]]; then
    local dirs=("$root/test/cli")
    [[ -d $root/../shared/data/curves ]] && dirs+=("$root/../shared/data/curves")
    while IFS= read -r -d '' file; do
      if [[ $file == "$root/test/cli/"* ]]; then
        case ${file##*.} in txt | dat) ;; *) continue ;; esac
      fi
      count=$((count + 1))
      cp "$file" "$seeds/$count.${file##*.}"
    done < <(find "${dirs[@]}" -type f -size -16k -print0 | sort -z)
    echo "$count"
    return
  fi
  local dirs=("$root/test/cli")
  if [[ -d $root/../shared/data/meshes ]]; then
    dirs+=("$root/../shared/data/meshes")
  else
    echo "fuzz.sh: no ../shared/data/meshes, seeds from test/cli only" >&2
  fi
  # with selector bytes: smaller files, and a few combinations per file
  local size_limit=-64k cap=400 combinations=1 radix files=() per_file=1
  for radix in "${radices[@]}"; do combinations=$((combinations * radix)); done
  [[ ${#radices[@]} -gt 0 ]] && size_limit=-16k
  while IFS= read -r -d '' file; do
    files+=("$file")
  done < <(find "${dirs[@]}" -type f \( -iname '*.off' -o -iname '*.obj' -o -iname '*.ply' -o -iname '*.stl' \) \
    -size "$size_limit" -print0 | sort -z)
  # rounds over the files until the cap (each file once without selectors)
  if [[ ${#radices[@]} -gt 0 && ${#files[@]} -gt 0 ]]; then
    per_file=$(((cap + ${#files[@]} - 1) / ${#files[@]}))
    [[ $per_file -le $combinations ]] || per_file=$combinations
  fi
  local counter=0 variant value selectors
  for ((variant = 0; variant < per_file; ++variant)); do
    for file in "${files[@]}"; do
      [[ ${#radices[@]} -eq 0 || $count -lt $cap ]] || break 2
      extension=${file##*.}
      case ${extension,,} in
        off) byte='\x00' ;;
        obj) byte='\x01' ;;
        ply) byte='\x02' ;;
        stl) byte='\x03' ;;
        *) continue ;;
      esac
      selectors=
      value=$((counter % combinations))
      for radix in "${radices[@]}"; do
        selectors+=$(printf '\\x%02x' $((value % radix)))
        value=$((value / radix))
      done
      counter=$((counter + 1))
      count=$((count + 1))
      { printf '%b' "$byte$selectors"; cat "$file"; } >"$seeds/$count.${extension,,}"
    done
  done
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
  seed_count=$(make_seeds "$work/seeds" "${seed_kind[@]}")
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
