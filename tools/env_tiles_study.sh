#!/usr/bin/env bash
# Dahm & Keller section 4.2 at equal time: a scene lit by an environment map through an
# opening, Q-guided with NEE choosing the map's tiles by their power (--light-learning off)
# and by what each cache point learned (on), against an unguided reference. Prints relMSE at
# equal samples per seed, the wall time of each and the time to equal error, learned over
# power: (relMSE x seconds) learned / (relMSE x seconds) power.
# Usage: tools/env_tiles_study.sh [SCENE] [ENV] [SPP] [REFERENCE_SPP] [SEEDS]   (needs build/)
set -euo pipefail
cd "$(dirname "$0")/.."
scene=${1:-assets/cornell_box.gltf}
env=${2:-assets/sky_sun.hdr}
spp=${3:-128}
refspp=${4:-4096}
seeds=${5:-3}
out=${OUT:-out/env_tiles}
size="--width 96 --height 96"
mkdir -p "$out"
if [ ! -f "$out/reference.pfm" ]; then
  ./build/qlight render --scene "$scene" --env "$env" $size --spp "$refspp" --batch 32 \
    --guiding off --out "$out/reference.pfm"
fi
for seed in $(seq 1 "$seeds"); do
  for ll in off on; do
    ./build/qlight render --scene "$scene" --env "$env" $size --spp "$spp" --batch 2 \
      --guiding q --light-learning "$ll" --seed "$seed" \
      --out "$out/$ll-$seed.pfm" --stats-json "$out/$ll-$seed.json" >/dev/null
  done
done
python3 - "$out" "$seeds" <<'PY'
import json, subprocess, sys
out, seeds = sys.argv[1], int(sys.argv[2])
def relmse(image):
    line = subprocess.run(["./build/tools/image_compare", f"{out}/reference.pfm", image],
                          capture_output=True, text=True, check=True).stdout.split()
    return float(line[-1])
ratios = []
for seed in range(1, seeds + 1):
    row = {}
    for ll in ("off", "on"):
        stats = json.load(open(f"{out}/{ll}-{seed}.json"))
        row[ll] = (relmse(f"{out}/{ll}-{seed}.pfm"), stats["seconds"])
    eq = row["on"][0] / row["off"][0]
    t = (row["on"][0] * row["on"][1]) / (row["off"][0] * row["off"][1])
    ratios.append((eq, row["on"][1] / row["off"][1], t))
    print(f"seed {seed}: relMSE power {row['off'][0]:.4f} learned {row['on'][0]:.4f} (x{eq:.2f}); "
          f"seconds {row['off'][1]:.1f} vs {row['on'][1]:.1f}; time to equal error x{t:.2f}")
n = len(ratios)
print("mean: relMSE at equal spp x%.2f, time per sample x%.2f, time to equal error x%.2f"
      % tuple(sum(r[i] for r in ratios) / n for i in range(3)))
PY
