#!/usr/bin/env bash
# Re-vendors three-viewer.min.js, the one script of report.html's 3D viewer: three.js with its
# GLTFLoader and OrbitControls addons (entry.js), at the versions package-lock.json pins,
# bundled and minified by the pinned esbuild into a script that defines the global `THREE`,
# and three.js' licence beside it (LICENSE.three). sim includes both with include_str!, so a
# machine with only Rust still writes report.html.
#
# Usage: sim/vendor/three/vendor.sh           rewrites the committed files
#        sim/vendor/three/vendor.sh --check   fails if they differ from what the pins give
# Needs node and npm; installs the pinned packages into sim/vendor/three/node_modules.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here"
if [ ! -f node_modules/.package-lock.json ] || [ package-lock.json -nt node_modules/.package-lock.json ]; then
  npm ci --no-audit --no-fund >&2
fi
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
node_modules/.bin/esbuild entry.js --bundle --minify --format=iife --global-name=THREE \
  --legal-comments=none --log-level=warning --outfile="$tmp/three-viewer.min.js"
cp node_modules/three/LICENSE "$tmp/LICENSE.three"
if [ "${1:-}" = "--check" ]; then
  for f in three-viewer.min.js LICENSE.three; do
    cmp -s "$tmp/$f" "$f" || {
      echo "vendor check: sim/vendor/three/$f differs from what package-lock.json's pins give (run sim/vendor/three/vendor.sh)" >&2
      exit 1
    }
  done
  echo "vendor check: three-viewer.min.js and LICENSE.three match three $(node -p 'require("./node_modules/three/package.json").version')"
else
  cp "$tmp/three-viewer.min.js" "$tmp/LICENSE.three" .
fi
