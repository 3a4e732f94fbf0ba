#!/usr/bin/env bash
# Builds the release wasm and the static site in dist/ (scripts/site.mjs, esbuild):
#   dist/index.html, embed.html          (from www/, the one <head> in www/head.partial.html)
#   dist/assets/*-<hash>.{js,css,wasm,json}  (every module, chunk, wasm and stylesheet: immutable)
#   dist/pkg/photogrammetry_playground.js, examples.js, lab/pkg/photogrammetry_lab.js
#                                        (the public JS API entries, docs/API.md: fixed names)
#   dist/embed.js, sw.js                 (fixed names), dist/vendor/ (KaTeX, uqr), dist/lab/samples/
#   dist/prerender/                      (each example's seed solution, scripts/prerender.mjs)
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
[ "${SKIP_SETUP:-0}" = 1 ] || bash scripts/setup.sh
# DIST=dir builds the site there instead of dist/ (e.g. a second copy to test against)
DIST="${DIST:-dist}"

# Two cargo invocations link the wasm modules (cargo runs each one's links in parallel):
# 1. every crate with its default features: web/<topic>/ (one per topic of examples::TOPICS)
#    with practice mode (its practice and grade exports and the examples' drills), web/all/
#    (every example and practice mode: the public API), lab/ (the image lab);
# 2. the topic crates again without their 'practice' feature: the module an example's page
#    loads (catalog, solve, parse_inputs; none of the drills' code linked in).
topics=$(cd web && ls -d */ | tr -d / | grep -vx all)
echo "build: cargo build --release --target wasm32-unknown-unknown --workspace --lib"
cargo build --release --target wasm32-unknown-unknown --workspace --lib
# The sources of the site, staged: www/ and what the build generates beside it (the
# wasm-bindgen packages, catalog.json, vendor/); scripts/site.mjs builds dist/ from it.
STAGE="target/site-stage/$(basename "$DIST")"
rm -rf "$STAGE" "$DIST"
mkdir -p "$STAGE" "$DIST"
cp -R www/. "$STAGE"/
# the hand-written API entries (www/api/) sit beside the generated modules they load
mkdir -p "$STAGE"/pkg "$STAGE"/lab/pkg "$STAGE"/lab/pkg-simd "$STAGE"/vendor/katex/fonts
mv "$STAGE"/api/* "$STAGE"/pkg/ && rmdir "$STAGE"/api
bindgen() { wasm-bindgen --target web --no-typescript --remove-name-section --remove-producers-section "$@"; }
export -f bindgen
# wasm-bindgen for each module, two at a time: pkg/<name>.js + <name>_bg.wasm; the topics'
# practice builds first, as pkg/<topic>_practice.js (invocation 2 then replaces their wasm)
modules=$(cd web && ls -d */ | tr -d /)
for name in $topics; do echo "$name"; done | xargs -P 2 -I{} bash -c \
  "bindgen --out-dir '$STAGE/pkg' --out-name {}_practice target/wasm32-unknown-unknown/release/playground_{}.wasm"
bindgen --out-dir "$STAGE"/pkg --out-name all target/wasm32-unknown-unknown/release/playground_all.wasm
echo "build: cargo build --release --target wasm32-unknown-unknown --no-default-features (the topics' example modules)"
cargo build --release --target wasm32-unknown-unknown --lib --no-default-features $(for t in $topics; do printf ' -p playground-%s' "$t"; done)
for name in $topics; do echo "$name"; done | xargs -P 2 -I{} bash -c \
  "bindgen --out-dir '$STAGE/pkg' --out-name {} target/wasm32-unknown-unknown/release/playground_{}.wasm"
# The image lab's own module (lab/), loaded only when #/lab opens.
bindgen --out-dir "$STAGE"/lab/pkg target/wasm32-unknown-unknown/release/photogrammetry_lab.wasm
# The catalog as data, written natively from the Rust entries (examples/catalog_json.rs, serde_json;
# a host build of the core, the one `cargo test` makes), then checked entry by entry against the
# wasm's own catalog() (pkg/all.js) and the modules built (scripts/catalog-json.mjs).
echo "build: cargo run --example catalog_json (catalog.json)"
cargo run --quiet --example catalog_json -- "$STAGE"/catalog.json
node scripts/catalog-json.mjs "$STAGE"
# ... and its SIMD128 build (profile `fast`, the target dir `npm run bench -- ops`
# also uses), which the lab's worker loads where the browser has SIMD: without the
# `formats` feature (JPEG its only decoder; the worker has the scalar build above
# decode the other formats), so that a lab visit downloads one build.
echo "build: cargo build --profile fast --target wasm32-unknown-unknown -p photogrammetry-lab --no-default-features (+simd128)"
RUSTFLAGS="-C target-feature=+simd128" cargo build --profile fast --target wasm32-unknown-unknown \
  -p photogrammetry-lab --lib --no-default-features --target-dir target/bench-simd
bindgen --out-dir "$STAGE"/lab/pkg-simd target/bench-simd/wasm32-unknown-unknown/fast/photogrammetry_lab.wasm
# KaTeX (loaded by math.js after the first numbers) as its authors minified it, and the QR
# encoder of the printed worksheets (uqr, MIT, no dependencies: practice/sheets.js imports it
# when a sheet is made) as one ES module: both keep their names (vendor/)
katex=node_modules/katex/dist
cp "$katex/katex.min.js" "$katex/katex.min.css" "$STAGE"/vendor/katex/
cp "$katex"/fonts/*.woff2 "$STAGE"/vendor/katex/fonts/
npx --no-install esbuild node_modules/uqr/dist/index.mjs --bundle --format=esm --minify \
  --legal-comments=none --log-level=warning --outfile="$STAGE"/vendor/uqr.js
sizes=$(for name in $modules; do printf ' %s %s' "$name" "$(gzip -9c "$STAGE/pkg/${name}_bg.wasm" | wc -c)"; done)
sizes="$sizes; practice:$(for name in $topics; do printf ' %s %s' "$name" "$(gzip -9c "$STAGE/pkg/${name}_practice_bg.wasm" | wc -c)"; done)"
lab="lab $(gzip -9c "$STAGE"/lab/pkg/photogrammetry_lab_bg.wasm | wc -c), lab SIMD $(gzip -9c "$STAGE"/lab/pkg-simd/photogrammetry_lab_bg.wasm | wc -c)"
# esbuild: bundles, splits, minifies and hashes into dist/assets/, writes the HTML
# (scripts/site.mjs); then each example's seed solution as the page renders it
# (scripts/prerender.mjs, in Chromium: shown before the page's JS has run); then the
# service worker's list, _headers and the .gz/.br copies
node scripts/site.mjs build "$STAGE" "$DIST"
node scripts/prerender.mjs "$DIST"
node scripts/site.mjs finish "$STAGE" "$DIST"
echo "build: $DIST/ ready ($(du -sh "$DIST" | cut -f1); wasm gzipped bytes:$sizes; $lab)"
