#!/bin/sh
# Painting file load and save, two builds of paintcore on one machine (docs/painting-format.md):
# painting_io_compare.cpp is built against each source tree's build/release libraries, then
# each operation runs RUNS times, the two builds alternating; medians and ratios are printed.
# The painting must be one both builds read (an older build refuses newer versions).
#   tests/bench/painting_io_compare.sh BEFORE_TREE AFTER_TREE PAINTING [RUNS]
set -eu
before=$1 after=$2 painting=$3 runs=${4:-5}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
here=$(cd "$(dirname "$0")" && pwd)
for side in before after; do
  eval tree=\$$side
  g++ -O2 -std=c++20 -I "$tree/paintcore/include" -o "$work/$side" "$here/painting_io_compare.cpp" \
    "$tree/build/release/paintcore/libimpasto_paintcore.a" \
    "$tree/build/release/files/libimpasto_files.a" "$tree/build/release/util/libimpasto_util.a" \
    -ltbb -lpthread
done
for op in load save; do
  i=0
  while [ $i -lt "$runs" ]; do
    for side in before after; do
      "$work/$side" $op "$painting" "$work/out.impasto" | sed "s/^/{\"side\":\"$side\",\"run\":$i,\"row\":/; s/\$/}/"
    done
    i=$((i + 1))
  done
done | /usr/bin/python3 -c '
import json, statistics, sys
rows = [json.loads(line) for line in sys.stdin]
def median(op, side, key):
    return statistics.median(r["row"][key] for r in rows if r["side"] == side and r["row"]["op"] == op)
for op in ("load", "save"):
    b, a = median(op, "before", "ms"), median(op, "after", "ms")
    cb, ca = median(op, "before", "cpu_ms"), median(op, "after", "cpu_ms")
    mb, ma = median(op, "before", "peak_extra_mb"), median(op, "after", "peak_extra_mb")
    print("%s: wall %.0f -> %.0f ms (%.2fx), CPU %.0f -> %.0f ms (%.2fx), peak memory added %.0f -> %.0f MB" % (op, b, a, b / a, cb, ca, cb / ca, mb, ma))
'
