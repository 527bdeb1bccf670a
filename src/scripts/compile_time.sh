#!/usr/bin/env bash
# Compile time of a plain subdivision program, ours against CGAL's
# Subdivision_method_3 (issue: "compile time is part of the API").
#
#   bash src/scripts/compile_time.sh [--write-doc] [runs]     (default 5 runs)
#   bash src/scripts/compile_time.sh --instructions [--write-doc]
#
# --instructions counts, instead of timing, the instructions the compiler runs
# for refine_only.cpp (valgrind's callgrind on g++ and its children, cc1plus
# above all): the same count on every run, whatever else the machine does, so
# a difference of 1 % is real. It takes about 2 minutes per probe; with
# --write-doc it writes doc/compile_instructions.md.
#
# Compiles src/bench/compile_time/probe.cpp (read, refine, write) and
# refine_only.cpp (the refinement alone) as every probe below `runs` times,
# one at a time, taking turns,
# with g++ -std=c++17 -O2 as a user would, and prints the least CPU time
# (user + sys) of each, the time above the read-and-write program all probes
# share, and the ratio to Subdivision_method_3. The least of several runs is
# the figure to compare on a shared machine: the noise only ever adds.
# --write-doc also writes the table to doc/compile_time.md.
#
# A step in the second table is not always code: g++ collects its garbage
# when its heap has doubled since the last collection, so a few thousand more
# tokens anywhere in the file can move the first collection and add a second
# one, about 0.8 G of the 23 G instructions cc1plus runs for refine_only.cpp
# (c7d9f24's Loop probe plus 5000 empty static_asserts gets it, as the one
# did at fd32dfe). To compare without noise, count instructions with
# `valgrind --tool=callgrind` on cc1plus (`g++ -###` shows its command line)
# and subtract the inclusive count of ggc_collect.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
write_doc=0
if [[ ${1:-} == --instructions ]]; then
  command -v valgrind >/dev/null || { echo "compile_time.sh: --instructions needs valgrind" >&2; exit 2; }
  cxx=${CXX:-g++}
  out=$(mktemp -d)
  trap 'rm -rf "$out"' EXIT
  declare -A count
  for p in read_write sm3_catmull_clark subdiv_narrow_catmull_clark sm3_loop subdiv_narrow_loop; do
    case $p in
      read_write) f="" ;;
      sm3_catmull_clark) f="-DPROBE_SM3" ;;
      subdiv_narrow_catmull_clark) f="-DPROBE_SUBDIV_NARROW" ;;
      sm3_loop) f="-DPROBE_SM3 -DPROBE_LOOP" ;;
      subdiv_narrow_loop) f="-DPROBE_SUBDIV_NARROW -DPROBE_LOOP" ;;
    esac
    rm -f "$out"/cg.*
    # shellcheck disable=SC2086
    valgrind --tool=callgrind --trace-children=yes --callgrind-out-file="$out/cg.%p" "$cxx" -std=c++17 -O2 \
      -I "$root/include" $f -c "$root/src/bench/compile_time/refine_only.cpp" -o "$out/$p.o" 2>/dev/null
    count[$p]=$(awk '/^summary:/ {s += $2} END {printf "%.0f", s}' "$out"/cg.*)
  done
  instruction_table() {
    echo "| program (refine_only.cpp) | instructions (G) | above Surface_mesh | vs Subdivision_method_3 |"
    echo "|---|---|---|---|"
    for p in read_write sm3_catmull_clark subdiv_narrow_catmull_clark sm3_loop subdiv_narrow_loop; do
      ref=-
      case $p in
        *catmull_clark) ref=${count[sm3_catmull_clark]} ;;
        *loop) ref=${count[sm3_loop]} ;;
      esac
      awk -v p="$p" -v c="${count[$p]}" -v b="${count[read_write]}" -v r="$ref" 'BEGIN {
        printf "| %s | %.2f | %+.2f | %s |\n", p, c / 1e9, (c - b) / 1e9, r == "-" ? "-" : sprintf("%.3f", c / r) }'
    done
  }
  instruction_table
  if [[ ${2:-} == --write-doc ]]; then
    {
      echo "# Compile time, in instructions"
      echo
      echo "Written by \`src/scripts/compile_time.sh --instructions --write-doc\`; do not edit by hand."
      echo "The instructions g++ and its children (cc1plus above all) run to compile"
      echo "\`src/bench/compile_time/refine_only.cpp\` (a function that refines a \`Surface_mesh\` 3 levels)"
      echo "with \`-std=c++17 -O2\`, counted by valgrind's callgrind: the same on every run, unlike the"
      echo "CPU times of [compile_time.md](compile_time.md). \`subdiv_narrow_*\` include only the scheme's"
      echo "header, \`sm3_*\` CGAL's \`<CGAL/subdivision_method_3.h>\`, \`read_write\` \`<CGAL/Surface_mesh.h>\` alone."
      echo "The count includes g++'s garbage collections, which run when its heap has doubled"
      echo "since the last one: a small change anywhere can add or remove one (0.4 to 0.9 G here)."
      echo
      instruction_table
      echo
      echo "($("$cxx" --version | head -1), $(date -u +%Y-%m-%d))"
    } >"$root/doc/compile_instructions.md"
    echo "wrote $root/doc/compile_instructions.md"
  fi
  exit 0
