#!/usr/bin/env bash
# The soak run: 10,000 headless frames of the demo's default scene (door ajar, moving light) at
# 64x36 with guiding, learned light selection and tracking (the demo's forgetting on light moves), the validation layer
# on (without synchronization validation, whose history in Debian 12's layer grows by
# ~150 KB per frame; tests run with it). Prints resident memory and device allocations at frames 1,000 and 10,000, the range of
# the Q tables at the end, rejected samples and the exit code (3: validation messages).
# Usage: tools/soak.sh [BUILD_DIR] [FRAMES]
set -uo pipefail
build=${1:-build}
frames=${2:-10000}
out=$(mktemp -d)
start=$(date +%s)
QLIGHT_VALIDATION=1 QLIGHT_SYNC_VALIDATION=0 "$build/qlight" demo --headless --frames "$frames" --width 64 --height 36 \
  --save-every 0 --light-learning on --out "$out" > "$out/log.txt" 2>&1
rc=$?
tail -1 "$out/log.txt"
/usr/bin/python3 - "$out/stats.json" "$frames" "$rc" "$(( $(date +%s) - start ))" <<'PY'
import json, sys
stats = json.load(open(sys.argv[1]))
frames, rc, seconds = int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
detail = stats["frames_detail"]
def at(n):
    return detail[min(n, len(detail)) - 1]
early, last = at(1000), at(frames)
print(f"soak: {len(detail)} frames in {seconds} s, exit code {rc} (3: validation messages)")
for name, f in (("frame 1,000", early), (f"frame {len(detail):,}", last)):
    print(f"  {name}: resident {f['resident_mib']:.1f} MiB, device {f['device_allocations']} "
          f"allocations, {f['device_mib']:.1f} MiB")
print(f"  resident growth after frame 1,000: {last['resident_mib'] - early['resident_mib']:+.1f} MiB; "
      f"device allocations {last['device_allocations'] - early['device_allocations']:+d}")
print(f"  Q range at the end: [{stats.get('q_min')}, {stats.get('q_max')}], "
      f"{stats.get('q_non_finite')} entries not finite")
print(f"  rejected (NaN/Inf) samples: {stats['invalid_samples']}")
PY
rm -rf "$out"
exit $rc
