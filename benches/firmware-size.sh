#!/usr/bin/env bash
# Flash and RAM of the firmware examples on Cortex-M, the library's share, and checks that the
# Cortex-M0 build has no soft-float routines and shows which functions reach 64-bit division.
#
#   bash benches/firmware-size.sh [TARGET]        (default thumbv6m-none-eabi)
#
# Needs `arm-none-eabi-size`/`-nm`/`-objdump` (Debian: binutils-arm-none-eabi) or LLVM's
# `llvm-size`/`llvm-nm`/`llvm-objdump`; installs the former with apt-get when neither is there.
set -euo pipefail
cd "$(dirname "$0")/.."
target=${1:-thumbv6m-none-eabi}
xcargo=../shared/embedded/xcargo
build() { # build EXAMPLE FEATURES [ENV=VALUE...]: prints the ELF path
  local example=$1 features=$2; shift 2
  local dir=target/size-$features${1:+-baseline}
  env "$@" CARGO_TARGET_DIR="$dir" "$xcargo" "$target" build --release -q --example "$example" --features "$features" >&2
  echo "$dir/$target/release/examples/$example"
}
if command -v arm-none-eabi-size >/dev/null; then
  size=arm-none-eabi-size nm=arm-none-eabi-nm objdump=arm-none-eabi-objdump
elif command -v llvm-size >/dev/null; then
  size=llvm-size nm=llvm-nm objdump=llvm-objdump
else
  apt-get install -y -qq --no-install-recommends binutils-arm-none-eabi >/dev/null
  size=arm-none-eabi-size nm=arm-none-eabi-nm objdump=arm-none-eabi-objdump
fi
section() { $size -A "$1" | awk -v s="$2" '$1 == s {print $2}'; }
row() { printf '%-44s %8s %8s %8s\n' "$@"; }

echo "== $target (release profile of Cargo.toml; sizes in bytes)"
row "build" ".text" ".rodata" ".bss"
fulls=()
for features in firmware firmware,small-code; do
  full=$(build firmware "$features")
  fulls+=("$full")
  minimal=$(build firmware_minimal "$features")
  baseline=$(build firmware_minimal "$features" FW_BASELINE=1)
  row "firmware (every mode), $features" "$(section "$full" .text)" "$(section "$full" .rodata)" "$(section "$full" .bss)"
  row "firmware_minimal, $features" "$(section "$minimal" .text)" "$(section "$minimal" .rodata)" "$(section "$minimal" .bss)"
  row "firmware_minimal, nothing drawn" "$(section "$baseline" .text)" "$(section "$baseline" .rodata)" "$(section "$baseline" .bss)"
  lib=$(( $(section "$minimal" .text) + $(section "$minimal" .rodata) - $(section "$baseline" .text) - $(section "$baseline" .rodata) ))
  echo "  -> library code for flat + Gouraud into a framebuffer ($features): $lib bytes"
done
echo "(RAM: the examples keep frame, depth buffer and scenes on the stack, which .bss does not show:"
echo " firmware_minimal a 320x240 Rgb565 frame, 153,600 bytes; see README for band rendering)"

for full in "${fulls[@]}"; do
  echo
  echo "== $full"
  echo "soft-float routines (must be none):"
  if $nm "$full" | grep -E '__aeabi_[fd]|__(add|sub|mul|div)[sd]f3|__float|__fix'; then
    echo "FAIL: soft-float code linked" >&2; exit 1
  fi
  echo "  none"
  echo "functions calling 64-bit division (__aeabi_ldivmod / __aeabi_uldivmod):"
  $objdump -d -C --no-show-raw-insn "$full" | awk '
    /^[0-9a-f]+ <.*>:$/ { fn = $0; sub(/^[0-9a-f]+ </, "", fn); sub(/>:$/, "", fn) }
    /[[:space:]]bl[[:space:]].*<__aeabi_u?ldivmod>/ { print "  " fn }' | sort | uniq -c
done
