#!/usr/bin/env bash
# Installs whatever is missing on a fresh machine and runs every test of flexarm:
# native (cargo test), wasm in headless Chromium (wasm-pack test), and the page end to end
# (Playwright driving Debian's Chromium).
# Usage: bash scripts/test.sh
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
. scripts/setup.sh

ensure_rust
step "native tests (cargo test)"
cargo test --locked

ensure_python_env
step "the exported Python scripts, run with NumPy and SciPy (cargo test --test export_python -- --ignored)"
cargo test --locked --test export_python -- --ignored

ensure_node
step "unit tests of the page's modules (node --test www/js/)"
node --test www/js/

ensure_wasm_toolchain
ensure_browser
step "wasm tests in headless Chromium (wasm-pack test)"
wasm-pack test --headless --chrome --chromedriver "$(command -v chromedriver)" wasm-tests

build_wasm
step "type-checking the page's modules against the wasm-bindgen declarations (tsc --checkJs; the façade strictly)"
(cd tests/e2e && npm ci --no-audit --no-fund --loglevel=error)
tests/e2e/node_modules/.bin/tsc -p www/jsconfig.json
tests/e2e/node_modules/.bin/tsc -p www/jsconfig.strict.json

ensure_firefox
step "the offline file (flexarm bundle → target/offline/flexarm-offline.html), which the end-to-end tests open from disk"
mkdir -p target/offline
cargo run --locked --quiet --bin flexarm -- bundle --out target/offline/flexarm-offline.html

step "end-to-end tests of the page (Playwright + Chromium)"
node --test tests/e2e/
