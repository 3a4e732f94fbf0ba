#!/usr/bin/env bash
# npm test: set up what is missing, then every test, stopping at the first
# failure: format, lints (host and wasm), native tests, wasm tests in headless
# Chromium, and the built page end to end in Chromium.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"
bash scripts/setup.sh --test
export CHROMEDRIVER=/usr/bin/chromedriver

# each step says how long the one before took (where CI's time goes)
last=$SECONDS
step() { printf '\n== (%ss) %s\n' "$((SECONDS - last))" "$*"; last=$SECONDS; }
trap 'printf "\n== npm test: %ss in all\n" "$SECONDS"' EXIT
step "cargo fmt --check"
cargo fmt --all -- --check
step "cargo clippy (host and wasm32, the core and the lab) -D warnings"
cargo clippy --workspace --all-targets -- -D warnings
cargo clippy --workspace --all-targets --target wasm32-unknown-unknown -- -D warnings
# the SIMD loops of the fast paths (own target dir: no rebuild ping-pong)
SIMD_FLAGS="-C target-feature=+simd128"
RUSTFLAGS="$SIMD_FLAGS" cargo clippy --workspace --all-targets --target wasm32-unknown-unknown --target-dir target/simd128 -- -D warnings
step "cargo test (native, the core and the lab)"
cargo test --workspace
step "cargo test --target wasm32-unknown-unknown (wasm-bindgen-test in headless Chromium)"
cargo test --target wasm32-unknown-unknown --test 'web*'
cargo test --target wasm32-unknown-unknown -p photogrammetry-lab --test 'web*'
step "fast paths against their references as wasm with +simd128 (web_fast in Node)"
RUSTFLAGS="$SIMD_FLAGS" cargo test --target wasm32-unknown-unknown --target-dir target/simd128 --test web_fast
step "unit tests of the page modules (Node)"
node --test tests/unit/
step "build the page"
SKIP_SETUP=1 bash scripts/build.sh
step "end-to-end tests of the page in Chromium"
# two files at a time: most of a page test is waiting (loads, frames, idle
# callbacks), and two Chromiums keep both cores busy
node --test --test-concurrency=2 tests/e2e/
