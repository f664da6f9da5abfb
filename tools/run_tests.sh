#!/usr/bin/env bash
# The whole test suite: the README's test command, and CI's (.ci/run). ctest over build/, and a
# failure when any test was skipped: tests skip only when an input is missing (../shared beside the
# repository, see tests/common/test_paths.h), and where the suite is the gate nothing may be missing.
# Extra arguments go to ctest (e.g. -R scene).
set -euo pipefail
cd "$(dirname "$0")/.."
log=$(mktemp)
trap 'rm -f "$log"' EXIT
status=0
ctest --test-dir build --output-on-failure "$@" | tee "$log" || status=$?
if grep -q "(Skipped)" "$log"; then
  echo "run_tests: the tests listed above as Skipped did not run (each names what it is missing); failing" >&2
  exit 1
fi
exit "$status"
