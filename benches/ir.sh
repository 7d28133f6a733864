#!/usr/bin/env bash
# Instructions per pixel and per triangle for one perf mode and scene, counted by callgrind.
#
#   bash benches/ir.sh MODE SCENE [FRAMES_A FRAMES_B]     (default 5 and 10 frames)
#
# Runs `examples/perf` under callgrind twice and divides the difference in instructions by the
# difference in pixels and triangles drawn, so start-up, scene building and the counting frame
# cancel out. Instruction counts repeat exactly from run to run, unlike time.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=$1 scene=$2 a=${3:-5} b=${4:-10}
command -v valgrind >/dev/null || { echo "needs valgrind (apt-get install valgrind)" >&2; exit 1; }
cargo build --profile measure -q --example perf
bin=target/measure/examples/perf
instructions() { valgrind --tool=callgrind --callgrind-out-file=/dev/null "$bin" "$mode" "$scene" "$1" 2>&1 | awk '/Collected/ {print $4}'; }
last_line() { "$bin" "$mode" "$scene" "$1" | tail -n 1; }
field() { sed -n "s/.*$1=\([0-9]*\).*/\1/p"; }
ia=$(instructions "$a") ib=$(instructions "$b")
la=$(last_line "$a") lb=$(last_line "$b")
pa=$(field pixels <<<"$la") pb=$(field pixels <<<"$lb")
ta=$(field triangles <<<"$la") tb=$(field triangles <<<"$lb")
awk -v i="$((ib - ia))" -v p="$((pb - pa))" -v t="$((tb - ta))" -v m="$mode" -v s="$scene" \
  'BEGIN { printf "%s %s: %.3f instructions/pixel, %.1f instructions/triangle (%.1f px/triangle)\n", m, s, i / p, i / t, p / t }'
