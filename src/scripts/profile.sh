#!/usr/bin/env bash
# Where the time of one benchmark job goes: perf record on
# `subdiv-bench --profile`, then the hottest functions with their template
# arguments cut off, so that the lines fit on a screen. doc/profile.md was
# made with it.
#
#   bash src/scripts/profile.sh [--heap warm|fresh] PEER SCHEME INPUT LEVELS [REPEATS]
#   bash src/scripts/profile.sh ours Loop tri20k 3 40
#
# PEER, SCHEME, INPUT as for `subdiv-bench --profile` (src/bench/README.md).
# Needs `perf` (Debian: linux-perf) and a built build/src/subdiv-bench
# (BENCH=path overrides it).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
bench="${BENCH:-$root/build/src/subdiv-bench}"
heap=(--heap warm)
if [[ "${1:-}" == "--heap" ]]; then
  heap=(--heap "$2")
  shift 2
fi
if [[ $# -lt 4 ]]; then
  sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'
  exit 2
fi
command -v perf >/dev/null || { echo "profile.sh: perf not found (apt-get install linux-perf)" >&2; exit 1; }
[[ -x "$bench" ]] || { echo "profile.sh: $bench not built (cmake --build build --target subdiv-bench)" >&2; exit 1; }

data="$(mktemp)"
trap 'rm -f "$data"' EXIT
perf record -q -o "$data" "$bench" "${heap[@]}" --profile "$@" 2>/dev/null | tail -1
# self time per function; names shortened: namespaces and template arguments dropped
perf report -i "$data" --no-children --sort symbol -g none 2>/dev/null |
  grep -E '^ +[0-9.]+%' |
  python3 -c '
import re, sys
totals = {}
for line in sys.stdin:
    m = re.match(r"\s*([0-9.]+)%\s+\[(.)\]\s+(.*)", line)
    if not m:
        continue
    share, where, name = float(m.group(1)), m.group(2), m.group(3)
    name = re.sub(r"\s+-\s+-\s*$", "", name).strip()
    lambda_in = "::{lambda" in name
    if lambda_in:
        name = name[:name.index("::{lambda")]
    # drop template arguments (nested <...>) and parameter lists, keep the last two name parts
    while True:
        shorter = re.sub(r"<[^<>]*>", "", name)
        if shorter == name:
            break
        name = shorter
    name = re.sub(r"\([^()]*\)", "", name)
    name = re.sub(r"\([^()]*\)", "", name)
    name = "::".join(name.split("::")[-2:]) if where == "." else "[kernel] " + name
    if lambda_in:
        name += " (a lambda in it)"
    totals[name] = totals.get(name, 0) + share
for name, share in sorted(totals.items(), key=lambda x: -x[1])[:15]:
    if share >= 0.5:
        print("%6.1f %%  %s" % (share, name))
'
