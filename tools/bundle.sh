#!/usr/bin/env bash
# A relocatable bundle of vkrt for a machine that cannot build it (a GPU machine): the binaries,
# the run-time modules, the libraries they need that are not the C runtime or the Vulkan loader,
# the GLSL sources (for --shader-dir), and wrappers that point the dynamic loader at the bundle.
#
#   tools/bundle.sh OUT [BUILD] [--tests] [--no-oiio]
#     OUT       the bundle's folder (replaced)
#     BUILD     the build folder (default build/)
#     --tests   also the agreement and Vulkan test binaries (run them with VKRT_SHARED=<scenes>)
#     --no-oiio leave OpenImageIO out (PNG/PPM output only, no textures, no EXR): here 48 MB with
#               --tests instead of ~400 MB (OpenImageIO brings ~250 libraries), under the 64 MiB a
#               device call may carry
#
# Run a bundled binary through its wrapper: OUT/vkrt scene.xml ..., OUT/vkrt-bench gpu rays ...
# The machine needs glibc as new as this one's and a Vulkan loader (libvulkan.so.1) with its
# driver: the loader is left out on purpose, since it must find that machine's ICDs.
set -euo pipefail
out=${1:?usage: tools/bundle.sh OUT [BUILD] [--tests] [--no-oiio]}
shift
build=build
tests=0
oiio=1
for arg in "$@"; do
  case "$arg" in
    --tests) tests=1 ;;
    --no-oiio) oiio=0 ;;
    *) build=$arg ;;
  esac
done
root=$(cd "$(dirname "$0")/.." && pwd)
[ -x "$build/vkrt" ] || { echo "bundle: $build/vkrt not found (build first: ./setup.sh)" >&2; exit 1; }

rm -rf "$out"
mkdir -p "$out/bin" "$out/lib"
binaries=("$build/vkrt" "$build/vkrt-bench")
modules=("$build/libvkrt_mpi.so")
[ "$oiio" = 1 ] && modules+=("$build/libvkrt_oiio.so")
if [ "$tests" = 1 ]; then
  binaries+=("$build/tests/agreement/vkrt_agreement_tests" "$build/tests/vulkan/vkrt_vulkan_tests")
fi
cp "${binaries[@]}" "${modules[@]}" "$out/bin/"
cp -r "$root/shaders" "$out/shaders"

# Every library the binaries and modules resolve to, except the C runtime and the Vulkan loader.
skip='^(linux-vdso|ld-linux|libc\.so|libm\.so|libdl\.so|libpthread\.so|librt\.so|libvulkan\.so)'
for f in "${binaries[@]}" "${modules[@]}"; do
  ldd "$f" | awk '$2 == "=>" && $3 ~ /^\// {print $3}'
done | sort -u | while read -r lib; do
  name=$(basename "$lib")
  [[ "$name" =~ $skip ]] && continue
  cp -L "$lib" "$out/lib/$name"
done

# Wrappers: the bundle's lib/ first, then the machine's (its Vulkan loader and driver).
for f in "$out"/bin/*; do
  name=$(basename "$f")
  case "$name" in *.so) continue ;; esac
  cat > "$out/$name" <<WRAP
#!/bin/sh
here=\$(dirname "\$(readlink -f "\$0")")
LD_LIBRARY_PATH="\$here/lib\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}" exec "\$here/bin/$name" "\$@"
WRAP
  chmod +x "$out/$name"
done
echo "bundle: $out: $(ls "$out/bin" | wc -l) binaries and modules, $(ls "$out/lib" | wc -l) libraries, $(du -sh "$out" | cut -f1)"
