#!/usr/bin/env bash
# Renders the README's picture: the Cornell box and the door scene side by side.
# Needs a built qlight (build/qlight) and imagemagick's convert.
set -euo pipefail
cd "$(dirname "$0")/.."
out=docs/images
mkdir -p "$out"
spp=${SPP:-512}
./build/qlight render --scene assets/cornell_box.gltf --out "$out/cornell_box.png" --spp "$spp" --batch 16 --stats-json "$out/cornell_box.json"
./build/qlight render --scene assets/door_ajar.gltf --out "$out/door_ajar.png" --spp "$spp" --batch 16 --stats-json "$out/door_ajar.json"
convert "$out/cornell_box.png" "$out/door_ajar.png" +append "$out/renders.png"
