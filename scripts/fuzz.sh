#!/usr/bin/env bash
# the fuzzing harness for hours: the CI test
# (crates/rolldyn-cli/tests/end_to_end/fuzz.rs) with many more cases, on the release
# build. Usage: scripts/fuzz.sh [CASES] [SEED]   (default 100000 cases, seed 1)
# Prints the cases per command and exit code, and every failure with its
# seed and case number (the case text is printed; add it to REGRESSIONS).
set -euo pipefail
cd "$(dirname "$0")/.."
cases=${1:-100000}
seed=${2:-1}
ROLLDYN_FUZZ_CASES=$cases ROLLDYN_FUZZ_SEED=$seed \
  cargo test --release -p rolldyn-cli --test end_to_end fuzz::fuzzed -- --nocapture 2>&1 \
  | grep -vE '^(running|test |$)'
