#!/usr/bin/env bash
# tools/bundle.sh's promises, checked end to end (ctest tools.bundle_runs_where_it_is_moved):
#  - the bundle, moved to another folder and run under env -i with the OpenImageIO module pointed at
#    nothing, renders an environment-map scene and a textured scene to the build's bytes (PNG decoded
#    natively, no path of the build compiled in);
#  - no binary or library of vkrt's holds an AVX-512 (zmm) instruction;
#  - the bundle's agreement test binary passes with only VKRT_SHARED set;
#  - the bundle carries the Vulkan loader and the validation layer.
#   bundle_check.sh BUILD WORK SHARED
set -euo pipefail
trap 'echo "bundle_check.sh: failed at line $LINENO (exit $?)"' ERR
build=$1 work=$2 shared=$3
repo=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$work" && mkdir -p "$work"
"$repo/tools/bundle.sh" "$work/bundle" "$build" --tests --no-oiio > "$work/bundle.log" 2>&1 ||
  { echo "bundle.sh failed:"; cat "$work/bundle.log"; exit 1; }
mv "$work/bundle" "$work/moved"
bundle=$work/moved
clean() { env -i PATH=/usr/bin:/bin HOME="$work" VKRT_OIIO_MODULE=/nonexistent/libvkrt_oiio.so "$@"; }

for scene in mirrorTest2.xml earth.xml; do
  # --device gpu: the bundle's own loader and embedded kernels render (auto would take the CPU
  # reference where lavapipe is the only device).
  clean "$bundle/vkrt" "$shared/scenes/upstream/$scene" -w 48 -h 36 -r 2 -q --device gpu -o "$work/bundled_$scene.png"
  "$build/vkrt" "$shared/scenes/upstream/$scene" -w 48 -h 36 -r 2 -q --device gpu -o "$work/built_$scene.png"
  cmp "$work/bundled_$scene.png" "$work/built_$scene.png"
  echo "same bytes: $scene"
done

zmm=0
for f in "$bundle"/bin/*; do
  n=$(objdump -d --no-show-raw-insn "$f" | grep -c '%zmm' || true)
  [ "$n" -gt 0 ] && echo "zmm instructions in $(basename "$f"): $n"
  zmm=$((zmm + n))
done
echo "zmm instructions in the bundle's binaries: $zmm"
[ "$zmm" = 0 ]

[ -f "$bundle/lib/libvulkan.so.1" ] && echo "loader: bundled"
[ -f "$bundle/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json" ] && echo "validation layer: bundled"

env -i PATH=/usr/bin:/bin HOME="$work" VKRT_SHARED="$shared" "$bundle/vkrt_agreement_tests" \
  --gtest_filter=GpuCpuAgreement.EveryUpstreamAndBundledSceneAt64x64 > "$work/agreement.log" 2>&1 ||
  { cat "$work/agreement.log"; exit 1; }
grep '\[  PASSED  \] 1 test' "$work/agreement.log"
echo "bundle-ok"
