#!/usr/bin/env bash
# The default demo behind `make run`: one ObjectNav episode in the built-in simulator. Generates
# an apartment, draws it, and lets the UAV search it for a bed with the coarse-to-fine planner:
# LiDAR + depth camera -> rolling grid, coverage mask, connectivity graph, regions, objects ->
# frontiers and camera-unseen patches -> planner -> flight. Prints the result and writes
# OUT_DIR/result.json, scene_graph.json, trajectory.csv, topdown.png and world.png.
# Usage: scripts/demo.sh path/to/ussnav [OUT_DIR]
# Environment: USSNAV_DEMO_GOAL (default bed), USSNAV_DEMO_PLANNER (default full).
set -euo pipefail
USSNAV=${1:?usage: demo.sh USSNAV [OUT_DIR]}
OUT=${2:-out/demo}
GOAL=${USSNAV_DEMO_GOAL:-bed}
PLANNER=${USSNAV_DEMO_PLANNER:-full}
mkdir -p "$OUT"
"$USSNAV" --version
"$USSNAV" world generate --style apartment --seed 1 --rooms 8 --out "$OUT/world.json"
"$USSNAV" world render "$OUT/world.json" --out "$OUT/world.png"
"$USSNAV" world stats "$OUT/world.json" | head -4
"$USSNAV" explore --world "$OUT/world.json" --goal "$GOAL" --planner "$PLANNER" --seed 1 --out "$OUT"
"$USSNAV" graph stats "$OUT/scene_graph.json"
echo
"$USSNAV" ask --graph "$OUT/scene_graph.json" --question "Describe the layout"
echo
echo "demo: results in $OUT/ (world.png, topdown.png, result.json, scene_graph.json, trajectory.csv)"
echo "      open $OUT/scene_graph.html in a browser to explore the scene graph (pan, zoom, click)"
