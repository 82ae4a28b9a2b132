#!/usr/bin/env bash
# The test suite built with a sanitizer and run, in a build folder of its own:
#   scripts/sanitize.sh address [ctest arguments]  # ASan + UBSan, build-asan/, every test
#   scripts/sanitize.sh thread [ctest arguments]   # TSan, build-tsan/, the concurrent tests
# A report fails the test that caused it (the sanitizers abort the process), so the
# summary ctest prints is the answer; reports are in the failing test's output.
# docs/reliability.md gives how long each takes and what they found.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-address}
shift || true

targets=()
extra_packages=(ccache)  # the compiler launcher below
link_flags=""
case "$mode" in
  address)
    build=build-asan
    # -fno-sanitize-recover: an undefined-behaviour report ends the process like an
    # ASan one, so the test fails instead of printing and passing.
    flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
    # Two ways our Eigen differs from the one Debian's PCL (built without ASan, as C++14)
    # was compiled with, each making a buffer allocated on one side and freed on the
    # other look like a bad free (docs/reliability.md, "Sanitizers"):
    # - seeing ASan (__SANITIZE_ADDRESS__), Eigen stops trusting malloc's 16-byte
    #   alignment and allocates behind a header of its own ("free on address which was
    #   not malloc()-ed"); glibc's and ASan's malloc both align to 16 on x86-64;
    # - in C++17 and later Eigen leaves aligned new to the language and drops the class
    #   operator new/delete that PCL's C++14 build gives its clouds (malloc there,
    #   global delete here: "alloc-dealloc-mismatch").
    flags="$flags -DEIGEN_MALLOC_ALREADY_ALIGNED=1 -DEIGEN_HAS_CXX17_OVERALIGN=0"
    # Style checks read sources, not binaries: nothing for a sanitizer to see. The memory
    # soak bounds resident memory, which under ASan is the sanitizer's (a 256 MB quarantine
    # of freed blocks, and shadow memory): it fails there by ~420 MiB, by design.
    selection=(-LE "style|soak")
    export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
    export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
    export LSAN_OPTIONS="suppressions=$PWD/scripts/sanitizers/lsan.supp"
    ;;
  thread)
    build=build-tsan
    flags="-fsanitize=thread -fno-omit-frame-pointer"
    # The tests that run threads against each other: the programs labelled "threads"
    # (sessions and stores, the client against in-process servers, the robot's sources),
    # the PostgreSQL store and every test of the real server process (its gRPC worker
    # threads). Only their programs are built: the unit tests' forty-odd others would
    # double the build for nothing TSan looks at.
    # Not the ROS tests: the ROS bridge is not among the programs built here. Not the
    # memory soak: it bounds the server's resident memory, which under TSan is the
    # sanitizer's (shadow memory, and an allocator that keeps what is freed).
    selection=(-L "threads|service|integration|cluster|postgres" -LE "ros|soak")
    targets=(relmap-server relmap relmap-robot relmap-load session_test session_store_test
      postgres_session_store_test client_test robot_adapter_test service_in_process_test
      server_integration_test client_integration_test cluster_test robot_end_to_end_test
      sim_runner_end_to_end_test)
    # Two of Debian's libraries are replaced, for our programs only, by an RPATH searched
    # before the system's for every library they load (DT_RPATH, not RUNPATH, so that it
    # also serves PCL's and gRPC's own dependencies). Not LD_LIBRARY_PATH: the tests' other
    # processes (Python's grpc, nginx, PostgreSQL) must keep Debian's, and a TSan-built
    # libgrpc cannot be loaded into an uninstrumented Python.
    # - OpenMP: LLVM's libomp, which serves GCC's GOMP calls, with its Archer tool. Archer
    #   tells TSan where a parallel region's fork, barriers and join order memory, which
    #   libgomp (not instrumented, futex barriers) cannot: with libgomp every region
    #   reports the master's stack variables its workers read. ignore_noninstrumented_modules
    #   keeps libomp's own uninstrumented locks out of the reports, as Archer asks.
    # - gRPC and Abseil built with TSan (scripts/sanitizers/build-tsan-grpc.sh), same
    #   sonames: with Debian's, TSan cannot see gRPC's synchronisation and every server and
    #   client test fails on its reports.
    extra_packages+=(libomp-14-dev)
    openmp=$PWD/$build/openmp
    mkdir -p "$openmp"
    ln -sf /usr/lib/llvm-14/lib/libomp.so.5 "$openmp/libgomp.so.1"
    export OMP_TOOL_LIBRARIES=/usr/lib/llvm-14/lib/libarcher.so
    deps=$PWD/build-tsan-deps/lib
    if [ ! -f "$deps/libgrpc++.so.1.51" ]; then
      echo "sanitize thread: no TSan-built gRPC in $deps; the gRPC tests will report" \
        "inside Debian's (run scripts/sanitizers/build-tsan-grpc.sh first)" >&2
    fi
    link_flags="-Wl,--disable-new-dtags,-rpath,$openmp:$deps"
    # Exported before the build: gtest_discover_tests runs each program at build time.
    export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:ignore_noninstrumented_modules=1:suppressions=$PWD/scripts/sanitizers/tsan.supp"
    ;;
  *)
    echo "usage: scripts/sanitize.sh address|thread [ctest arguments]" >&2
    exit 2
    ;;
esac
./scripts/install-deps.sh "${extra_packages[@]}"

start=$(date +%s)
# -g1: line tables for the reports' stacks at a fraction of full debug info's build time.
# ccache: the shared cache (base_dir /work) lets a second worktree's sanitized build, or a
# re-run after a change, reuse the objects of the first instead of a half-hour rebuild.
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache \
  -DCMAKE_CXX_FLAGS="$flags -g1" -DCMAKE_C_FLAGS="$flags -g1" \
  -DCMAKE_EXE_LINKER_FLAGS="$flags $link_flags" -DCMAKE_SHARED_LINKER_FLAGS="$flags"
# Two jobs: a sanitized PCL translation unit takes over 1 GB of compiler memory.
cmake --build "$build" -j 2 ${targets:+--target "${targets[@]}"}
built=$(date +%s)
status=0
ctest --test-dir "$build" --output-on-failure -j 2 "${selection[@]}" "$@" || status=$?
echo "sanitize $mode: build $((built - start)) s, tests $(($(date +%s) - built)) s, ctest exit $status"
exit "$status"
