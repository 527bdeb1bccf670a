#!/usr/bin/env bash
# Compile time of a plain subdivision program, ours against CGAL's
# Subdivision_method_3 (issue: "compile time is part of the API").
#
#   bash src/scripts/compile_time.sh [--write-doc] [runs]     (default 5 runs)
#
# Compiles src/bench/compile_time/probe.cpp as every probe below `runs` times,
# one at a time,
# with g++ -std=c++17 -O2 as a user would, and prints the least CPU time
# (user + sys) of each, the time above the read-and-write program all probes
# share, and the ratio to Subdivision_method_3. The least of several runs is
# the figure to compare on a shared machine: the noise only ever adds.
# --write-doc also writes the table to doc/compile_time.md.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
write_doc=0
if [[ ${1:-} == --write-doc ]]; then
  write_doc=1
  shift
fi
runs=${1:-5}
[[ $runs =~ ^[1-9][0-9]*$ ]] || { echo "compile_time.sh: runs must be a positive integer, got '$runs'" >&2; exit 2; }
cxx=${CXX:-g++}
probes=(read_write sm3_catmull_clark subdiv_catmull_clark subdiv_narrow_catmull_clark sm3_loop subdiv_loop)
# the preprocessor flags of each probe (probe.cpp says what they select)
declare -A flags=(
  [read_write]=""
  [sm3_catmull_clark]="-DPROBE_SM3"
  [subdiv_catmull_clark]="-DPROBE_SUBDIV"
  [subdiv_narrow_catmull_clark]="-DPROBE_SUBDIV_NARROW"
  [sm3_loop]="-DPROBE_SM3 -DPROBE_LOOP"
  [subdiv_loop]="-DPROBE_SUBDIV -DPROBE_LOOP"
)
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

declare -A best
for ((r = 0; r < runs; ++r)); do
  for p in "${probes[@]}"; do
    /usr/bin/time -f "%U %S" -o "$out/time" "$cxx" -std=c++17 -O2 -I "$root/include" -I /usr/include/eigen3 \
      ${flags[$p]} -c "$root/src/bench/compile_time/probe.cpp" -o "$out/$p.o"
    t=$(awk '{printf "%.2f", $1 + $2}' "$out/time")
    if [[ -z ${best[$p]:-} ]] || awk -v a="$t" -v b="${best[$p]}" 'BEGIN{exit !(a < b)}'; then
      best[$p]=$t
    fi
  done
done

table() {
  echo "| program | CPU s (least of $runs) | above read+write | vs Subdivision_method_3 |"
  echo "|---|---|---|---|"
  base=${best[read_write]}
  for p in "${probes[@]}"; do
    case $p in
      *catmull_clark) ref=${best[sm3_catmull_clark]} ;;
      *loop) ref=${best[sm3_loop]} ;;
      *) ref= ;;
    esac
    above=$(awk -v a="${best[$p]}" -v b="$base" 'BEGIN{printf "%+.2f", a - b}')
    ratio=-
    [[ -n $ref ]] && ratio=$(awk -v a="${best[$p]}" -v b="$ref" 'BEGIN{printf "%.3f", a / b}')
    echo "| $p | ${best[$p]} | $above | $ratio |"
  done
  echo
  echo "($("$cxx" --version | head -1), $(nproc) cores, $(date -u +%Y-%m-%d))"
}

table
if ((write_doc)); then
  {
    echo "# Compile time"
    echo
    echo "Written by \`src/scripts/compile_time.sh --write-doc $runs\`; do not edit by hand. Each program"
    echo "(\`src/bench/compile_time/probe.cpp\`, one per library and scheme) reads a mesh, refines it 3 levels and writes it, compiled"
    echo "with \`g++ -std=c++17 -O2\` as a user would; the time is CPU (user + sys), the least"
    echo "of $runs compiles, one at a time. \`read_write\` is the part every program shares."
    echo "\`subdiv_*\` include \`<CGAL/Subdiv.h>\`, \`subdiv_narrow_*\` only"
    echo "\`<CGAL/Subdiv/surface_subdivision.h>\`, \`sm3_*\` CGAL's \`<CGAL/subdivision_method_3.h>\`."
    echo "Load average before the run: $load_before. On a shared machine the noise between"
    echo "compiles (up to 30 %) can exceed the differences in the table: compare within one run,"
    echo "and trust a difference only when it stays when the run is repeated with more compiles."
    echo
    table
  } >"$root/doc/compile_time.md"
  echo "wrote $root/doc/compile_time.md"
fi
