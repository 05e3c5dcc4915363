#!/usr/bin/env bash
# Fixed-seed renders of every shipped scene (guided, guided with learned light selection,
# unguided at an animation time) and a 6-frame headless demo, for refactors that must not
# change a pixel: render the set before and after, then `cmp` the files pairwise
# (e.g. `diff -r --brief BEFORE AFTER`).
# usage: tools/render_fixed_set.sh OUTDIR [QLIGHT_BINARY (default build/qlight)]
set -euo pipefail
out=$1
bin=${2:-build/qlight}
assets=$(cd "$(dirname "$0")/../assets" && pwd)
mkdir -p "$out"
for scene in "$assets"/*.gltf; do
  name=$(basename "$scene" .gltf)
  common=(--scene "$scene" --width 96 --height 64 --batch 2 --seed 11)
  "$bin" render "${common[@]}" --spp 8 --out "$out/$name.pfm" >/dev/null
  "$bin" render "${common[@]}" --spp 8 --light-learning on --out "$out/${name}_ll.pfm" >/dev/null
  "$bin" render "${common[@]}" --spp 4 --guiding off --time 1.3 --out "$out/${name}_off.pfm" >/dev/null
done
"$bin" demo --headless --frames 6 --width 96 --height 64 --out "$out/demo" --save-every 0 >/dev/null
rm -f "$out/demo/stats.json"  # timings differ from run to run
echo "render_fixed_set: $(find "$out" -type f | wc -l) files in $out"
