#!/usr/bin/env bash
# The race against Blender's Cycles on the same cores (issue 10): the same glTF scene, Lambertian
# materials, resolution and bounce limit, no denoising; each renderer's error (relMSE) against
# its own long reference (reference noise subtracted), and the time each needs to reach the
# error Cycles has after 256 samples. Needs Debian's blender package (apt-get install blender).
# usage: tools/race_cycles.sh [SCENE (default assets/door_ajar.gltf)] [OUTDIR (default out/race)]
# Environment: REF_SPP (default 4096, per half of each reference), SEEDS (default "1 2"),
# CYCLES_SPP (default "32 64 128 256 512"), QLIGHT_SPP (default "64 128 256 512 1024"),
# THREADS (default: cores).
set -euo pipefail
cd "$(dirname "$0")/.."
scene=$(realpath "${1:-assets/door_ajar.gltf}")
out=${2:-out/race}
width=256 height=144 depth=8
ref_spp=${REF_SPP:-4096}
threads=${THREADS:-$(nproc)}
command -v blender >/dev/null || { echo "race_cycles: blender is not installed (apt-get install blender)" >&2; exit 1; }
mkdir -p "$out"
results="$out/results.jsonl"
: >"$results"

# qlight's depth counts surface vertices (8: NEE at the 8th, no scattering from it), Cycles'
# max bounces the scatterings after the first hit: the same paths at depth - 1.
cycles() {  # seed spp...
  local seed=$1
  shift
  blender -b -noaudio --python tools/cycles_render.py -- "$scene" "$out/cycles_s$seed" \
    "$width" "$height" "$((depth - 1))" "$threads" "$seed" "$@" 2>&1 |
    sed -n 's/^CYCLES_RESULT //p' | while read -r line; do
      spp=$(echo "$line" | python3 -c 'import json,sys; print(json.load(sys.stdin)["spp"])')
      echo "{\"renderer\": \"cycles\", \"image\": \"$out/cycles_s${seed}_$spp.pfm\", \"result\": $line}" >>"$results"
    done
}

qlight() {  # method seed spp
  local method=$1 seed=$2 spp=$3
  local image="$out/qlight_${method}_s${seed}_$spp.pfm"
  build/qlight render --scene "$scene" --width "$width" --height "$height" --max-depth "$depth" \
    --guiding "$method" --spp "$spp" --seed "$seed" --out "$image" --stats-json "$image.json" \
    >/dev/null 2>"$image.log"
  local seconds
  seconds=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["seconds"])' "$image.json")
  echo "{\"renderer\": \"qlight_$method\", \"image\": \"$image\", \"result\": {\"spp\": $spp, \"seconds\": $seconds, \"seed\": $seed}}" >>"$results"
}

echo "race_cycles: references ($ref_spp spp per half)"
cycles 101 "$ref_spp"
cycles 102 "$ref_spp"
qlight off 101 "$ref_spp"
qlight off 102 "$ref_spp"
echo "race_cycles: test renders"
for seed in ${SEEDS:-1 2}; do
  # shellcheck disable=SC2086
  cycles "$seed" ${CYCLES_SPP:-32 64 128 256 512}
  for spp in ${QLIGHT_SPP:-64 128 256 512 1024}; do
    qlight q "$seed" "$spp"
    qlight off "$seed" "$spp"
  done
done
python3 tools/race_report.py "$results" >"$out/report.md"
cat "$out/report.md"
