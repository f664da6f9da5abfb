#!/usr/bin/env bash
# A self-contained, relocatable bundle of vkrt for a machine that cannot build it (a GPU machine):
# the binaries, the run-time modules, every library they need but the C runtime, the Vulkan loader
# and the Khronos validation layer, the GLSL sources and the repository's scenes, the device check
# (tools/gpu_check.sh), and wrappers that point the dynamic loader and the Vulkan loader at the
# bundle. docs/BENCHMARKS.md "On a GPU machine" says how to use it.
#
#   tools/bundle.sh OUT [BUILD] [--tests] [--no-oiio] [--archive]
#     OUT        the bundle's folder (replaced)
#     BUILD      the build folder (default build/)
#     --tests    also the GPU test binaries (agreement, vulkan, stability, study) and the test kernels
#     --no-oiio  leave OpenImageIO out: EXR and formats other than PNG/PPM cannot be read or
#                written; PNG textures and environment maps still load (png_reader.h)
#     --archive  also OUT.tar.gz beside OUT (what a device call carries: under its 64 MiB)
#
# Run a bundled binary through its wrapper: OUT/vkrt scene.xml ..., OUT/vkrt-bench gpu rays ...,
# OUT/gpu_check.sh. The machine needs an x86-64-v3 processor (CMakeLists.txt VKRT_ARCH), glibc and
# libstdc++ as new as this one's (Debian 12: glibc 2.36, GCC 12) and its GPU's Vulkan driver (an ICD manifest); the loader
# comes from the bundle, so a machine with the driver but no libvulkan.so.1 runs it.
set -euo pipefail
trap 'echo "bundle: failed at line $LINENO (exit $?)" >&2' ERR
out=${1:?usage: tools/bundle.sh OUT [BUILD] [--tests] [--no-oiio] [--archive]}
shift
build=build
tests=0
oiio=1
archive=0
for arg in "$@"; do
  case "$arg" in
    --tests) tests=1 ;;
    --no-oiio) oiio=0 ;;
    --archive) archive=1 ;;
    -*) echo "bundle: unknown option $arg" >&2; exit 2 ;;
    *) build=$arg ;;
  esac
done
root=$(cd "$(dirname "$0")/.." && pwd)
[ -x "$build/vkrt" ] || { echo "bundle: $build/vkrt not found (build first: ./setup.sh)" >&2; exit 1; }

rm -rf "$out"
mkdir -p "$out/bin" "$out/lib" "$out/share/vulkan/explicit_layer.d"
binaries=("$build/vkrt" "$build/vkrt-bench")
modules=("$build/libvkrt_mpi.so")
[ "$oiio" = 1 ] && modules+=("$build/libvkrt_oiio.so")
if [ "$tests" = 1 ]; then
  for t in agreement/vkrt_agreement_tests vulkan/vkrt_vulkan_tests stability/vkrt_stability_tests study/vkrt_study_tests; do
    binaries+=("$build/tests/$t")
  done
fi
cp "${binaries[@]}" "${modules[@]}" "$out/bin/"
# The test binaries find shaders/ and scenes/ in the nearest folder above them that has both
# (tests/common/test_paths.cpp), the run-time modules beside them (host/modules/module_loader.h).
cp -r "$root/shaders" "$root/scenes" "$out/"
if [ "$tests" = 1 ]; then
  mkdir -p "$out/tests/vulkan"
  cp -r "$root/tests/vulkan/kernels" "$out/tests/vulkan/"
fi
cp "$root/tools/gpu_check.sh" "$out/gpu_check.sh"

# Every library the binaries and modules resolve to, except the C and C++ runtimes: the machine's
# own, with its dynamic linker; and its GPU driver, loaded into the same process, may need a newer
# libstdc++ than this machine's (GCC 12's), which an older one first on the path would refuse.
skip='^(linux-vdso|ld-linux|libc\.so|libm\.so|libdl\.so|libpthread\.so|librt\.so|libstdc\+\+\.so|libgcc_s\.so)'
for f in "${binaries[@]}" "${modules[@]}"; do
  ldd "$f" | awk '$2 == "=>" && $3 ~ /^\// {print $3}'
done | sort -u | while read -r lib; do
  name=$(basename "$lib")
  [[ "$name" =~ $skip ]] && continue
  cp -L "$lib" "$out/lib/$name"
done
[ -e "$out/lib/libvulkan.so.1" ] || { echo "bundle: the binaries do not link libvulkan.so.1" >&2; exit 1; }

# The validation layer: the GPU tests run with it (tests/agreement), as here, so that the first run
# on a real driver reports synchronisation errors lavapipe's in-order execution hides.
layer_json=/usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json
# No early exit in awk: under pipefail, ldconfig killed by SIGPIPE would end the script silently.
layer_lib=$(ldconfig -p | awk '/libVkLayer_khronos_validation.so / && !found {print $NF; found = 1}')
if [ -f "$layer_json" ] && [ -n "$layer_lib" ]; then
  cp "$layer_json" "$out/share/vulkan/explicit_layer.d/"
  cp -L "$layer_lib" "$out/lib/"
else
  echo "bundle: no Khronos validation layer here (vulkan-validationlayers): the bundle's tests will need VKRT_VALIDATION=if-present" >&2
fi

# Wrappers: the bundle's lib/ first (its Vulkan loader too), the bundle's validation layer added to
# the loader's search, and the NVIDIA container driver's ICD manifest, which lives outside the
# loader's default folders, added where it exists (a user's VK_DRIVER_FILES / VK_ICD_FILENAMES win).
for f in "$out"/bin/*; do
  name=$(basename "$f")
  case "$name" in *.so) continue ;; esac
  cat > "$out/$name" <<WRAP
#!/bin/sh
here=\$(dirname "\$(readlink -f "\$0")")
export LD_LIBRARY_PATH="\$here/lib\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}"
export VK_ADD_LAYER_PATH="\$here/share/vulkan/explicit_layer.d\${VK_ADD_LAYER_PATH:+:\$VK_ADD_LAYER_PATH}"
if [ -z "\${VK_DRIVER_FILES:-}\${VK_ICD_FILENAMES:-}" ]; then
  for icd in /usr/local/nvidia/share/vulkan/icd.d/*.json; do
    [ -f "\$icd" ] && export VK_ADD_DRIVER_FILES="\${VK_ADD_DRIVER_FILES:+\$VK_ADD_DRIVER_FILES:}\$icd"
  done
fi
exec "\$here/bin/$name" "\$@"
WRAP
  chmod +x "$out/$name"
done
echo "bundle: $out: $(ls "$out/bin" | wc -l) binaries and modules, $(ls "$out/lib" | wc -l) libraries, $(du -sh "$out" | cut -f1)"
if [ "$archive" = 1 ]; then
  tar -C "$(dirname "$out")" -czf "$out.tar.gz" "$(basename "$out")"
  echo "bundle: $out.tar.gz $(du -h "$out.tar.gz" | cut -f1)"
fi
