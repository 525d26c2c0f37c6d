#!/usr/bin/env bash
# Builds and runs the cagd C ABI fuzz harness (fuzz/capi/README.md).
#   bash fuzz/capi/run.sh short      # 100 000 calls, fixed seed (what CI runs), ~30 s
#   bash fuzz/capi/run.sh valgrind   # 4 000 calls under valgrind (what CI runs)
#   bash fuzz/capi/run.sh long       # 10^7 calls (CAGD_FUZZ_CALLS, CAGD_FUZZ_SEED override)
#   bash fuzz/capi/run.sh libfuzzer [libFuzzer flags]   # coverage-guided, stable rustc
# Extra environment: CAGD_FUZZ_KEEP_GOING=1 (count violations instead of aborting at the
# first), CAGD_FUZZ_SECONDS (wall budget), CAGD_FUZZ_ONLY=<cagd_function> (one function).
set -euo pipefail
cd "$(dirname "$0")/../.."
mode=${1:-short}
shift || true
out=target/capi-fuzz
mkdir -p "$out"
CC=${CC:-cc}
srcs=(fuzz/capi/harness.c fuzz/capi/ops.c)

native_libs() { # the flags a C program needs next to libcagd_capi.a
    local f=$1
    sed -e 's/^.*native-static-libs: //' "$f" | tr '\n' ' '
}

release_lib() {
    local libs_file="$PWD/target/release/cagd_capi.native-static-libs"
    cargo rustc --release -p cagd-capi --lib -- --print "native-static-libs=$libs_file" >&2
    if [ ! -s "$libs_file" ]; then
        touch crates/cagd-capi/src/lib.rs
        cargo rustc --release -p cagd-capi --lib -- --print "native-static-libs=$libs_file" >&2
    fi
    echo "$libs_file"
}

build_random() {
    local libs_file
    libs_file=$(release_lib)
    # shellcheck disable=SC2046
    "$CC" -std=c11 -Wall -Wextra -Wpedantic -Werror -O2 -g -Iinclude "${srcs[@]}" \
        fuzz/capi/main.c target/release/libcagd_capi.a $(native_libs "$libs_file") -lm \
        -o "$out/capi-fuzz"
}

case "$mode" in
short)
    build_random
    "$out/capi-fuzz" --calls "${CAGD_FUZZ_CALLS:-100000}" --seed "${CAGD_FUZZ_SEED:-20261126}" "$@"
    ;;
valgrind)
    build_random
    valgrind --quiet --leak-check=full --show-leak-kinds=definite,indirect \
        --errors-for-leak-kinds=definite,indirect --error-exitcode=1 \
        "$out/capi-fuzz" --calls "${CAGD_FUZZ_CALLS:-4000}" --seed "${CAGD_FUZZ_SEED:-7}" "$@"
    ;;
long)
    build_random
    "$out/capi-fuzz" --calls "${CAGD_FUZZ_CALLS:-10000000}" --seed "${CAGD_FUZZ_SEED:-1}" "$@"
    ;;
libfuzzer)
    # Coverage-guided: the Rust static library is instrumented with SanitizerCoverage on
    # the stable toolchain (the flags cargo-fuzz passes), the C harness by clang's
    # -fsanitize=fuzzer, which also links libFuzzer (Debian: clang, libclang-rt-dev).
    CLANG=${CLANG:-$(command -v clang-19 || command -v clang)}
    RUSTFLAGS="-C passes=sancov-module -C llvm-args=-sanitizer-coverage-level=4 \
-C llvm-args=-sanitizer-coverage-inline-8bit-counters -C llvm-args=-sanitizer-coverage-pc-table \
-C llvm-args=-sanitizer-coverage-trace-compares -C debug-assertions -C overflow-checks" \
        cargo build --release -p cagd-capi --target x86_64-unknown-linux-gnu \
        --target-dir target/capi-fuzz/sancov >&2
    "$CLANG" -std=c11 -O1 -g -fsanitize=fuzzer -Iinclude "${srcs[@]}" fuzz/capi/libfuzzer.c \
        target/capi-fuzz/sancov/x86_64-unknown-linux-gnu/release/libcagd_capi.a -lm -ldl -lpthread -lgcc_s \
        -o "$out/capi-libfuzzer"
    mkdir -p "$out/corpus"
    "$out/capi-libfuzzer" "$out/corpus" -max_len=4096 -timeout=20 "$@"
    ;;
*)
    echo "usage: $0 short|valgrind|long|libfuzzer [args]" >&2
    exit 2
    ;;
esac
