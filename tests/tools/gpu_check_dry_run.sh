#!/usr/bin/env bash
# tools/gpu_check.sh --dry-run from a bundle made here, run as on a GPU machine (env -i, only
# VKRT_SHARED set), on lavapipe with tiny sizes (ctest tools.gpu_check_dry_run): every stage must
# end ok and write its file, and the summary must name the device, the agreement and the rates.
#   gpu_check_dry_run.sh BUILD WORK SHARED
set -uo pipefail
build=$1 work=$2 shared=$3
repo=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$work" && mkdir -p "$work"
if ! "$repo/tools/bundle.sh" "$work/bundle" "$build" --tests --no-oiio > "$work/bundle.log" 2>&1; then
  echo "bundle.sh failed:"; cat "$work/bundle.log"; exit 1
fi
# A budget far above the ~1 minute it takes alone: in the suite it shares two cores with the fuzzing
# build, and a stage cut short would fail the test for a reason that is not a defect.
env -i PATH=/usr/bin:/bin HOME="$work" VKRT_SHARED="$shared" "$work/bundle/gpu_check.sh" --dry-run --budget 1200 \
  --out "$work/results" > "$work/gpu_check.log" 2>&1
rc=$?
[ "$rc" = 0 ] || { echo "gpu_check.sh exited $rc:"; cat "$work/gpu_check.log"; }
for f in device.txt agreement.txt agreement.xml rays.txt renders.txt gpu_scenes.txt stages.txt progress.log summary.txt; do
  [ -s "$work/results/$f" ] || echo "missing $f"
done
cat "$work/results/stages.txt" "$work/results/summary.txt"
