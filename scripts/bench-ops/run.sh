#!/usr/bin/env bash
# npm run bench -- ops [--json FILE] [--no-native]: sets up what the
# benchmark alone needs (never by npm start / npm test, never shipped):
#   scripts/bench-ops/node_modules  @techstark/opencv-js (its own package.json)
#   .venv-bench/                    numpy for gen_images.py, opencv-python-headless
#                                   for the optional native column
#   data/                           the inputs, from ../shared/bench/gen_images.py
# then builds the lab's wasm with +simd128 (profile `fast`, feature `bench`:
# FastImage) and runs bench.mjs.
# Env: BENCH_SIZES (512,2048,4096), BENCH_BUDGET_S, BENCH_MIN_REPS,
# BENCH_MAX_REPS, BENCH_WARMUP, BENCH_TASKS (comma list), BENCH_SIMD=0 for the
# scalar build.
set -euo pipefail
cd "$(dirname "$0")/../.."
export PATH="$HOME/.cargo/bin:$PATH"
bash scripts/setup.sh
# ../shared/bench beside the repository (or above a worktree); SHARED_BENCH overrides
shared=${SHARED_BENCH:-}
for d in ../shared/bench ../../shared/bench; do [ -n "$shared" ] || { [ -f "$d/gen_images.py" ] && shared=$d; }; done
shared=${shared:-../shared/bench}
[ -f "$shared/gen_images.py" ] || { echo "bench ops: $shared/gen_images.py not found (the shared benchmark contract)"; exit 1; }
if [ ! -d scripts/bench-ops/node_modules/@techstark/opencv-js ]; then
  echo "bench ops: installing @techstark/opencv-js into scripts/bench-ops/ (benchmark only)"
  (cd scripts/bench-ops && npm install --no-audit --no-fund)
fi
if [ ! -x .venv-bench/bin/python ]; then
  echo "bench ops: creating .venv-bench (numpy; opencv-python-headless for the native column)"
  python3 -m venv .venv-bench
fi
.venv-bench/bin/python -c 'import numpy' 2>/dev/null || .venv-bench/bin/pip install -q numpy
.venv-bench/bin/python -c 'import cv2' 2>/dev/null || .venv-bench/bin/pip install -q opencv-python-headless \
  || echo "bench ops: no opencv-python-headless; the native column stays empty"
sizes=${BENCH_SIZES:-512,2048,4096}
need=0
for n in ${sizes//,/ }; do [ -f "data/gray_$n.u8" ] && [ -f "data/bin_$n.u8" ] || need=1; done
[ -f data/manifest.json ] || need=1
if [ $need = 1 ]; then
  echo "bench ops: generating data/ for $sizes"
  .venv-bench/bin/python "$shared/gen_images.py" --out data --sizes 512,2048,4096
fi
simd=${BENCH_SIMD:-1}
if [ "$simd" = 1 ]; then flags="-C target-feature=+simd128"; dir=target/bench-simd; else flags=""; dir=target/bench-scalar; fi
# --features bench: the FastImage exports bench.mjs times (never in the page's build)
echo "bench ops: cargo build -p photogrammetry-lab --features bench --profile fast --target wasm32-unknown-unknown (RUSTFLAGS='$flags')"
RUSTFLAGS="$flags" cargo build -p photogrammetry-lab --features bench --profile fast --target wasm32-unknown-unknown --target-dir "$dir"
wasm-bindgen --target web --no-typescript --out-dir "$dir/pkg" "$dir/wasm32-unknown-unknown/fast/photogrammetry_lab.wasm"
BENCH_PKG="$dir/pkg" node scripts/bench-ops/bench.mjs "$@"
