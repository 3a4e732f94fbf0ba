#!/usr/bin/env bash
# Builds the release wasm and assembles the static site in dist/:
#   dist/index.html, embed.html, *.js, style.css   (from www/)
#   dist/pkg/<module>.js + <module>_bg.wasm        (wasm-bindgen --target web; web/*)
#   dist/pkg/photogrammetry_playground.js, examples.js  (the JS API entries, hand-written in www/api/)
#   dist/catalog.json                              (the catalog, from the Rust entries, natively)
#   dist/vendor/katex/                             (KaTeX from its npm package)
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
[ "${SKIP_SETUP:-0}" = 1 ] || bash scripts/setup.sh
# DIST=dir builds the site there instead of dist/ (e.g. a second copy to test against)
DIST="${DIST:-dist}"

# One cargo invocation links every wasm module (cargo runs them in parallel):
# the core (the root crate) is compiled once, and each module is a thin crate
# that links it: web/<topic>/ (one per topic of examples::MODULES), web/all/
# (every example and practice mode), lab/ (the image lab).
echo "build: cargo build --release --target wasm32-unknown-unknown --workspace --lib"
cargo build --release --target wasm32-unknown-unknown --workspace --lib

rm -rf "$DIST"
mkdir -p "$DIST"/pkg "$DIST"/lab/pkg "$DIST"/vendor/katex
cp -R www/. "$DIST"/
# the hand-written API entries (www/api/) sit beside the generated modules they load
mv "$DIST"/api/* "$DIST"/pkg/ && rmdir "$DIST"/api
# wasm-bindgen for each module, two at a time: dist/pkg/<name>.js + <name>_bg.wasm
modules=$(cd web && ls -d */ | tr -d /)
for name in $modules; do echo "$name"; done | xargs -P 2 -I{} \
  wasm-bindgen --target web --no-typescript --remove-name-section --remove-producers-section \
  --out-dir "$DIST"/pkg --out-name {} target/wasm32-unknown-unknown/release/playground_{}.wasm
# The image lab's own module (lab/), loaded only when #/lab opens.
wasm-bindgen --target web --no-typescript --remove-name-section --remove-producers-section --out-dir "$DIST"/lab/pkg \
  target/wasm32-unknown-unknown/release/photogrammetry_lab.wasm
# The catalog as data, written natively from the Rust entries (examples/catalog_json.rs, serde_json;
# a host build of the core, the one `cargo test` makes), then checked entry by entry against the
# wasm's own catalog() (pkg/all.js) and the modules built (scripts/catalog-json.mjs).
echo "build: cargo run --example catalog_json (catalog.json)"
cargo run --quiet --example catalog_json -- "$DIST"/catalog.json
node scripts/catalog-json.mjs "$DIST"
# ... and its SIMD128 build (profile `fast`, the target dir `npm run bench -- ops`
# also uses), which the lab's worker loads where the browser has SIMD.
echo "build: cargo build --profile fast --target wasm32-unknown-unknown -p photogrammetry-lab (+simd128)"
RUSTFLAGS="-C target-feature=+simd128" cargo build --profile fast --target wasm32-unknown-unknown \
  -p photogrammetry-lab --lib --target-dir target/bench-simd
mkdir -p "$DIST"/lab/pkg-simd
wasm-bindgen --target web --no-typescript --remove-name-section --remove-producers-section --out-dir "$DIST"/lab/pkg-simd \
  target/bench-simd/wasm32-unknown-unknown/fast/photogrammetry_lab.wasm
katex=node_modules/katex/dist
cp "$katex/katex.min.js" "$katex/katex.min.css" "$DIST"/vendor/katex/
mkdir -p "$DIST"/vendor/katex/fonts
cp "$katex"/fonts/*.woff2 "$DIST"/vendor/katex/fonts/
# The QR encoder of the printed worksheets (uqr, MIT, no dependencies), one ES module
# bundled and minified by esbuild; practice/sheets.js imports it only when a sheet is made.
npx --no-install esbuild node_modules/uqr/dist/index.mjs --bundle --format=esm --minify \
  --legal-comments=none --log-level=warning --outfile="$DIST"/vendor/uqr.js
sizes=$(for name in $modules; do printf ' %s %s' "$name" "$(gzip -9c "$DIST/pkg/${name}_bg.wasm" | wc -c)"; done)
lab="lab $(gzip -9c "$DIST"/lab/pkg/photogrammetry_lab_bg.wasm | wc -c), lab SIMD $(gzip -9c "$DIST"/lab/pkg-simd/photogrammetry_lab_bg.wasm | wc -c)"
# hashed names and the HTML with its import map; then each example's seed solution as the page
# renders it (scripts/prerender.mjs, in Chromium: shown before the page's JS has run); then
# _headers, the service worker's list (sw-manifest.mjs) and the .gz/.br copies
node scripts/bundle.mjs "$DIST"
node scripts/assets.mjs "$DIST" --stage names
node scripts/prerender.mjs "$DIST"
node scripts/assets.mjs "$DIST" --stage finish
echo "build: $DIST/ ready ($(du -sh "$DIST" | cut -f1); wasm gzipped bytes:$sizes; $lab)"
