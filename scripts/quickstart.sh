#!/usr/bin/env bash
# Install what is missing, build geardyn, and run the quickstart case.
# Results, tables and pictures land in results/quickstart/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/deps.sh
if [ -d build/meson-info ]; then meson setup --reconfigure build >/dev/null; else meson setup build >/dev/null; fi
ninja -C build
./build/src/cli/geardyn run cases/quickstart.ini --out results/quickstart
echo "results: $(pwd)/results/quickstart (summary.json, time_history.csv, poincare.csv, events.csv, *.png, *.svg)"
