#!/usr/bin/env bash
# Fuzzing the scene loaders (issue 22; tests/fuzz/README.md says what is fuzzed and how to go longer).
#   tools/fuzz.sh build DIR                 configure and build the fuzzing build (clang, libFuzzer, ASan, UBSan)
#   tools/fuzz.sh test DIR                  the scene loaders' unit tests from that build, under the sanitizers
#   tools/fuzz.sh run DIR TARGET SECONDS    fuzz TARGET (xml_scene json_scene obj texture bvh merge_part) from the ../shared seeds
# Findings (crashing inputs) are written to DIR/artifacts/; the grown corpus stays in DIR/corpus/TARGET.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
shared=${VKRT_SHARED:-$repo/../shared}
export LSAN_OPTIONS=suppressions=$repo/tests/fuzz/lsan.supp:print_suppressions=0  # OpenImageIO's own leak
command=${1:?usage: fuzz.sh build|test|run DIR ...}
dir=${2:?usage: fuzz.sh build|test|run DIR ...}

# Seeds: the course's own files of each kind, up to 256 KiB each (a 5 MB mesh would slow every run
# of the target to a crawl without finding more than its first 64 KiB do).
seed() {
    local target=$1 out=$dir/seeds/$1
    [ -d "$out" ] && return 0
    local partial=$out.partial
    rm -rf "$partial"
    mkdir -p "$partial"
    local pattern
    case $target in
        xml_scene) pattern='*.xml' ;;
        json_scene) pattern='*.json' ;;
        obj) pattern='*.obj' ;;
        texture) pattern='*.png' ;;
        bvh) mkdir -p "$out"; rm -rf "$partial"; return 0 ;;  # raw floats: libFuzzer starts from nothing
        merge_part) cp -r "$repo/tests/fuzz/seeds/merge_part" "$out"; rm -rf "$partial"; return 0 ;;  # two parts vkrt wrote
    esac
    if [ ! -d "$shared/scenes" ]; then
        if [ "${VKRT_REQUIRE_SHARED:-}" = 1 ]; then echo "fuzz.sh: missing $shared/scenes (the seed corpus)" >&2; exit 1; fi
        echo "fuzz.sh: no $shared/scenes: fuzzing $target from an empty corpus" >&2
        mv "$partial" "$out"
        return 0
    fi
    # Files of one name in several folders (two al.obj) are all kept: numbered copies.
    find "$shared/scenes" -name "$pattern" -size -256k -exec cp --backup=numbered -t "$partial" {} +
    mv "$partial" "$out"
}

case $command in
    build)
        cmake -S "$repo" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVKRT_FUZZ=ON \
            -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DVKRT_SHARED_DIR="$shared" > "$dir.configure.log" 2>&1 ||
            { cat "$dir.configure.log"; exit 1; }
        cmake --build "$dir" -j"$(nproc)"
        ;;
    test)
        # One process for all of them (each ctest entry would start ASan and OpenImageIO again).
        "$dir/tests/scene/vkrt_scene_tests"
        ;;
    run)
        target=${3:?target}
        seconds=${4:?seconds}
        seed "$target"
        mkdir -p "$dir/corpus/$target" "$dir/artifacts"
        # -timeout: an input that takes 10 s is a finding (a hang); -rss_limit_mb: so is one that
        # needs more than 4 GiB. The timeout is wall-clock time: a long run beside a build (nice'd)
        # can starve a 13 ms input past 10 s, so such runs raise it with VKRT_FUZZ_TIMEOUT=60.
        "$dir/tests/fuzz/fuzz_$target" -max_total_time="$seconds" -max_len=65536 -timeout="${VKRT_FUZZ_TIMEOUT:-10}" -rss_limit_mb=4096 \
            -print_final_stats=1 -artifact_prefix="$dir/artifacts/$target-" "$dir/corpus/$target" "$dir/seeds/$target"
        ;;
    *)
        echo "usage: fuzz.sh build|test|run DIR ..." >&2
        exit 2
        ;;
esac
