#!/usr/bin/env bash
# The replay checks that need Node.js and a browser: runs vehicle-sim on the default world
# (test-track), the obstacles world (test-track), the e-puck world (square) and the ACC world
# with the radar overlay (`replayOverlay = true`: marker nodes with step-interpolated
# translation and scale channels), the double-lane-change world with the overlay (traffic
# cones, a radar's markers and a lidar's POINTS clouds shown by scale channels), validates each
# replay.glb with the Khronos glTF validator (0 errors and 0 warnings), then renders two of them
# with <model-viewer> in headless Chromium at two animation times each (the screenshots must
# differ and the console stay free of errors). Then opens report.html of the test track and
# of the two-cars world from disk with the network blocked (report.mjs): following each car at
# three times, the car is centred and covers more than 5 % of the viewer (and once for the
# two cars renamed `world` and `ground`, the names of scene nodes); the screenshot of
# the two-cars page is $REPORT_SCREENSHOT (default OUT_DIR/report.png; the README's is
# sim/docs/report.png, made with REPORT_SCREENSHOT=sim/docs/report.png).
#
# Usage: sim/tests/replay/check.sh [OUT_DIR]   (default: target/replay-checks)
# Needs node, npm and /usr/bin/chromium (or $CHROMIUM); installs the npm packages of
# package-lock.json into sim/tests/replay/node_modules when missing. Outputs, screenshots
# included, stay in OUT_DIR.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
out="${1:-$root/target/replay-checks}"
chromium="${CHROMIUM:-/usr/bin/chromium}"

for tool in node npm; do
  command -v "$tool" >/dev/null || { echo "replay check: '$tool' not found (install Node.js)" >&2; exit 1; }
done
[ -x "$chromium" ] || { echo "replay check: no Chromium at $chromium (apt-get install chromium)" >&2; exit 1; }

# Installed once, and again whenever package-lock.json changes.
if [ ! -f "$here/node_modules/.package-lock.json" ] ||
   [ "$here/package-lock.json" -nt "$here/node_modules/.package-lock.json" ]; then
  echo "replay check: installing the npm packages into $here/node_modules"
  (cd "$here" && npm ci --no-audit --no-fund)
fi

rm -rf "$out"
mkdir -p "$out"
cd "$root"
cargo build -p sim --bin vehicle-sim
sim="$root/target/debug/vehicle-sim"
"$sim" --out "$out/test-track" >/dev/null
"$sim" --world sim/worlds/obstacles.toml --out "$out/obstacles" >/dev/null
"$sim" --world sim/worlds/e-puck.toml --out "$out/e-puck" >/dev/null
{ echo "replayOverlay = true"; cat sim/worlds/acc.toml; } >"$out/acc-overlay.toml"
"$sim" --world "$out/acc-overlay.toml" --out "$out/acc-overlay" >/dev/null
"$sim" --world sim/worlds/two-cars.toml --out "$out/two-cars" >/dev/null
# The two cars named as the scene's root and ground nodes: the viewer finds cars by node index.
sed 's/^name = "prius"/name = "world"/; s/^name = "bmw"/name = "ground"/' \
  sim/worlds/two-cars.toml >"$out/clashing-names.toml"
"$sim" --world "$out/clashing-names.toml" --out "$out/clashing-names" >/dev/null
{ echo "replayOverlay = true"; cat sim/worlds/double-lane-change.toml; } >"$out/cones-overlay.toml"
"$sim" --world "$out/cones-overlay.toml" --out "$out/cones-overlay" >/dev/null

node "$here/validate.mjs" "$out/test-track/replay.glb" "$out/obstacles/replay.glb" \
  "$out/e-puck/replay.glb" "$out/acc-overlay/replay.glb" "$out/two-cars/replay.glb" \
  "$out/cones-overlay/replay.glb"
# A C controller's run under VEHICLE_OUT (written by capi's test
# a_controller_run_writes_the_outputs_of_the_same_programme, which `cargo test` runs first).
controller_glb="$root/target/tmp/capi-c_programs/outputs-controller/replay.glb"
if [ -f "$controller_glb" ]; then
  node "$here/validate.mjs" "$controller_glb"
elif [ "${CI:-}" = "true" ]; then
  echo "replay check: no $controller_glb: the C API tests did not run first" >&2
  exit 1
else
  echo "replay check: skipping the controller run's replay (run cargo test -p capi first)"
fi

# The point between the positions of a scenario's vehicle at two times (s), from the
# telemetry CSV: "x,y" in m.
midpoint() {
  awk -F, -v s="$2" -v t1="$3" -v t2="$4" '
    $1 == s && !a && $3 + 0 >= t1 { ax = $4; ay = $5; a = 1 }
    $1 == s && !b && $3 + 0 >= t2 { bx = $4; by = $5; b = 1 }
    END { if (!(a && b)) exit 1; printf "%.3f,%.3f", (ax + bx) / 2, (ay + by) / 2 }' "$1"
}

target="$(midpoint "$out/test-track/telemetry.csv" lane-change 9 11)"
node "$here/render.mjs" --glb "$out/test-track/replay.glb" --animation lane-change \
  --times 9,11 --target "$target" --radius 45 --out "$out" --name test-track_lane-change
target="$(midpoint "$out/e-puck/telemetry.csv" square 8 20)"
node "$here/render.mjs" --glb "$out/e-puck/replay.glb" --animation square \
  --times 8,20 --target "$target" --radius 0.6 --out "$out" --name e-puck_square
node "$here/report.mjs" --html "$out/test-track/report.html" --part lane-change --times 2,9,11 \
  --out "$out" --name report_test-track
node "$here/report.mjs" --html "$out/two-cars/report.html" --part programme --times 2,10,20 \
  --out "$out" --name report_two-cars --shot "${REPORT_SCREENSHOT:-$out/report.png}"
node "$here/report.mjs" --html "$out/clashing-names/report.html" --part programme --times 10 \
  --out "$out" --name report_clashing-names
echo "replay check passed: outputs and screenshots in $out"
