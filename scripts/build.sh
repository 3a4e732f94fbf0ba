#!/usr/bin/env bash
# Builds the release wasm and assembles the static site in dist/:
#   dist/index.html, embed.html, *.js, style.css   (from www/)
#   dist/pkg/                                      (wasm-bindgen --target web)
#   dist/vendor/katex/                             (KaTeX from its npm package)
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
[ "${SKIP_SETUP:-0}" = 1 ] || bash scripts/setup.sh

echo "build: cargo build --release --target wasm32-unknown-unknown"
cargo build --release --target wasm32-unknown-unknown --lib

rm -rf dist
mkdir -p dist/pkg dist/vendor/katex
wasm-bindgen --target web --no-typescript --remove-name-section --remove-producers-section --out-dir dist/pkg \
  target/wasm32-unknown-unknown/release/photogrammetry_playground.wasm
cp -R www/. dist/
# The image lab's own module (lab/), loaded only when #/lab opens.
echo "build: cargo build --release --target wasm32-unknown-unknown -p photogrammetry-lab"
cargo build --release --target wasm32-unknown-unknown -p photogrammetry-lab --lib
mkdir -p dist/lab/pkg
wasm-bindgen --target web --no-typescript --remove-name-section --remove-producers-section --out-dir dist/lab/pkg \
  target/wasm32-unknown-unknown/release/photogrammetry_lab.wasm
# ... and its SIMD128 build (profile `fast`, the target dir `npm run bench -- ops`
# also uses), which the lab's worker loads where the browser has SIMD.
echo "build: cargo build --profile fast --target wasm32-unknown-unknown -p photogrammetry-lab (+simd128)"
RUSTFLAGS="-C target-feature=+simd128" cargo build --profile fast --target wasm32-unknown-unknown \
  -p photogrammetry-lab --lib --target-dir target/bench-simd
mkdir -p dist/lab/pkg-simd
wasm-bindgen --target web --no-typescript --remove-name-section --remove-producers-section --out-dir dist/lab/pkg-simd \
  target/bench-simd/wasm32-unknown-unknown/fast/photogrammetry_lab.wasm
katex=node_modules/katex/dist
cp "$katex/katex.min.js" "$katex/katex.min.css" dist/vendor/katex/
mkdir -p dist/vendor/katex/fonts
cp "$katex"/fonts/*.woff2 dist/vendor/katex/fonts/
node scripts/sw-manifest.mjs dist   # the service worker's version and file list
echo "build: dist/ ready ($(du -sh dist | cut -f1); wasm $(wc -c < dist/pkg/photogrammetry_playground_bg.wasm) bytes, lab wasm $(wc -c < dist/lab/pkg/photogrammetry_lab_bg.wasm) bytes, SIMD $(wc -c < dist/lab/pkg-simd/photogrammetry_lab_bg.wasm))"
