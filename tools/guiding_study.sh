#!/usr/bin/env bash
# Dahm & Keller's experiment on the door scene: guided vs unguided path tracing
# without NEE and Russian roulette at equal samples per pixel, against a
# converged reference. Prints the emitter-hit share, mean path length and
# relative MSE of each, and the GPU time of the learning passes.
# Usage: tools/guiding_study.sh [SCENE] [SPP] [REFERENCE_SPP]   (needs build/)
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-assets/door_ajar.gltf}
spp=${2:-64}
refspp=${3:-2048}
out=${OUT:-out/study}
size="--width 160 --height 90"
mkdir -p "$out"
if [ ! -f "$out/reference.pfm" ]; then
  ./build/qlight render --scene "$scene" $size --spp "$refspp" --batch 32 --max-depth 12 \
    --out "$out/reference.pfm" --stats-json "$out/reference.json"
fi
for g in off q; do
  ./build/qlight render --scene "$scene" $size --spp "$spp" --batch 4 --max-depth 12 --nee off --rr off \
    --guiding "$g" --out "$out/$g.pfm" --stats-json "$out/$g.json"
done
./build/tools/image_compare "$out/reference.pfm" "$out/off.pfm" "$out/q.pfm"
python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
off, q = (json.load(open(f"{out}/{g}.json")) for g in ("off", "q"))
print(f"emitter hit share: unguided {off['emitter_hit_share']:.5f}, guided {q['emitter_hit_share']:.5f} "
      f"({q['emitter_hit_share'] / max(off['emitter_hit_share'], 1e-12):.1f}x); last frame guided "
      f"{q['emitter_hit_share_by_frame'][-1]:.5f} ({q['emitter_hit_share_by_frame'][-1] / max(off['emitter_hit_share'], 1e-12):.1f}x)")
print(f"mean path length: unguided {off['mean_path_length']:.3f}, guided {q['mean_path_length']:.3f} "
      f"({100 * (1 - q['mean_path_length'] / off['mean_path_length']):.1f}% shorter)")
g = q.get("guiding_stats", {})
total = q["gpu_ms_total"] / max(q["frames"], 1)
print(f"guided frame GPU {total:.1f} ms, learning passes {g.get('learning_gpu_ms_per_frame', 0):.1f} ms "
      f"({100 * g.get('learning_gpu_ms_per_frame', 0) / max(total, 1e-9):.1f}%); points {g.get('points')}; "
      f"wall {off['seconds']:.1f} s unguided vs {q['seconds']:.1f} s guided")
PY
