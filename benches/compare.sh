#!/usr/bin/env bash
# trirast beside embedded-graphics' `Triangle` and embedded-3dgfx, on the same scenes and the
# same 320x240 `Rgb565` framebuffer, counted by callgrind (instructions repeat exactly from run
# to run; time does not on a shared machine). Prints a Markdown table.
#
#   bash benches/compare.sh [FRAMES_A FRAMES_B]      (default 2 and 4)
#
# Each figure is the difference between a FRAMES_B and a FRAMES_A run divided by the difference
# in pixels or triangles drawn, so start-up, scene building and the counting frame cancel out.
# Pixels are those the rasterizer wrote, overdraw included: per-triangle figures are the fair
# comparison for rasterizers that draw shared edges twice.
set -euo pipefail
cd "$(dirname "$0")/.."
a=${1:-2} b=${2:-4}
command -v valgrind >/dev/null || { echo "needs valgrind (apt-get install valgrind)" >&2; exit 1; }
cargo build --profile measure -q --example perf
cargo build --release -q --manifest-path benches/peers/Cargo.toml
ours=target/measure/examples/perf
peers=benches/peers/target/release/trirast-peers

instructions() { valgrind --tool=callgrind --callgrind-out-file=/dev/null "$@" 2>&1 | awk '/Collected/ {print $4}'; }
field() { sed -n "s/.*$1=\([0-9]*\).*/\1/p"; }
declare -A ipp ipt ppt over gap
measure() { # measure BIN MODE SCENE
  local bin=$1 mode=$2 scene=$3
  local ia ib la lb
  ia=$(instructions "$bin" "$mode" "$scene" "$a")
  ib=$(instructions "$bin" "$mode" "$scene" "$b")
  la=$("$bin" "$mode" "$scene" "$a" | tail -n 2)
  lb=$("$bin" "$mode" "$scene" "$b" | tail -n 1)
  local pa pb ta tb
  pa=$(tail -n 1 <<<"$la" | field pixels) pb=$(field pixels <<<"$lb")
  ta=$(tail -n 1 <<<"$la" | field triangles) tb=$(field triangles <<<"$lb")
  local key="$mode/$scene"
  ipp[$key]=$(awk -v i="$((ib - ia))" -v p="$((pb - pa))" 'BEGIN { printf "%.2f", i / p }')
  ipt[$key]=$(awk -v i="$((ib - ia))" -v t="$((tb - ta))" 'BEGIN { printf "%.0f", i / t }')
  ppt[$key]=$(awk -v p="$((pb - pa))" -v t="$((tb - ta))" 'BEGIN { printf "%.1f", p / t }')
  over[$key]=$(head -n 1 <<<"$la" | field overdraw)
  gap[$key]=$(head -n 1 <<<"$la" | field gaps)
}

scenes=(big small mesh)
our_modes=(flat gouraud gouraud-z tex-nearest tex-bilinear band)
for scene in "${scenes[@]}"; do
  for mode in "${our_modes[@]}" eg-flat; do measure "$ours" "$mode" "$scene"; done
  for mode in 3dgfx-flat 3dgfx-gouraud; do measure "$peers" "$mode" "$scene"; done
done

ratio() { awk -v x="$1" -v y="$2" 'BEGIN { printf "%.1fx", y / x }'; }
echo "Callgrind instructions, x86-64, $(date -u +%Y-%m-%d), \`bash benches/compare.sh $a $b\`"
echo
echo "| Mode | Scene | px/triangle | instructions/pixel | instructions/triangle | overdraw | gaps | peer | peer's instructions / ours, per triangle |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for scene in "${scenes[@]}"; do
  for mode in "${our_modes[@]}" eg-flat 3dgfx-flat 3dgfx-gouraud; do
    k="$mode/$scene"
    case $mode in
      flat) peer=eg-flat; peer2=3dgfx-flat ;;
      gouraud) peer=3dgfx-gouraud; peer2= ;;
      *) peer=; peer2= ;;
    esac
    cmp=""; against=""
    for p in $peer $peer2; do
      against+="${against:+, }$p"
      cmp+="${cmp:+, }$(ratio "${ipt[$k]}" "${ipt[$p/$scene]}")"
      if [ "$scene" = big ]; then cmp+=" ($(ratio "${ipp[$k]}" "${ipp[$p/$scene]}") per px)"; fi
    done
    # Overdraw and gaps only mean something on `mesh`, which covers the screen exactly once
    # (the other scenes overlap on purpose).
    o=${over[$k]} g=${gap[$k]}; [ "$scene" = mesh ] || { o="-"; g="-"; }
    echo "| $mode | $scene | ${ppt[$k]} | ${ipp[$k]} | ${ipt[$k]} | $o | $g | ${against:--} | ${cmp:--} |"
  done
done
