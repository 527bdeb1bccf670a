#!/bin/sh
# A run of cgal-subdiv stopped by SIGTERM while it writes its output leaves
# nothing behind: neither OUTPUT nor the temporary file it writes first.
#   sh signal_cleanup.sh EXE WORKDIR MESH
set -u
exe=$1 work=$2 mesh=$3
rm -rf "$work" && mkdir -p "$work" || exit 1
# 7 levels of Loop on the 64 triangles of the torus: a million faces, whose
# ASCII output takes seconds to write
"$exe" surface "$mesh" -o "$work/out.off" --scheme loop --levels 7 >/dev/null 2>&1 &
pid=$!
tries=0
while [ ! -e "$work/out.off.tmp$pid" ]; do
  tries=$((tries + 1))
  if [ $tries -gt 1200 ] || ! kill -0 $pid 2>/dev/null; then
    echo "the temporary file $work/out.off.tmp$pid never appeared"
    kill -KILL $pid 2>/dev/null
    exit 1
  fi
  sleep 0.05
done
kill -TERM $pid
wait $pid
rc=$?
if [ $rc -ne 143 ]; then
  echo "exit status $rc after SIGTERM, expected 143 (killed by the signal)"
  exit 1
fi
left=$(ls -A "$work")
if [ -n "$left" ]; then
  echo "left behind in $work: $left"
  exit 1
fi
echo "SIGTERM while writing: exit 143, nothing left behind"
