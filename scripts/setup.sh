# Sourced by scripts/test.sh and scripts/serve.sh: shared helpers and the native toolchain check.
# Everything comes from the package registries (crates.io, npm, PyPI, Debian); nothing else is fetched.

step() { printf '\n==> %s\n' "$*"; }

export PATH="$HOME/.cargo/bin:$PATH"
if ! command -v cargo >/dev/null 2>&1; then
    echo "error: cargo is not installed; this machine kind ships Rust via rustup (see README)" >&2
    exit 1
fi
