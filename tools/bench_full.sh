#!/usr/bin/env bash
# The full benchmark of the README and docs/bench/: traversal against Embree on the same
# cores (when built), then `qlight bench` on every shipped scene with that result included.
# usage: tools/bench_full.sh [OUTDIR (default docs/bench)] [extra qlight bench options]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/bench}
shift || true
mkdir -p "$out"
traversal=()
if [ -x build/bench/bench_traversal_vs_embree ]; then
  build/bench/bench_traversal_vs_embree --out "$out/traversal.json"
  traversal=(--traversal "$out/traversal.json")
fi
build/qlight bench --out "$out" "${traversal[@]}" "$@"
