#!/usr/bin/env bash
# npm start: set up what is missing, build, and serve dist/ on
# http://127.0.0.1:8080 (PORT=9000 npm start, or npm start -- --port 9000).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
exec node scripts/serve.mjs --dir dist "$@"
