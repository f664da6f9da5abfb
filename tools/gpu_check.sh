#!/usr/bin/env bash
# The device check: one command, run once on a GPU machine from the bundle (tools/bundle.sh
# --tests), that measures rather than debugs. Each stage has its own share of the time budget
# and writes its result file as soon as it ends, so a run cut short still reports what it finished;
# summary.txt is rewritten after every stage. docs/BENCHMARKS.md "On a GPU machine" says how to
# run it and read the files.
#
#   gpu_check.sh [--out DIR] [--budget SECONDS] [--dry-run] [--build DIR]
#     --out DIR        result files (default ./gpu_check_results)
#     --budget S       total seconds for all stages (default 480)
#     --dry-run        tiny sizes, for lavapipe: every stage and file, in about a minute (a ctest test)
#     --build DIR      run from a build folder instead of a bundle (the binaries' wrappers beside this script)
#   VKRT_SHARED        the course's scenes (shared/ with scenes/upstream and scenes/json): required
#
# Stages and files (each also logged to progress.log):
#   device     device.txt       vkrt --list-devices (the device, driver, queue family, timestamp support, limits)
#   agreement  agreement.txt    GPU vs CPU on every course scene, XML and JSON (env maps, textures), validation on;
#                               the wavefront stages against the megakernel on a scene per feature;
#              agreement.xml    gtest's report, one entry per test
#   rays       rays.txt         vkrt-bench gpu rays: >= 16M rays of each kind on a mesh that fills the frame (Buddha),
#                               wall-clock and timestamp (kernel) rates, GPU hits checked against the CPU's
#   renders    renders.txt      whole-scene renders at 1920x1080, 64 rpp: a cold process (empty pipeline caches)
#                               then a warm one, per scene and per GPU kernel (--gpu-kernel megakernel, wavefront)
#   scenes     gpu_scenes.txt   vkrt-bench gpu scenes: every upstream scene, specialised and general kernel vs CPU
#   summary    summary.txt      one line per stage and one line for all
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=gpu_check_results
budget=480
dry=0
bin=$here
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out=$2; shift 2 ;;
    --budget) budget=$2; shift 2 ;;
    --dry-run) dry=1; shift ;;
    --build) bin=$(cd "$2" && pwd); shift 2 ;;
    *) echo "gpu_check: unknown argument $1 (see the comment at the top of $0)" >&2; exit 2 ;;
  esac
done
shared=${VKRT_SHARED:-}
if [ -z "$shared" ] || [ ! -d "$shared/scenes/upstream" ] || [ ! -d "$shared/scenes/json" ]; then
  echo "gpu_check: set VKRT_SHARED to the folder holding scenes/upstream and scenes/json (the course's scenes)" >&2
  exit 2
fi
export VKRT_SHARED=$shared
# Test binaries: beside the wrappers in a bundle, under tests/ in a build folder.
test_binary() {
  if [ -x "$bin/$1" ]; then echo "$bin/$1"; else echo "$bin/tests/$2/$1"; fi
}
vkrt=$bin/vkrt
bench=$bin/vkrt-bench
agreement=$(test_binary vkrt_agreement_tests agreement)
for f in "$vkrt" "$bench" "$agreement"; do
  [ -x "$f" ] || { echo "gpu_check: $f not found (a bundle made with tools/bundle.sh --tests, or --build DIR)" >&2; exit 2; }
