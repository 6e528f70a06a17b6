#!/usr/bin/env bash
# Regenerates the figures of docs/surfaces.md with the ctess CLI.
# Usage: docs/img/generate_surfaces.sh [path/to/ctess]   (default: build/release/tools/ctess/ctess)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
ctess="${1:-$here/../../build/release/tools/ctess/ctess}"
cd "$here"

# The three built-in surfaces at the default thresholds (5 degrees, 0.05), max level 12 to keep files small.
for name in sphere torus ripple; do
  "$ctess" surface --name "$name" --max-level 12 --format svg --view param --out "surface_${name}_param.svg"
  "$ctess" surface --name "$name" --max-level 12 --format svg --view shaded --out "surface_${name}_shaded.svg"
done
# Męciński 2011's sinusoid case: the distance test alone sees a flat plane.
"$ctess" surface --name ripple --max-level 12 --angle 180 --format svg --view shaded --out surface_ripple_distance_only_shaded.svg
