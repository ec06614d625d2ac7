#!/usr/bin/env bash
# The default demo behind `make run`: generate an office floor, draw it, fly a lawnmower over it
# with the LiDAR + depth camera, build the scene graph (rolling grid, coverage mask,
# connectivity graph, objects) and write pictures and statistics into OUT_DIR.
# Usage: scripts/demo.sh path/to/ussnav [OUT_DIR]
set -euo pipefail
USSNAV=${1:?usage: demo.sh USSNAV [OUT_DIR]}
OUT=${2:-out/demo}
FRAMES=${USSNAV_DEMO_FRAMES:-900}
mkdir -p "$OUT"
"$USSNAV" --version
"$USSNAV" world generate --style office --seed 1 --out "$OUT/world.json"
"$USSNAV" world render "$OUT/world.json" --out "$OUT/world.png"
"$USSNAV" world stats "$OUT/world.json"
"$USSNAV" map --world "$OUT/world.json" --trajectory lawnmower --skeleton --max-frames "$FRAMES" --out "$OUT"
echo
echo "demo: results in $OUT/ (world.png, map.png, stats.json$( [ -f "$OUT/scene_graph.json" ] && echo ', scene_graph.json'))"