fi
if [[ ${1:-} == --write-doc ]]; then
  write_doc=1
  shift
fi
runs=${1:-5}
[[ $runs =~ ^[1-9][0-9]*$ ]] || { echo "compile_time.sh: runs must be a positive integer, got '$runs'" >&2; exit 2; }
cxx=${CXX:-g++}
probes=(read_write sm3_catmull_clark subdiv_catmull_clark subdiv_narrow_catmull_clark sm3_loop subdiv_loop subdiv_narrow_loop)
# the preprocessor flags of each probe (probe.cpp says what they select)
declare -A flags=(
  [read_write]=""
  [sm3_catmull_clark]="-DPROBE_SM3"
  [subdiv_catmull_clark]="-DPROBE_SUBDIV"
  [subdiv_narrow_catmull_clark]="-DPROBE_SUBDIV_NARROW"
  [sm3_loop]="-DPROBE_SM3 -DPROBE_LOOP"
  [subdiv_loop]="-DPROBE_SUBDIV -DPROBE_LOOP"
  [subdiv_narrow_loop]="-DPROBE_SUBDIV_NARROW -DPROBE_LOOP"
)
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# the two programs: the whole one, and the refinement alone
sources=(probe refine_only)

declare -A best
for ((r = 0; r < runs; ++r)); do
  for source in "${sources[@]}"; do
    for p in "${probes[@]}"; do
      /usr/bin/time -f "%U %S" -o "$out/time" "$cxx" -std=c++17 -O2 -I "$root/include" -I /usr/include/eigen3 \
        ${flags[$p]} -c "$root/src/bench/compile_time/$source.cpp" -o "$out/$p.o"
      t=$(awk '{printf "%.2f", $1 + $2}' "$out/time")
      key="$source/$p"
      if [[ -z ${best[$key]:-} ]] || awk -v a="$t" -v b="${best[$key]}" 'BEGIN{exit !(a < b)}'; then
        best[$key]=$t
      fi
    done
  done
done

# table SOURCE FIRST_COLUMN: the least times of the probes of SOURCE.cpp
table() {
  local source=$1 shared=$2
  echo "| program | CPU s (least of $runs) | above $shared | vs Subdivision_method_3 |"
  echo "|---|---|---|---|"
  local base=${best[$source/read_write]}
  for p in "${probes[@]}"; do
    local ref= ratio=- above
    case $p in
      *catmull_clark) ref=${best[$source/sm3_catmull_clark]} ;;
      *loop) ref=${best[$source/sm3_loop]} ;;
    esac
    above=$(awk -v a="${best[$source/$p]}" -v b="$base" 'BEGIN{printf "%+.2f", a - b}')
    [[ -n $ref ]] && ratio=$(awk -v a="${best[$source/$p]}" -v b="$ref" 'BEGIN{printf "%.3f", a / b}')
    echo "| $p | ${best[$source/$p]} | $above | $ratio |"
  done
}

tables() {
  echo "Whole program (\`probe.cpp\`: read, refine 3 levels, write; \`read_write\` is the part every program shares):"
  echo
  table probe "read+write"
  echo
  echo "Refinement alone (\`refine_only.cpp\`: a function that refines a \`Surface_mesh\` 3 levels; \`read_write\`"
  echo "is here the same function clearing the mesh, i.e. \`<CGAL/Surface_mesh.h>\` alone):"
  echo
  table refine_only "Surface_mesh"
  echo
  echo "($("$cxx" --version | head -1), $(nproc) cores, $(date -u +%Y-%m-%d))"
}

tables
if ((write_doc)); then
  {
    echo "# Compile time"
    echo
    echo "Written by \`src/scripts/compile_time.sh --write-doc $runs\`; do not edit by hand. Each program"
    echo "(\`src/bench/compile_time/\`, one per library and scheme) is compiled"
    echo "with \`g++ -std=c++17 -O2\` as a user would; the time is CPU (user + sys), the least"
    echo "of $runs compiles, the compiles of every program taking turns."
    echo "\`subdiv_*\` include \`<CGAL/Subdiv.h>\`, \`subdiv_narrow_*\` only the scheme's header"
    echo "(\`<CGAL/Subdiv/loop_subdivision.h>\`, \`<CGAL/Subdiv/catmull_clark_subdivision.h>\`),"
    echo "\`sm3_*\` CGAL's \`<CGAL/subdivision_method_3.h>\`."
    echo "Load average before the run: $load_before. On a shared machine the noise between"
    echo "compiles (up to 30 %) can exceed the differences in the first table: the second, where"
    echo "the shared part is a quarter as large, resolves them better. Trust a difference only"
    echo "when it stays when the run is repeated with more compiles."
    echo
    tables
  } >"$root/doc/compile_time.md"
  echo "wrote $root/doc/compile_time.md"
fi
