#!/usr/bin/env bash
# The default demo behind `make run`. Usage: scripts/demo.sh path/to/ussnav OUT_DIR
set -euo pipefail
USSNAV=${1:?usage: demo.sh USSNAV OUT_DIR}
OUT=${2:-out/demo}
mkdir -p "$OUT"
"$USSNAV" --version
echo "demo: the demo is assembled as the stages land"
