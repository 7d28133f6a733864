#!/usr/bin/env bash
# The SSD0323 OLED of QEMU's lm3s6965evb board (Cortex-M3), end to end: builds
# examples/ssd0323.rs for thumbv7m-none-eabi, runs it under QEMU until the firmware reports
# "frame sent" over semihosting, takes QEMU's screen dump of the display through the monitor,
# and has the host build of the same example compare it with the host render, pixel for pixel.
#   bash examples/ssd0323.sh        # writes target/ssd0323/{screen.ppm,screen.png,host.png}
# Needs qemu-system-arm (../shared/embedded/setup installs it) and the thumbv7m target (or
# ../shared/embedded/xcargo, which builds core from source where rustup has no target).
set -euo pipefail
cd "$(dirname "$0")/.."
out=target/ssd0323
mkdir -p "$out"
command -v qemu-system-arm >/dev/null || [ ! -x ../shared/embedded/setup ] || ../shared/embedded/setup

# The board has 64 KB of RAM at 0x2000_0000; memory.x describes the MPS2 boards' 4 MB, which
# is fine for code and statics (the firmware's fit) but not for the stack top, so move it.
# RUSTFLAGS replaces .cargo/config.toml's flags for the target, hence -Tlink.x again; the build
# gets its own directory so the firmware benchmarks' builds are not invalidated.
export RUSTFLAGS="-C link-arg=-Tlink.x -C link-arg=--defsym=_stack_start=0x20010000"
export CARGO_TARGET_DIR=target/lm3s6965evb
if [ -x ../shared/embedded/xcargo ]; then
  ../shared/embedded/xcargo thumbv7m-none-eabi build --release -q --example ssd0323
else
  cargo build --target thumbv7m-none-eabi --release -q --example ssd0323
fi
unset RUSTFLAGS CARGO_TARGET_DIR
elf=target/lm3s6965evb/thumbv7m-none-eabi/release/examples/ssd0323

# The monitor reads stdin and shares stdout with the firmware's semihosting output: once the
# firmware has sent its frame, dump the screen, then quit.
rm -f "$out/qemu.txt" "$out/screen.ppm"
{
  for _ in $(seq 600); do
    grep -qs 'ssd0323: \(frame sent\|error\)' "$out/qemu.txt" && break
    sleep 0.1
  done
  echo "screendump $out/screen.ppm"
  echo quit
} | timeout 120 qemu-system-arm -machine lm3s6965evb -display none -serial null \
  -semihosting-config enable=on,target=native -monitor stdio -kernel "$elf" >"$out/qemu.txt"
grep -ao 'ssd0323: .*' "$out/qemu.txt" | tee /dev/stderr | grep -q 'frame sent'

cargo run --release -q --example ssd0323 -- "$out/screen.ppm"
