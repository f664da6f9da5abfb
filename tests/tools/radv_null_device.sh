#!/usr/bin/env bash
# RADV's null device (RADV_FORCE_FAMILY=navi21 with the radeon ICD of mesa-vulkan-drivers): a real
# GPU compiler without the GPU. (1) vkrt-bench gpu kernels builds the kernel variants of two course
# scenes and of the general kernel there, with registers from the compiler, and ends with its
# summary line; (2) vkrt itself refuses the device with a message instead of crashing in the
# driver (RADV segfaults on the first command pool of a null device).
# Usage: radv_null_device.sh BUILD_DIR SHARED_DIR. Skipped (exit 77) only where the radeon ICD is absent.
set -uo pipefail
build=$1 shared=$2
icd=/usr/share/vulkan/icd.d/radeon_icd.x86_64.json
if [ ! -f "$icd" ]; then
    echo "SKIP: no $icd (mesa-vulkan-drivers' radeon ICD): RADV's null device is not available"
    exit 77
fi
export RADV_FORCE_FAMILY=navi21 VK_ICD_FILENAMES=$icd XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-/tmp}
out=$("$build/vkrt-bench" gpu kernels "$shared/scenes/upstream/oneSphere.xml" "$shared/scenes/json/CornellBox_Dielectric.json" --general 2>&1)
rc=$?
echo "$out"
[ $rc -eq 0 ] || { echo "FAIL: vkrt-bench gpu kernels exited $rc"; exit 1; }
echo "$out" | grep -q "NAVI21" || { echo "FAIL: not built on RADV's null device"; exit 1; }
# Every row reports VGPRs from the compiler (a number, not '-').
rows=$(echo "$out" | grep -cE '^(oneSphere.xml|CornellBox_Dielectric.json) +(render|general) +[0-9]+ +[0-9]+ ')
[ "$rows" -eq 4 ] || { echo "FAIL: $rows of 4 rows carry register counts"; exit 1; }
echo "$out" | grep -qE '^kernels: [0-9]+ variants, max VGPRs [0-9]+, spilled VGPRs [0-9]+, max scratch [0-9]+ bytes$' ||
    { echo "FAIL: no summary line"; exit 1; }
msg=$("$build/vkrt" "$shared/scenes/upstream/oneSphere.xml" --device gpu -o "${TMPDIR:-/tmp}/radv_null_$$.png" 2>&1)
rc=$?
echo "$msg"
[ $rc -eq 1 ] || { echo "FAIL: vkrt on the null device exited $rc (1 expected: a message, not a crash)"; exit 1; }
echo "$msg" | grep -q "has no device memory" || { echo "FAIL: the message does not say why"; exit 1; }
echo "radv-null-ok"
