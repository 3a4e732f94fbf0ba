#!/usr/bin/env bash
# npm run bench: build the page, then measure in headless Chromium what it
# loads (gzipped bytes) and how long it takes to show the first solution.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --test
SKIP_SETUP=1 bash scripts/build.sh
node scripts/bench.mjs "$@"
node scripts/bench-embed.mjs "$@"
