#!/usr/bin/env bash
# Runs the Python/NumPy/SciPy baseline of the flexarm closed loop (bench/python_loop.py).
# Creates a virtualenv at ${FLEXARM_PY_VENV:-target/py-bench-venv} (relative to the repo root)
# with numpy and scipy from PyPI if it is missing, then passes all arguments through, e.g.
#   bash bench/run_python.sh --delta 0.01 --duration 10 --pf paper --repeats 3
# Only the JSON result goes to stdout; setup messages go to stderr.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

VENV="${FLEXARM_PY_VENV:-target/py-bench-venv}"
PY="$VENV/bin/python"

if ! { [ -x "$PY" ] && "$PY" -c 'import numpy, scipy' >/dev/null 2>&1; }; then
    echo "run_python.sh: setting up virtualenv in $VENV (numpy, scipy from PyPI)" >&2
    start=$(date +%s)
    mkdir -p "$(dirname "$VENV")"
    python3 -m venv "$VENV"
    "$PY" -m pip install --quiet --disable-pip-version-check numpy scipy >&2
    echo "run_python.sh: virtualenv ready in $(( $(date +%s) - start )) s" >&2
fi

exec "$PY" bench/python_loop.py "$@"
