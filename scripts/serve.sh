#!/usr/bin/env bash
# Installs whatever is missing on a fresh machine, builds the wasm module in release mode and
# serves the demo from www/ on 127.0.0.1 (port $PORT, default 8080), printing the URL.
# Usage: bash scripts/serve.sh
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
. scripts/setup.sh

ensure_wasm_toolchain
build_wasm
PORT="${PORT:-8080}"
step "serving www/ — open http://127.0.0.1:$PORT/ (Ctrl-C stops)"
exec python3 -m http.server "$PORT" --bind 127.0.0.1 --directory www
