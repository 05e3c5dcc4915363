#!/usr/bin/env bash
# Renders each glTF feature sample in tests/data/gltf-samples/features (plus any given as
# extra folders) with the default camera, lit by the sky-with-sun map, and assembles them
# into one labelled image sheet: docs/images/gltf_features.png.
# Usage: bash tools/render_feature_sheet.sh [build-dir] [extra sample folders...]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
shift || true
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
samples=(tests/data/gltf-samples/features/*/glTF "$@")
for dir in "${samples[@]}"; do
  [ -d "$dir" ] || continue
  name=$(basename "$(dirname "$dir")")
  scene=$(ls "$dir"/*.gltf "$dir"/*.glb 2>/dev/null | head -1 || true)
  [ -n "$scene" ] || continue
  "$build/qlight" render --scene "$scene" --out "$out/$name.png" --width 320 --height 240 \
    --spp 64 --env assets/sky_sun.hdr --time 0.5 >/dev/null 2>&1 || echo "failed: $name" >&2
done
/usr/bin/python3 - "$out" docs/images/gltf_features.png <<'PY'
import sys, os
from PIL import Image, ImageDraw
src, dst = sys.argv[1], sys.argv[2]
names = sorted(f[:-4] for f in os.listdir(src) if f.endswith('.png'))
cols, w, h, label = 4, 320, 240, 18
rows = (len(names) + cols - 1) // cols
sheet = Image.new('RGB', (cols * w, rows * (h + label)), 'white')
draw = ImageDraw.Draw(sheet)
for i, n in enumerate(names):
    x, y = (i % cols) * w, (i // cols) * (h + label)
    sheet.paste(Image.open(os.path.join(src, n + '.png')).convert('RGB'), (x, y + label))
    draw.text((x + 4, y + 3), n, fill='black')
sheet.save(dst)
print(dst, len(names), 'samples')
PY
