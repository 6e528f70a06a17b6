#!/usr/bin/env bash
# Regenerates the figures of docs/algorithm.md and the README with the ctess CLI (and, for the viewer
# screenshots, `ctess serve` in headless chromium).
# Usage: docs/img/generate.sh [path/to/ctess]   (default: build/release/tools/ctess/ctess)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
ctess="${1:-$here/../../build/release/tools/ctess/ctess}"
cd "$here"

# §1: how edge points move with the factor.
"$ctess" sweep --mode cp --from 1 --to 16 --steps 300 --svg sweep_cp.svg
"$ctess" sweep --mode d3d11-even --from 2 --to 16 --steps 300 --svg sweep_d3d11_even.svg
"$ctess" sweep --mode one-at-a-time --from 1 --to 16 --steps 300 --svg sweep_one_at_a_time.svg
"$ctess" sweep --mode even-spacing --from 1 --to 16 --steps 300 --svg sweep_even_spacing.svg

# §2: triangle patterns (name, mode, factors, extra options).
while read -r name mode factors extra; do
  [ -z "$name" ] && continue
  # shellcheck disable=SC2086
  "$ctess" pattern --mode "$mode" --factors "$factors" --format svg --out "$name.svg" $extra
done <<'LIST'
cp_8_8_8 cp 8,8,8 --layout shared
d3d11_even_8_8_8 d3d11-even 8,8,8,8
cp_16_8_4 cp 16,8,4 --layout shared
cp_10.3_6_3 cp 10.3,6,3 --layout shared
cp_10.3_rule_b cp 10.3,10.3,10.3 --layout shared --column-rule minimal
cp_10.3_rule_a cp 10.3,10.3,10.3 --layout shared --column-rule staircase
cp_32_12_20 cp 32,12,20 --layout shared
cp_32_32_8 cp 32,32,8 --layout shared
cp_40_1.2_2.5 cp 40,1.2,2.5 --layout shared
cp_1.5_1.5_1.5 cp 1.5,1.5,1.5 --layout shared
cp_1.5_20_1.2 cp 1.5,20,1.2 --layout shared
cp_2.5_1.2_40 cp 2.5,1.2,40 --layout shared
cp_64_1_1 cp 64,1,1 --layout shared
cp_anim_1.3 cp 1.3,1.3,1.3 --layout shared
cp_anim_2 cp 2,2,2 --layout shared
cp_anim_2.6 cp 2.6,2.6,2.6 --layout shared
cp_8_8_8_provoking cp 8,8,8 --provoking
cp_5_5_5_provoking cp 5,5,5 --provoking
cp_quad_12_5_12_30 cp 12,5,12,30 --domain quad --layout shared
uniform_11_9_6 uniform 11,9,6
uniform_7_6_3 uniform 7,6,3
uniform_11_4_2 uniform 11,4,2
uniform_16_13_9 uniform 16,13,9
uniform_40_30_20 uniform 40,30,20
uniform_11_9_6_provoking uniform 11,9,6 --layout provoking --provoking
LIST

# README: CP beside D3D11 fractional_even on the same edges (bottom 16, right 8, left 4; D3D11 names them
# Veq0, Weq0, Ueq0, inside = 16), the CP quad, and the viewer (needs chromium; see docs/viewer.md).
"$ctess" pattern --mode cp --factors 16,8,4 --format svg --provoking --out cp_16_8_4_provoking.svg
"$ctess" pattern --mode d3d11-even --factors 4,16,8 --format svg --provoking --out d3d11_even_4_16_8.svg
"$ctess" pattern --mode cp --domain quad --factors 12,5,12,30 --format svg --provoking --out cp_quad_12_5_12_30_provoking.svg
if [ -x /usr/bin/chromium ] || [ -n "${CTESS_CHROMIUM:-}" ]; then
  node "$here/snapshot.mjs" viewer "$ctess" viewer_pattern.png '?mode=cp&factors=16,8,4'
  node "$here/snapshot.mjs" viewer "$ctess" viewer_mesh.png '?view=mesh&mesh=torus'
  node "$here/snapshot.mjs" viewer "$ctess" viewer_uniform_mesh.png '?view=mesh&mesh=torus&pattern=uniform'
else
  echo "chromium not found: viewer_pattern.png, viewer_mesh.png and viewer_uniform_mesh.png not regenerated"
fi
echo "figures written to $here"
