#!/usr/bin/env bash
# Checks that every tracked *.h and *.cpp file of the checkout is formatted as
# .clang-format says, with Debian 12's clang-format (14): what CI runs (ctest
# test format_check, test/format_check.cmake; doc/ci.md).
#
#   bash src/scripts/check_format.sh        # from anywhere in the checkout
#
# Exit codes: 0 formatted, 1 some file is not (each is listed, with the
# command that fixes it), 77 skipped: not a git checkout (the files checked
# are git's tracked files), git or clang-format missing, or a clang-format
# other than 14 (another version formats some constructs differently; the
# test turns 77 into "skipped").
set -euo pipefail

readonly CLANG_FORMAT_MAJOR=14

skip() {
  printf 'format check skipped: %s\n' "$*"
  exit 77
}

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd -P)
command -v git >/dev/null 2>&1 || skip "git is not installed (the check lists the tracked files with git ls-files)"
toplevel=$(git -C "$root" rev-parse --show-toplevel 2>&1) || toplevel=
[[ $toplevel == "$root" ]] ||
  skip "$root is not the top of a git checkout (the check lists the tracked files with git ls-files)${toplevel:+; git: $toplevel}"

clang_format=${CLANG_FORMAT:-}
if [[ -z $clang_format ]]; then
  for candidate in clang-format-$CLANG_FORMAT_MAJOR clang-format; do
    if command -v "$candidate" >/dev/null 2>&1; then
      clang_format=$candidate
      break
    fi
  done
fi
[[ -n $clang_format ]] || skip "clang-format is not installed (Debian: apt-get install clang-format)"
version=$("$clang_format" --version)
[[ $version =~ version[[:space:]]+([0-9]+)\. ]] || skip "cannot read the version of $clang_format: $version"
((BASH_REMATCH[1] == CLANG_FORMAT_MAJOR)) ||
  skip "$clang_format is version ${BASH_REMATCH[1]}; the tree is formatted with clang-format $CLANG_FORMAT_MAJOR (Debian 12)"

cd "$root"
mapfile -d '' files < <(git ls-files -z -- '*.h' '*.cpp')
((${#files[@]})) || skip "no tracked *.h or *.cpp file"

# one clang-format for every file; it names each file it would change
# ("FILE:LINE:COL: error: code should be clang-formatted [-Wclang-format-violations]")
existing=()
for file in "${files[@]}"; do
  [[ -f $file ]] && existing+=("$file") # not deleted in the work tree
done
status=0
report=$("$clang_format" --dry-run --Werror "${existing[@]}" 2>&1) || status=$?
mapfile -t violating < <(sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: .*\[-Wclang-format-violations\]$/\1/p' <<<"$report" | sort -u)
if ((status != 0 && ${#violating[@]} == 0)); then
  # clang-format failed in another way (a bad .clang-format, say)
  printf '%s failed (exit %d):\n%s\n' "$clang_format" "$status" "$report"
  exit 1
fi
unformatted=("${violating[@]}")
if ((${#unformatted[@]})); then
  printf 'not formatted as .clang-format says (%s):\n' "$version"
  printf '  %s\n' "${unformatted[@]}"
  printf 'fix with: %s -i %s\n' "$clang_format" "${unformatted[*]}"
  exit 1
fi
printf '%d tracked *.h and *.cpp files checked with %s: formatted\n' "${#existing[@]}" "$clang_format"
