#!/usr/bin/env bash
# The viewer's CI check (.ci/run: "check viewer"): installs the locked npm packages, records
# two scenes with the C# runner, type-checks and builds the viewer, runs the reader's unit
# tests (vitest) on those recordings and the browser tests (scripts/e2e.mjs on a recording,
# scripts/e2e-live.mjs on a run streamed by 'fulcrum run --live'; Debian's Chromium through
# playwright-core). Any failure, a missing browser included, exits non-zero.
# Usage: bash Viewer~/scripts/ci.sh   (from anywhere; builds the runner if it is not built)
set -euo pipefail
cd "$(dirname "$0")/.."
viewer=$(pwd)
repo=$(cd .. && pwd)
start=$SECONDS
step() { echo "== viewer: $* ($((SECONDS - start)) s)"; }

export CHROMIUM=${CHROMIUM:-/usr/bin/chromium}
if [ ! -x "$CHROMIUM" ]; then
  step "no browser at $CHROMIUM: apt-get install -y chromium"
  if [ "$(id -u)" = 0 ] && command -v apt-get > /dev/null; then
    apt-get install -y chromium > /tmp/fulcrum-viewer-apt.log 2>&1 \
      || { apt-get update > /dev/null 2>&1 && apt-get install -y chromium >> /tmp/fulcrum-viewer-apt.log 2>&1; } || true
  fi
  if [ ! -x "$CHROMIUM" ]; then
    echo "FAILED: Chromium is required for the viewer's browser test and could not be installed" >&2
    echo "        (install it with 'apt-get install -y chromium' or set CHROMIUM=/path/to/chromium)" >&2
    exit 1
  fi
fi

step "npm ci"
npm ci --no-audit --no-fund --loglevel=error

runner="$repo/.artifacts/bin/Fulcrum.Runner/release/fulcrum.dll"
if [ ! -f "$runner" ]; then
  step "building the runner"
  dotnet build "$repo/Samples~/Runner/Fulcrum.Runner.csproj" -c Release > /dev/null
fi
export FULCRUM="dotnet $runner"

step "recording test scenes with the C# runner"
export DATA="$viewer/test-data" OUT="$viewer/test-output"
rm -rf "$DATA" "$OUT"; mkdir -p "$DATA" "$OUT"
$FULCRUM run "$repo/Samples~/Scenes/tower-20.json" --steps 180 --record "$DATA/tower.frec" | grep '^recording:'
$FULCRUM run "$repo/Samples~/Scenes/jelly-stack.json" --steps 120 --record "$DATA/jelly.frec" | grep '^recording:'

step "type check and build"
npm run --silent build -- --logLevel warn

step "reader unit tests (vitest)"
npx vitest run

step "browser test (Chromium: $("$CHROMIUM" --version 2> /dev/null | head -n 1))"
node scripts/e2e.mjs

step "live browser test (fulcrum run --live)"
SCENES="$repo/Samples~/Scenes" node scripts/e2e-live.mjs

step "done; screenshots in $OUT"
