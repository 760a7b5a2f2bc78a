# Shared by scripts/asan, scripts/tsan and scripts/fuzz (sourced, not run).

# configure_clang_sanitizer_build BUILD SANITIZER: configures BUILD as a clang
# unity build with FACADESLAM_SANITIZE=SANITIZER (address | thread).
# clang, not GCC: it compiles the instrumented code in 0.55-0.75x GCC's time
# (docs/benchmarks.md, "CI"), and only clang has libFuzzer. -O1 -g1: a third
# faster to compile than RelWithDebInfo's -O2 -g, and the sanitizers still get
# line numbers for their reports; the test programs' own code is built at -O0
# under the sanitizers (cmake/FacadeslamTargets.cmake).
configure_clang_sanitizer_build() {
  local build=$1 sanitizer=$2
  # A build folder configured with another compiler (GCC, before clang was
  # chosen here) cannot be switched in place: CMake would drop the options.
  if [ -f "$build/CMakeCache.txt" ] && ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++' "$build/CMakeCache.txt"; then
    rm -rf "$build"
  fi
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16 \
    -DFACADESLAM_SANITIZE="$sanitizer" -DFACADESLAM_BUILD_BENCH=OFF >/dev/null
}

# run_in_parallel FUNCTION RUN...: calls FUNCTION with each RUN as its one
# argument, as many at once as there are cores, starting the next as soon as
# any ends; fails if any failed.
run_in_parallel() {
  local function=$1 status=0 running=0 run
  shift
  for run in "$@"; do
    "$function" "$run" &
    running=$((running + 1))
    if [ "$running" -ge "$(nproc)" ]; then
      wait -n || status=1
      running=$((running - 1))
    fi
  done
  while [ "$running" -gt 0 ]; do
    wait -n || status=1
    running=$((running - 1))
  done
  return $status
}
