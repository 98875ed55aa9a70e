#!/usr/bin/env bash
# Prints the criterion medians of the last `cargo bench -p benches` run as a Markdown table,
# plus the machine line the README table starts with. Needs jq.
#   bash benches/table.sh [criterion-dir]   (default: target/criterion of the workspace)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
dir="${1:-${CRITERION_HOME:-${CARGO_TARGET_DIR:-$here/../target}/criterion}}"
command -v jq >/dev/null || { echo "table.sh: jq is required" >&2; exit 1; }
[ -d "$dir" ] || { echo "table.sh: no criterion results in $dir" >&2; exit 1; }

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(date -u +%F), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| benchmark | median |"
echo "|---|---:|"
find "$dir" -path '*/new/estimates.json' | sort -V | while read -r f; do
    id="${f#"$dir"/}"
    id="${id%/new/estimates.json}"
    ns="$(jq '.median.point_estimate' "$f")"
    awk -v id="$id" -v ns="$ns" 'BEGIN {
        if (ns < 1e3) printf "| %s | %.1f ns |\n", id, ns;
        else if (ns < 1e6) printf "| %s | %.2f µs |\n", id, ns / 1e3;
        else printf "| %s | %.2f ms |\n", id, ns / 1e6;
    }'
done
