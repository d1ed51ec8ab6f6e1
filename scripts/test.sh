#!/usr/bin/env bash
# Installs whatever is missing on a fresh machine and runs every test of flexarm.
# Usage: bash scripts/test.sh
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
. scripts/setup.sh

step "native tests (cargo test)"
cargo test --locked
