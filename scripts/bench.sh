#!/usr/bin/env bash
# npm run bench: build the page, then measure in headless Chromium what it
# loads (gzipped bytes) and how long it takes to show the first solution.
# npm run bench -- ops [--json FILE]: the image operators of ../shared/bench
# (T1–T7) against OpenCV.js in the same Node process (scripts/bench-ops/).
# npm run bench -- lab (or --lab): the image lab on a 12 MP photo (scripts/bench_lab.mjs).
# npm run bench -- motion: the moving-window figures played frame by frame (scripts/bench-motion.mjs).
# npm run bench -- sweep: a sweep of 200 points on every example with a number input (scripts/bench-sweep.mjs).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = ops ]; then
  shift
  exec bash scripts/bench-ops/run.sh "$@"
fi
bash scripts/setup.sh --test
SKIP_SETUP=1 bash scripts/build.sh
if [ "${1:-}" = motion ]; then
  shift
  exec node scripts/bench-motion.mjs "$@"
fi
if [ "${1:-}" = sweep ]; then
  shift
  exec node scripts/bench-sweep.mjs "$@"
fi
if [ "${1:-}" = lab ]; then
  shift
  exec node scripts/bench_lab.mjs "$@"
fi
node scripts/bench.mjs "$@"
node scripts/bench-embed.mjs "$@"
