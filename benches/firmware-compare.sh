#!/usr/bin/env bash
# Every figure of the firmware benchmark (`examples/firmware.rs`) at a base revision against the
# working tree, on Cortex-M0 and Cortex-M4F, under QEMU: instructions per pixel and per triangle
# for each mode and scene, their change, and whether each frame's checksum stayed the same.
# Instruction counts repeat exactly, so any change is the code's.
#
#   bash benches/firmware-compare.sh [--modes LIST] [--cores m0,m4] [BASE]
#   bash benches/firmware-compare.sh HEAD                       # uncommitted changes, every mode
#   bash benches/firmware-compare.sh --modes aa-flat,flat main  # a subset: builds in seconds
#
# BASE is any revision (default HEAD); it is built from a `git worktree` outside the tree (in
# $TMPDIR, kept between runs: cargo reads the `.cargo/config.toml` of every directory above the
# one it runs in, so a worktree inside would link `memory.x` twice). `--modes` builds only those
# modes (`FW_MODES`) on both sides: compare a subset against the same subset, since the code's
# placement alone moves figures by a few percent on Cortex-M0, and confirm in the every-mode
# build before landing. Exits 1 when a checksum differs between the two sides or a frame does
# not match the host's (a change meant to keep the pixels bit for bit did not), else 0. Needs
# `../shared/embedded/xcargo`, QEMU (`../shared/embedded/setup`) and python3.
set -euo pipefail
cd "$(dirname "$0")/.."
modes="" cores="m0,m4"
while [ $# -gt 0 ]; do
  case $1 in
    --modes) modes=$2; shift 2 ;;
    --cores) cores=$2; shift 2 ;;
    -h|--help) sed -n '2,18p' "$0"; exit 0 ;;
    *) break ;;
  esac
done
base=${1:-HEAD}
root=$PWD
out=$root/target/firmware-compare
xcargo=$root/../shared/embedded/xcargo
mkdir -p "$out"
rev=$(git rev-parse --verify "$base^{commit}")
# One worktree per clone (named after the clone's path), reused: only what changed rebuilds.
tree=${TMPDIR:-/tmp}/trirast-firmware-compare-$(cksum <<<"$root" | cut -d' ' -f1)
if [ -d "$tree" ] && git -C "$tree" rev-parse --git-dir >/dev/null 2>&1; then
  git -C "$tree" checkout -q --detach "$rev"
else
  rm -rf "$tree"
  git worktree prune
  git worktree add -q --detach "$tree" "$rev"
fi
run() { # run DIR CORE TAG: the firmware's output for DIR on CORE
  local dir=$1 core=$2 tag=$3 target
  case $core in
    m0) target=thumbv6m-none-eabi ;;
    m4) target=thumbv7em-none-eabihf ;;
    *) echo "unknown core $core (m0 or m4)" >&2; exit 2 ;;
  esac
  (cd "$dir" && env ${modes:+FW_MODES=$modes} CARGO_TARGET_DIR="$out/build-$tag-$core" \
    "$xcargo" "$target" run --profile measure -q --example firmware --features firmware) \
    >"$out/$tag-$core.txt" 2>&1 || true
}
status=0
for core in ${cores//,/ }; do
  run "$tree" "$core" base &
  run "$root" "$core" head &
  wait
  echo "== $core: $(git log -1 --format='%h %s' "$rev" | cut -c1-60) -> working tree${modes:+ (modes $modes)}"
  python3 - "$out/base-$core.txt" "$out/head-$core.txt" <<'PY' || status=1
import re, sys
line = re.compile(r"(\S+)\s+(\S+)\s+checksum=(\S+) (\S+) instructions=(\d+) .*per_pixel=([\d.]+) per_triangle=([\d.]+)")
def load(path):
    figures = {}
    for text in open(path, errors="replace"):
        m = line.match(text)
        if m:
            figures[(m[1], m[2])] = (m[3], m[4], int(m[5]), float(m[6]), float(m[7]))
    return figures
base, head = load(sys.argv[1]), load(sys.argv[2])
if not base or not head:
    print(f"no figures: see {sys.argv[1] if not base else sys.argv[2]}")
    sys.exit(1)
bad = 0
print(f"{'mode':16} {'scene':9} {'per pixel':>19} {'per triangle':>23} {'change':>8}  frame")
for key in base:
    if key not in head:
        print(f"{key[0]:16} {key[1]:9} missing in the working tree's build")
        bad += 1
        continue
    b, h = base[key], head[key]
    change = 100.0 * (h[2] - b[2]) / b[2]
    same = b[0] == h[0] and h[1] == "ok"
    bad += not same
    frame = "same" if same else f"CHANGED {b[0]} -> {h[0]} ({h[1]})"
    print(f"{key[0]:16} {key[1]:9} {b[3]:>9.2f} {h[3]:>9.2f} {b[4]:>11.1f} {h[4]:>11.1f} {change:>+7.2f}%  {frame}")
sys.exit(1 if bad else 0)
PY
done
exit $status
