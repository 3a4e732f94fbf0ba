#!/usr/bin/env bash
# Installs whatever the project needs and the machine is missing; quick when
# everything is there already.
#   scripts/setup.sh            build tools: wasm32 target, wasm-bindgen-cli
#                               (the version of the wasm-bindgen crate in
#                               Cargo.lock), npm dependencies, Chromium (the
#                               build's prerender step; Debian's package)
#   scripts/setup.sh --test     also rustfmt, clippy, chromedriver
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH="$HOME/.cargo/bin:$PATH"

for_tests=0
[ "${1:-}" = "--test" ] && for_tests=1
say() { echo "setup: $*"; }

command -v cargo >/dev/null || { say "cargo is missing: install Rust with rustup (https://rustup.rs) first" >&2; exit 1; }
command -v npm >/dev/null || { say "npm is missing: install Node.js 20 or newer first" >&2; exit 1; }

if ! rustup target list --installed | grep -qx wasm32-unknown-unknown; then
  say "adding the wasm32-unknown-unknown target"
  rustup target add wasm32-unknown-unknown
fi

if [ "$for_tests" = 1 ]; then
  for c in rustfmt clippy; do
    if ! rustup component list --installed | grep -q "^$c"; then
      say "adding $c"
      rustup component add "$c"
    fi
  done
fi

# wasm-bindgen-cli must match the wasm-bindgen crate exactly.
want=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock)
[ -n "$want" ] || { say "cannot read the wasm-bindgen version from Cargo.lock" >&2; exit 1; }
have=$(wasm-bindgen --version 2>/dev/null | awk '{print $2}' || true)
# It compiles (CPU) while npm and apt download (network, disk) below: on a
# fresh machine the two overlap instead of adding up.
bindgen_pid=""
bindgen_log=""
if [ "$have" != "$want" ] || ! command -v wasm-bindgen-test-runner >/dev/null; then
  say "installing wasm-bindgen-cli $want (have: ${have:-none}); this compiles for a few minutes, once, beside the other downloads"
  bindgen_log=$(mktemp)
  cargo install wasm-bindgen-cli --version "$want" >"$bindgen_log" 2>&1 &
  bindgen_pid=$!
fi

if [ ! -f node_modules/.package-lock.json ] || [ package-lock.json -nt node_modules/.package-lock.json ]; then
  say "installing npm dependencies"
  npm ci --no-audit --no-fund
fi

# Chromium: the build saves each example's seed solution as the page renders it
# (scripts/prerender.mjs); the tests drive the page and the wasm tests with it
if [ ! -x /usr/bin/chromium ] || { [ "$for_tests" = 1 ] && [ ! -x /usr/bin/chromedriver ]; }; then
  if [ "$for_tests" = 0 ] && ! command -v apt-get >/dev/null; then
    say "no Chromium and no apt-get: the build skips its prerender step (the page works; its first numbers come later)"
  else
    say "installing Debian's chromium and chromium-driver"
    sudo=""
    [ "$(id -u)" = 0 ] || sudo="sudo"
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get update
    $sudo apt-get install -y chromium chromium-driver
  fi
fi

if [ -n "$bindgen_pid" ]; then
  if wait "$bindgen_pid"; then
    say "wasm-bindgen-cli $want installed"
    rm -f "$bindgen_log"
  else
    cat "$bindgen_log" >&2
    say "cargo install wasm-bindgen-cli --version $want failed (its output is above)" >&2
    exit 1
  fi
fi
