#!/usr/bin/env bash
# The whole test suite (the README's test command; `.ci/run` calls it):
# the Rust workspace, then the Python package installed from the
# repository with pip, as a user installs it, and its tests (pytest).
# Needs the Rust toolchain, gcc and Python ≥ 3.9 with pip; everything else
# (maturin, numpy, pyarrow, pytest, Dask distributed, pandas, matplotlib)
# is installed into a virtual environment under target/.
set -euo pipefail
cd "$(dirname "$0")/.."

venv=target/python-venv
if [ ! -x "$venv/bin/python" ]; then
  python3 -m venv "$venv"
fi
# matplotlib and pyarrow first: the examples' plot scripts draw their figures
# headless in `cargo test` (crates/rolldyn-cli/tests/end_to_end/example_tables.rs).
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check "maturin>=1.16,<2" \
  "matplotlib>=3.5" "pyarrow>=15"

start=$SECONDS
ROLLDYN_PYTHON="$PWD/$venv/bin/python" cargo test --workspace
echo "[test] $((SECONDS - start)) s: cargo test --workspace"

# The dev profile (dependencies and the engine at -O2, Cargo.toml) reuses
# what `cargo test` built; a user's `pip install` builds the release
# profile.
start=$SECONDS
PATH="$PWD/$venv/bin:$PATH" MATURIN_PEP517_ARGS="--profile dev" "$venv/bin/python" -m pip install --quiet \
  --disable-pip-version-check --no-build-isolation "./crates/rolldyn-py[test,plot]"
echo "[test] $((SECONDS - start)) s: pip install ./crates/rolldyn-py"
ROLLDYN_CLI="$PWD/target/debug/rolldyn" "$venv/bin/python" -m pytest -q crates/rolldyn-py/tests