done
mkdir -p "$out"
out=$(cd "$out" && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
: > "$out/progress.log"
: > "$out/stages.txt"
start=$(date +%s)

log() { echo "$(date +%T) $*" | tee -a "$out/progress.log" >&2; }

# run_stage NAME SHARE_PERCENT COMMAND...: the command under `timeout`, its output in the stage's
# file; one line per stage in stages.txt: name, status (ok / failed rc N / cut short after S s), seconds.
run_stage() {
  local name=$1 share=$2 file=$3
  shift 3
  local limit=$((budget * share / 100))
  [ "$limit" -lt 10 ] && limit=10
  local left=$((budget - ($(date +%s) - start)))
  if [ "$left" -lt 5 ]; then
    echo "$name skipped (budget spent) 0" >> "$out/stages.txt"
    log "$name: skipped, the budget is spent"
    return
  fi
  [ "$limit" -gt "$left" ] && limit=$left
  log "$name: up to ${limit}s -> $file"
  local t0=$(date +%s)
  timeout --kill-after=10 "$limit" "$@" > "$out/$file" 2>&1
  local rc=$?
  local took=$(($(date +%s) - t0))
  local status=ok
  if [ "$rc" = 124 ] || [ "$rc" = 137 ]; then status="cut short after ${limit}s"
  elif [ "$rc" != 0 ]; then status="failed rc $rc"; fi
  echo "$name $status $took" >> "$out/stages.txt"
  log "$name: $status (${took}s)"
  write_summary
}

# The figures each stage's file holds, read back for summary.txt.
write_summary() {
  {
    echo "# vkrt device check, $(date -u +%Y-%m-%dT%H:%M:%SZ), budget ${budget}s$([ "$dry" = 1 ] && echo ', dry run')"
    sed 's/^/stage /' "$out/stages.txt"
    local device=$(sed -n 's/^0: \(.*\)$/\1/p' "$out/device.txt" 2>/dev/null | head -1)
    local passed=$(grep -o '\[  PASSED  \] [0-9]* test' "$out/agreement.txt" 2>/dev/null | grep -o '[0-9]*')
    local failed=$(grep -o '\[  FAILED  \] [0-9]* test' "$out/agreement.txt" 2>/dev/null | grep -o '[0-9]*')
    local rays=$(grep -E '^(primary|shadow|diffuse) rays' "$out/rays.txt" 2>/dev/null |
                 awk '{printf "%s%s %s M rays %.1f/%s Mrays/s", (NR > 1 ? ", " : ""), $1, sprintf("%.1f", $3 / 1e6), $5, $7}')
    local renders=$(grep -c '^render ' "$out/renders.txt" 2>/dev/null)
    local ratio=$(grep -m1 'gpu/cpu (time)' "$out/gpu_scenes.txt" 2>/dev/null | sed 's/^ *//; s/  */ /g')
    local scenes=$(grep -c -E '^[^ #].* [0-9.]+ +[0-9.]+$' "$out/gpu_scenes.txt" 2>/dev/null)
    echo "summary: device ${device:-unknown}; agreement ${passed:-0} passed, ${failed:-0} failed; rays (wall/kernel) ${rays:-none}; ${renders:-0} renders timed; ${scenes:-0} scenes in vkrt-bench gpu scenes, ${ratio:-no summary}"
  } > "$out/summary.txt"
}

if [ "$dry" = 1 ]; then
  rays_size=(64 64 1); rays_rounds=1; rays_zoom=5
  render_size=(-w 32 -h 18 -r 2)
  renders=("$bin/scenes/glass_and_instances.xml" "$shared/scenes/json/diffuseScene_multipleSpheres.json")
  [ -d "$bin/scenes" ] || renders[0]=$here/../scenes/glass_and_instances.xml
  agreement_filter='GpuCpuAgreement.EveryJsonSceneAt64x64With1Rpp:WavefrontRender.TheImageDoesNotDependOnThePathsInFlight'
  scenes_args=("$scratch/scenes" -w 16 -h 16 -r 1)
  mkdir -p "$scratch/scenes"
  cp "$shared/scenes/upstream/areaLight.xml" "$shared/scenes/upstream/boxSphereTest.xml" "$scratch/scenes/"
else
  # 2048 x 2048 x 5 = 21.0M primary rays; at zoom 5 the Buddha covers 96% of the frame (measured
  # here: primary_hit_fraction 0.964), so the shadow and diffuse sets (one ray per primary hit) are
  # about 20M each.
  rays_size=(2048 2048 5); rays_rounds=3; rays_zoom=5
  render_size=(-w 1920 -h 1080 -r 64)
  renders=("$bin/scenes/glass_and_instances.xml" "$shared/scenes/upstream/dragons00.xml"
           "$shared/scenes/json/diffuseScene_multipleSpheres.json" "$shared/scenes/json/emitterTest_OBJ.json")
  [ -d "$bin/scenes" ] || renders[0]=$here/../scenes/glass_and_instances.xml
  agreement_filter='GpuCpuAgreement.*:JsonTwins.*:ProgressiveRender.*:WavefrontRender*'
  scenes_args=("$shared/scenes/upstream" -w 256 -h 256 -r 16)
fi

renders_stage() {
  for scene in "${renders[@]}"; do
    [ -f "$scene" ] || { echo "missing $scene"; continue; }
    for kernel in megakernel wavefront; do
      for run in cold warm; do
        # Cold: a fresh process with empty pipeline caches (vkrt's and the NVIDIA driver's own);
        # warm: the same caches again, as a user's second render.
        [ "$run" = cold ] && rm -rf "$scratch/cache" && mkdir -p "$scratch/cache"
        line=$(VKRT_PIPELINE_CACHE_DIR="$scratch/cache/vkrt" __GL_SHADER_DISK_CACHE_PATH="$scratch/cache" \
               "$vkrt" "$scene" "${render_size[@]}" --device gpu --gpu-kernel "$kernel" -o "$scratch/render.png" 2>&1 | tail -1)
        echo "render $kernel $run $(basename "$scene"): $line"
      done
    done
  done
}

run_stage device 2 device.txt "$vkrt" --list-devices
run_stage agreement 35 agreement.txt env VKRT_REQUIRE_SHARED=1 "$agreement" --gtest_filter="$agreement_filter" \
  --gtest_output="xml:$out/agreement.xml"
run_stage rays 25 rays.txt "$bench" gpu rays "$shared/scenes/upstream/objFiles/buddha.obj" "${rays_size[@]}" \
  --zoom "$rays_zoom" --rounds "$rays_rounds" --threads "$(nproc)" --no-peer
export -f renders_stage
export vkrt scratch
run_stage renders 23 renders.txt bash -c "$(declare -p renders render_size); renders_stage"
run_stage scenes 15 gpu_scenes.txt "$bench" gpu scenes "${scenes_args[@]}"
write_summary
log "done in $(($(date +%s) - start))s: $out/summary.txt"
tail -1 "$out/summary.txt"
