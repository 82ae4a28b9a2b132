#!/usr/bin/env bash
# A timed libFuzzer campaign over the targets of tests/fuzz (docs/reliability.md
# "Fuzzing"): installs clang, builds the targets with ASan + UBSan in build-fuzz/,
# runs each for --seconds from its seed corpus and prints what it did.
#   scripts/fuzz-campaign.sh [--seconds N] [--jobs J] [--no-install] [--no-build] [target...]
# Default: every target, 60 s each, the PCL-free ones first. New corpus units go to
# out/fuzz/<target>/corpus (the committed seeds stay as they are), crashers,
# timeouts and OOMs to out/fuzz/<target>/, the fuzzer's log to out/fuzz/<target>/log.
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=60
jobs=2
install=1
build=1
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) seconds="$2"; shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    --no-install) install=0; shift ;;
    --no-build) build=0; install=0; shift ;;  # run the targets build-fuzz/ has
    -h|--help) sed -n 2,9p "$0"; exit 0 ;;
    -*) echo "fuzz-campaign: unknown option $1" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done
if [ ${#targets[@]} -eq 0 ]; then
  targets=(pcd_reader pcd_header robot_config scene_file snapshot pcd_decoder packed_decoder
           import service)
fi

# The largest input worth trying per target: a few times its largest seed.
max_len_of() {
  case "$1" in
    pcd_header|robot_config) echo 4096 ;;
    snapshot|packed_decoder|import) echo 8192 ;;
    service) echo 32768 ;;
    *) echo 16384 ;;
  esac
}

if [ "$install" -eq 1 ]; then ./scripts/install-deps.sh clang; fi

if [ "$build" -eq 1 ]; then
  # -O1 and line tables only, as OSS-Fuzz builds: the sanitized Eigen and PCL code
  # compiles in a fraction of -O2 -g's time, and stacks still name file:line.
  sanitizers="-O1 -gline-tables-only -fno-omit-frame-pointer"
  sanitizers+=" -fsanitize=fuzzer-no-link,address,undefined"
  nice -n 5 cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=Fuzz \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_C_FLAGS="$sanitizers" -DCMAKE_CXX_FLAGS="$sanitizers" \
    -DRELMAP_FUZZ=ON -DRELMAP_BUILD_TESTS=OFF -DRELMAP_BUILD_BENCHMARKS=OFF >/dev/null
  nice -n 5 cmake --build build-fuzz -j "$jobs" --target "${targets[@]/%/_fuzz}"
fi

# Leaks are reported per input; UB stops the run like a crash; PCL's OpenMP on one thread.
# alloc_dealloc_mismatch=0: Debian's PCL is built as C++14, where Eigen's
# EIGEN_MAKE_ALIGNED_OPERATOR_NEW gives pcl::PointCloud a class operator new (malloc);
# in relmap's C++20 the macro is empty (aligned new is the language's), so a cloud PCL
# allocates is deleted with the global operator delete. On x86-64 glibc Eigen's
# aligned malloc is plain malloc and the pair is harmless; ASan reports it on every
# supervoxel extraction (docs/reliability.md).
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:alloc_dealloc_mismatch=0}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}"
export OMP_NUM_THREADS=1

rows=()
for target in "${targets[@]}"; do
  out="out/fuzz/$target"
  mkdir -p "$out/corpus"
  if [ ! -d "tests/fuzz/corpus/$target" ]; then
    echo "fuzz-campaign: no seed corpus tests/fuzz/corpus/$target" >&2
    exit 1
  fi
  echo "fuzz-campaign: $target for ${seconds}s" >&2
  status=0
  nice -n 5 "build-fuzz/tests/fuzz/${target}_fuzz" -max_total_time="$seconds" \
    -max_len="$(max_len_of "$target")" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$out/" "$out/corpus" "tests/fuzz/corpus/$target" >"$out/log" 2>&1 ||
    status=$?
  executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$out/log" | tail -1)
  new_units=$(sed -n 's/^stat::new_units_added: *//p' "$out/log" | tail -1)
  crashes=$(find "$out" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'leak-*' \
              -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l)
  if [ "$status" -ne 0 ] && [ "$crashes" -eq 0 ]; then crashes="exit $status"; fi
  rows+=("$(printf '%-16s %8s %14s %10s %8s' "$target" "$seconds" "${executions:-?}" \
              "${new_units:-?}" "$crashes")")
done

printf '%-16s %8s %14s %10s %8s\n' target seconds executions new_units crashes
printf '%s\n' "${rows[@]}"
