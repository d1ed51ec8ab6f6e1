# Sourced by scripts/test.sh and scripts/serve.sh: installs whatever is missing, from the package
# registries only (crates.io, npm, Debian). No tool may fetch its own binaries or browser.

step() { printf '\n==> %s\n' "$*"; }

export PATH="$HOME/.cargo/bin:$PATH"

as_root() {
    if [ "$(id -u)" = 0 ]; then "$@"
    elif command -v sudo >/dev/null 2>&1; then sudo "$@"
    else echo "error: '$*' needs root (no sudo available)" >&2; exit 1
    fi
}

ensure_rust() {
    if ! command -v cargo >/dev/null 2>&1; then
        echo "error: cargo is not installed; install Rust with rustup first" >&2
        exit 1
    fi
}

# The wasm-bindgen CLI must have exactly the version of the wasm-bindgen crate in Cargo.lock
# (0.2.130); otherwise wasm-pack would try to download one from GitHub.
wasm_bindgen_version() {
    awk '/^name = "wasm-bindgen"$/{getline; print $3; exit}' Cargo.lock | tr -d '"'
}

ensure_wasm_toolchain() {
    ensure_rust
    if ! rustup target list --installed 2>/dev/null | grep -qx wasm32-unknown-unknown; then
        step "installing the wasm32-unknown-unknown target (rustup)"
        rustup target add wasm32-unknown-unknown
    fi
    if ! command -v wasm-pack >/dev/null 2>&1; then
        step "installing wasm-pack from crates.io (about 2 minutes)"
        cargo install wasm-pack --locked
    fi
    local want
    want=$(wasm_bindgen_version)
    if [ -z "$want" ]; then
        echo "error: Cargo.lock names no wasm-bindgen version" >&2
        exit 1
    fi
    if ! wasm-bindgen --version 2>/dev/null | grep -qx "wasm-bindgen $want"; then
        step "installing wasm-bindgen-cli $want from crates.io (about 3 minutes)"
        # Not --locked: a locked transitive version is missing from the registry index.
        cargo install wasm-bindgen-cli --version "$want" --force
    fi
}

ensure_browser() {
    if ! command -v chromium >/dev/null 2>&1 || ! command -v chromedriver >/dev/null 2>&1; then
        step "installing Debian's chromium and chromium-driver"
        as_root apt-get update -qq
        as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium chromium-driver >/dev/null
    fi
}

# Debian's firefox-esr (tests only): the offline file is also opened in Firefox, over its own
# Marionette protocol (tests/e2e/firefox.mjs) — no driver or browser is downloaded.
ensure_firefox() {
    if ! command -v firefox-esr >/dev/null 2>&1; then
        step "installing Debian's firefox-esr"
        as_root apt-get update -qq
        as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq firefox-esr >/dev/null
    fi
}

ensure_node() {
    if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
        step "installing Node.js and npm (Debian)"
        as_root apt-get update -qq
        as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq nodejs npm >/dev/null
    fi
}

# binaryen's wasm-opt from npm (132; Debian's 108 breaks the module), on PATH for wasm-pack.
ensure_binaryen() {
    ensure_node
    if [ ! -x scripts/node_modules/.bin/wasm-opt ]; then
        step "installing binaryen (wasm-opt) from npm"
        (cd scripts && npm ci --no-audit --no-fund --loglevel=error)
    fi
    export PATH="$PWD/scripts/node_modules/.bin:$PATH"
}

build_wasm() {
    ensure_binaryen
    step "building the wasm module (profile web, then wasm-opt: about 2 minutes) into www/pkg"
    local started=$SECONDS
    wasm-pack build --target web --profile web --out-dir www/pkg --no-pack
    # ~550 import names with wasm-bindgen's hashes, shortened: ≈ 10 kB of the gzip -9 size.
    node scripts/shrink-imports.mjs www/pkg
    echo "wasm build with wasm-opt: $((SECONDS - started)) s; $(wc -c < www/pkg/flexarm_bg.wasm) bytes"
}

# A Python with NumPy, SciPy and Matplotlib from PyPI, in a virtual environment of the repository's
# (for the exported Python scripts' test, its plot saved without a display, and the Python baseline
# of the benchmarks). Sets FLEXARM_PYTHON.
ensure_python_env() {
    local venv="${FLEXARM_PY_VENV:-target/py-bench-venv}"
    if ! { [ -x "$venv/bin/python" ] && "$venv/bin/python" -c 'import numpy, scipy, matplotlib' >/dev/null 2>&1; }; then
        step "making a Python virtual environment with numpy, scipy and matplotlib from PyPI in $venv"
        if ! command -v python3 >/dev/null 2>&1; then
            as_root apt-get update -qq
            as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq python3 python3-venv >/dev/null
        fi
        mkdir -p "$(dirname "$venv")"
        python3 -m venv "$venv"
        "$venv/bin/python" -m pip install --quiet --disable-pip-version-check numpy scipy matplotlib
    fi
    export FLEXARM_PYTHON="$PWD/$venv/bin/python"
}
