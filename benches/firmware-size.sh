#!/usr/bin/env bash
# Flash of the firmware examples on Cortex-M, each drawing mode's share of the library, and checks
# that the Cortex-M0 build has no soft-float routines and which functions reach 64-bit division.
#
#   bash benches/firmware-size.sh [--check] [TARGET...]
#                                  (default targets: thumbv6m-none-eabi thumbv7em-none-eabihf)
#
# Each mode's share is `examples/firmware_minimal.rs` built with `FW_MODE=<mode>` (inputs behind
# `black_box`, so nothing folds away) minus the same built with `FW_MODE=none`. With `--check`,
# fails when a budget is exceeded (else it marks them): every mode's firmware 64 KB of .text (also
# reported for the six modes the firmware had when that budget was set); flat 6 KB, Gouraud 8 KB, Gouraud +
# depth 10 KB, a texture style with every filter, wrap and modulation 12 KB (affine; the same
# with a perspective, flat with anti-aliased edges and an indexed mesh of flat triangles are
# reported beside them, without a budget of their own).
#
# Needs `arm-none-eabi-size`/`-nm`/`-objdump` (Debian: binutils-arm-none-eabi) or LLVM's
# `llvm-size`/`llvm-nm`/`llvm-objdump`; installs the former with apt-get when neither is there.
set -euo pipefail
cd "$(dirname "$0")/.."
check=0
if [ "${1:-}" = --check ]; then check=1; shift; fi
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(thumbv6m-none-eabi thumbv7em-none-eabihf)
xcargo=../shared/embedded/xcargo
profile=measure
if command -v arm-none-eabi-size >/dev/null; then
  size=arm-none-eabi-size nm=arm-none-eabi-nm objdump=arm-none-eabi-objdump
elif command -v llvm-size >/dev/null; then
  size=llvm-size nm=llvm-nm objdump=llvm-objdump
else
  as_root=""; [ "$(id -u)" -eq 0 ] || as_root="sudo"
  $as_root apt-get install -y -qq --no-install-recommends binutils-arm-none-eabi >/dev/null
  size=arm-none-eabi-size nm=arm-none-eabi-nm objdump=arm-none-eabi-objdump
fi
section() { $size -A "$1" | awk -v s="$2" '$1 == s {print $2}'; }
code() { echo $(( $(section "$1" .text) + $(section "$1" .rodata) )); }
row() { printf '%-34s %8s %8s %10s %8s\n' "$@"; }
failures=0
# The every-mode firmware's modes when the 64 KB budget was set; FW_MODES builds only those.
issue_modes=flat,gouraud,gouraud-z,tex-nearest,tex-bilinear,band
for target in "${targets[@]}"; do
  dir=target/xcargo/$target/$profile/examples
  build() { # build EXAMPLE [FW_MODE]: prints the ELF path (the mode's build is kept aside)
    env ${2:+FW_MODE=$2} "$xcargo" "$target" build --profile $profile -q --example "$1" --features firmware >&2
    local elf=$dir/$1${2:+-$2}
    [ -z "${2:-}" ] || cp "$dir/$1" "$elf"
    echo "$elf"
  }
  echo "== $target (profile $profile; bytes)"
  row "build" ".text" ".rodata" "share" "budget"
  full=$(build firmware)
  cp "$full" "$dir/firmware-all"; full=$dir/firmware-all # the six-mode build below replaces it
  row "firmware, every mode" "$(section "$full" .text)" "$(section "$full" .rodata)" "-" 65536
  [ "$(section "$full" .text)" -le 65536 ] || { echo "OVER BUDGET: every-mode firmware" >&2; failures=$((failures + 1)); }
  # The modes the budget was set for (issue 21), without the eleven added since.
  FW_MODES=$issue_modes "$xcargo" "$target" build --profile $profile -q --example firmware --features firmware >&2
  six=$dir/firmware-six; cp "$dir/firmware" "$six"
  row "firmware, the first six modes" "$(section "$six" .text)" "$(section "$six" .rodata)" "-" 65536
  [ "$(section "$six" .text)" -le 65536 ] || { echo "OVER BUDGET: six-mode firmware" >&2; failures=$((failures + 1)); }
  none=$(build firmware_minimal none)
  row "firmware_minimal, nothing drawn" "$(section "$none" .text)" "$(section "$none" .rodata)" "-" "-"
  for mode_budget in flat:6144 gouraud:8192 gouraud-z:10240 texture:12288 texture-perspective:- anti-aliased:- mesh:-; do
    mode=${mode_budget%%:*} budget=${mode_budget#*:}
    elf=$(build firmware_minimal "$mode")
    share=$(( $(code "$elf") - $(code "$none") ))
    row "  $mode" "$(section "$elf" .text)" "$(section "$elf" .rodata)" "$share" "$budget"
    [ "$budget" = - ] || [ "$share" -le "$budget" ] || { echo "OVER BUDGET: $mode on $target" >&2; failures=$((failures + 1)); }
  done
  echo "soft-float routines (must be none):"
  if $nm "$full" | grep -E '__aeabi_[fd]|__(add|sub|mul|div)[sd]f3|__float|__fix'; then
    echo "FAIL: soft-float code linked" >&2; exit 1
  fi
  echo "  none"
  echo "functions calling 64-bit division (__aeabi_ldivmod / __aeabi_uldivmod):"
  $objdump -d -C --no-show-raw-insn "$full" | awk '
    /^[0-9a-f]+ <[^$].*>:$/ { fn = $0; sub(/^[0-9a-f]+ </, "", fn); sub(/>:$/, "", fn) }
    /[[:space:]]bl[[:space:]].*<__aeabi_u?ldivmod>/ { print "  " fn }' | sort | uniq -c
  echo
done
echo "(RAM: the examples keep frame, depth buffer and scenes on the stack, which .bss does not show:"
echo " firmware_minimal a 320x240 Rgb565 frame, 153,600 bytes; see README for band rendering)"
[ "$failures" -eq 0 ] || { echo "$failures budget(s) exceeded" >&2; [ "$check" -eq 0 ] || exit 1; }
