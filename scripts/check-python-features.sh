#!/usr/bin/env bash
# Checks that the Python module's crates build with the same features in
# `cargo test --workspace` as in `pip install` (maturin builds rolldyn-py
# alone). Cargo unifies the features of a dev-dependency only into the
# builds that include it; if a dev-dependency turns on a feature of a crate
# the module shares (`clap/env`, `bitflags/std` through the benchmark
# harness's terminal-width help, a feature of the engine itself), pip's
# build cannot reuse the tests' artifacts and rebuilds the engine, Parquet
# and the CLI: three to four minutes more in CI. `.ci/run` calls this.
set -euo pipefail
cd "$(dirname "$0")/.."

features() {
  cargo tree --quiet "$@" --edges features --prefix none |
    sed -e 's/ (\*)$//' -e 's/ (command-line)$//' -e 's/ (proc-macro)$//' |
    grep -v '^$' | sort -u
}

module=$(mktemp)
workspace=$(mktemp)
trap 'rm -f "$module" "$workspace"' EXIT
features -p rolldyn-py --edges normal,build >"$module"
features --workspace >"$workspace"

# The crates in the module's graph, and the lines of those crates that
# only the workspace's build has.
crates=$(awk '{print $1}' "$module" | sort -u)
extra=$(comm -13 "$module" "$workspace" | awk -v crates="$crates" '
  BEGIN { n = split(crates, list, "\n"); for (i = 1; i <= n; i++) shared[list[i]] = 1 }
  ($1 in shared) { print }')
if [ -n "$extra" ]; then
  echo "error: the tests build these crates of the Python module with more features" >&2
  echo "than pip's build of it, which then rebuilds them (see this script's header):" >&2
  echo "$extra" | sed 's/^/  /' >&2
  echo "Give the dev-dependency that enables them the module's features, or enable" >&2
  echo "them in the workspace's dependency table too." >&2
  exit 1
fi
echo "The Python module's crates have the same features in the tests' build."
