#!/usr/bin/env bash
# Where a firmware mode's instructions go on Cortex-M: runs `examples/firmware.rs` built for one
# mode and scene under QEMU with `-d in_asm,exec,nochain` (every executed translation block is
# logged), counts each instruction's executions, and prints the functions by instructions and the
# hot code with its counts. Exact and repeatable, like the firmware's own SysTick counts.
#
#   bash benches/qemu-profile.sh TARGET MODE:SCENE [MIN_COUNT]
#   bash benches/qemu-profile.sh thumbv6m-none-eabi flat:small 2400
#
# TARGET is thumbv6m-none-eabi (run on mps2-an385) or thumbv7em-none-eabihf (mps2-an386). The
# listing (target/qemu-profile/hot.s) shows every instruction executed at least MIN_COUNT times
# (default: once per triangle of the scene), function by function, with its count. The summary
# gives each function's instructions per triangle, split into those run about once per triangle
# (set-up), more often (rows, spans, pixels) and less often. Only the drawing is counted, as the
# firmware's own figures count it: from the first block of a `modes::draw_*` function to the next
# block of `main`, whose scene generation and frame checks (library calls of their own, such as
# the covered pixels' walk) stay out; its total matches the firmware's count within the few
# hundred instructions of the SysTick reads.
set -euo pipefail
cd "$(dirname "$0")/.."
target=$1 only=$2 min=${3:-}
case $target in
  thumbv6m-none-eabi) board=mps2-an385 ;;
  thumbv7em-none-eabihf) board=mps2-an386 ;;
  *) echo "unknown target $target" >&2; exit 2 ;;
esac
out=target/qemu-profile
mkdir -p "$out"
FW_ONLY=$only CARGO_TARGET_DIR=$out/build ../shared/embedded/xcargo "$target" build --profile measure -q --example firmware --features firmware
elf=$out/build/$target/measure/examples/firmware
result=$(timeout 600 qemu-system-arm -machine "$board" -nographic -semihosting-config enable=on,target=native \
  -icount shift=3 -d in_asm,exec,nochain -D "$out/qemu.log" -kernel "$elf" | grep 'checksum=')
echo "$result"
triangles=$(sed -n 's/.* triangles=\([0-9]*\).*/\1/p' <<<"$result" | head -1)
command -v llvm-nm >/dev/null || { echo "needs llvm-nm and llvm-objdump (Debian: llvm)" >&2; exit 1; }
python3 - "$elf" "$out" "$min" "${triangles:-0}" <<'PY'
import bisect, collections, re, subprocess, sys
elf, out, min_count, triangles = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
symbols = []
for line in subprocess.run(["llvm-nm", "-C", "--numeric-sort", "-S", elf], capture_output=True, text=True).stdout.splitlines():
    parts = line.split(None, 3)
    if len(parts) == 4 and parts[2] in "tTwW":
        symbols.append((int(parts[0], 16) & ~1, int(parts[1], 16), re.sub(r"::h[0-9a-f]{16}", "", parts[3])))
starts = [s[0] for s in symbols]
def function(address):
    i = bisect.bisect_right(starts, address) - 1
    return symbols[i] if i >= 0 and address < symbols[i][0] + symbols[i][1] else None
# Only the drawing counts, as in the firmware's own figures: from a block of a
# `firmware::modes::draw_*` function until the next block of `main` (the harness, which
# generates the scenes and checks the frames, calling library code of its own).
def ranges(test):
    return [(s[0], s[0] + s[1]) for s in symbols if test(s[2])]
drawing = ranges(lambda name: name.startswith("firmware::modes::draw"))
harness = ranges(lambda name: name == "firmware::__cortex_m_rt_main")
def within(pc, spans):
    return any(lo <= pc < hi for lo, hi in spans)
blocks, current, counts, active, role = {}, None, collections.Counter(), False, {}
for line in open(f"{out}/qemu.log", errors="replace"):
    if line.startswith("IN:"):
        current = []
    elif current is not None and line.startswith("0x"):
        current.append(int(line[:10], 16))
    elif line.startswith("Trace"):
        pc = int(re.search(r"\[[0-9a-f]+/([0-9a-f]+)/", line).group(1), 16)
        if current:
            blocks[pc], current = current, None
        if pc not in role:
            role[pc] = 1 if within(pc, drawing) else -1 if within(pc, harness) else 0
        if role[pc]:
            active = role[pc] > 0
        if active:
            for address in blocks.get(pc, [pc]):
                counts[address] += 1
per_function = collections.Counter()
for address, n in counts.items():
    f = function(address)
    per_function[f] += n
# Per function, its instructions split by how often each ran against the scene's triangles:
# about once per triangle (set-up), more often (rows, spans, pixels), less often (rare paths,
# and whatever ran outside the drawing).
split = collections.defaultdict(lambda: [0, 0, 0])
for address, n in counts.items():
    f = function(address)
    if triangles and abs(n - triangles) <= triangles // 500 + 2:
        split[f][0] += n
    elif triangles and n > triangles:
        split[f][1] += n
    else:
        split[f][2] += n
total = sum(counts.values())
print(f"{total} instructions executed in the drawing (modes::draw_* and what they call)")
if triangles:
    print(f"per triangle ({triangles} triangles): all = once + more often + less often")
for f, n in per_function.most_common(15):
    name = f[2][:100] if f else '?'
    if triangles:
        once, more, less = (v / triangles for v in split[f])
        print(f"{n:12d} {100 * n / total:5.1f}%  {n / triangles:9.1f} = {once:7.1f} + {more:7.1f} + {less:7.1f}  {name}")
    else:
        print(f"{n:12d} {100 * n / total:5.1f}%  {name}")
threshold = int(min_count) if min_count else 1
with open(f"{out}/hot.s", "w") as listing:
    for f, n in per_function.most_common(30):
        if f is None or n < threshold:
            continue
        listing.write(f"=== {f[2]}: {n}\n")
        code = subprocess.run(["llvm-objdump", "-d", "-C", "--no-show-raw-insn", f"--start-address={f[0]}",
                               f"--stop-address={f[0] + f[1]}", elf], capture_output=True, text=True).stdout
        for line in code.splitlines():
            m = re.match(r"\s+([0-9a-f]+):", line)
            if m and counts.get(int(m.group(1), 16), 0) >= threshold:
                listing.write(f"{counts[int(m.group(1), 16)]:9d} {line.strip()}\n")
print(f"hot code: {out}/hot.s")
PY
