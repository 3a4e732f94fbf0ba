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
katex=node_modules/katex/dist
cp "$katex/katex.min.js" "$katex/katex.min.css" dist/vendor/katex/
mkdir -p dist/vendor/katex/fonts
cp "$katex"/fonts/*.woff2 dist/vendor/katex/fonts/
# hashed names, import map, .gz/.br, _headers, then the service worker's list (sw-manifest.mjs)
node scripts/assets.mjs dist
echo "build: dist/ ready ($(du -sh dist | cut -f1))"
