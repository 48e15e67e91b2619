#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs what is missing, builds (Release) and runs every test through ctest
# (the Python module's pytest suite too: /usr/bin/python3 -m pytest tests/python);
# then one clang build with ASan+UBSan and assertions on (build-san/) serves
# (a) every stage's tests but the [heavy] ones and (b) every libFuzzer target,
# each 10 s on its seed corpus. Any failure, sanitizer report
# or fuzzer crash fails the script. The last line is "N passed, N failed" over all parts.
#
# Time: .ci/run must stay under 20 minutes on 2 cores. Each part prints
# "test.sh: <part> took N s (CPU M s; load ...)"; the measured parts and the
# estimate for an idle machine are in docs/fuzzing.md ("CI budget"). The fuzz
# smoke run is 11 targets x 10 s, two at a time (about 65 s).
set -euo pipefail
# scripts/setup.sh installs every tool the tests need, so a test that finds
# one missing fails here instead of warning (the glTF validator test reads CI).
export CI=${CI:-true}
here=$(cd "$(dirname "$0")/.." && pwd)
jobs=$(nproc)
passed=0
failed=0
# ccache, when there, makes the second run of the sanitizer and fuzz builds cheap.
launcher=()
if command -v ccache >/dev/null 2>&1; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
stamp() { date +%s; }
# CPU seconds (user + system) of every finished child process so far, from
# bash's `times` (run in this shell, not a subshell, so it sees the children):
# with the wall time it tells how much of a part was waiting for a loaded
# machine. On an idle 2-core machine a part takes about its CPU seconds / 2
# when it keeps both cores busy, up to its CPU seconds when it does not.
times_file=$(mktemp)
trap 'rm -f "$times_file"' EXIT
cpu_seconds() {
  times >"$times_file"
  cpu=$(tail -n 1 "$times_file" | awk '{
    n = 0
    for (i = 1; i <= 2; i++) { split($i, a, /[ms]/); n += a[1] * 60 + a[2] }
    printf "%d", n }')
}
start_part() {
  t0=$(stamp)
  cpu_seconds
  c0=$cpu
}
report_time() {
  cpu_seconds
  echo "test.sh: $1 took $(($(stamp) - t0)) s (CPU $((cpu - c0)) s; $(uptime | sed 's/.*load/load/'))" >&2
}

# ctest's summary "N% tests passed, F tests failed out of T" -> passed/failed.
count_ctest() {
  local line t f
  line=$(grep -E 'tests passed, [0-9]+ tests? failed out of [0-9]+' "$1" | tail -n 1 || true)
  if [ -z "$line" ]; then
    failed=$((failed + 1))
    return
  fi
  f=$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\1/' <<<"$line")
  t=$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\2/' <<<"$line")
  passed=$((passed + t - f))
  failed=$((failed + f))
}

# --- Release build and the whole suite -------------------------------------
release_part() {
  start_part
  "$here/scripts/setup.sh" "$here/build"
  report_time "set-up and Release build"
  start_part
  cd "$here/build"
  ctest --output-on-failure -j"$jobs" --timeout 600 2>&1 | tee ctest.log || true
  count_ctest ctest.log
  report_time "Release ctest"
}

# --- (a)+(b) one clang build with ASan + UBSan, assertions enabled ------------
# The library is compiled once with -fsanitize=address,undefined (plus
# float-cast-overflow, -fno-sanitize-recover=all, and fuzzer-no-link for the
# fuzzer's coverage); the chosen Catch2 tests link it as they are, the fuzz_*
# harnesses link it with -fsanitize=fuzzer (tests/fuzz/CMakeLists.txt,
# SEAMLESS_FUZZ_LINK_LIBRARY). No NDEBUG: every SEAMLESS_DCHECK is live. Compile time
# is most of this part: line tables only (stack traces keep file:line) and
# the CLI and the tests at -O0 (SEAMLESS_CLI_TEST_COMPILE_OPTIONS) halve it.
# (a) runs the tests of every stage (base, interval, spline, model,
# tessellate, mesh, render) and the CLI, so that every SEAMLESS_DCHECK runs
# under its tests, but for the test cases tagged [heavy] (fine
# tessellations and sweeps: ASan makes them 50-100 times slower; they run in
# the Release part) and [native-allocator] (they measure glibc's malloc,
# which ASan replaces): SEAMLESS_TEST_SPEC, tests/CMakeLists.txt.
sanitize_part() {
  start_part
  # clang-14 is what scripts/setup.sh installs; the clang++ link comes from another package.
  clangxx=$(command -v clang++-14 || command -v clang++)
  san="-fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=all -fno-omit-frame-pointer"
  cmake -S "$here" -B "$here/build-san" -DCMAKE_CXX_COMPILER="$clangxx" -DCMAKE_BUILD_TYPE=Sanitize \
    -DCMAKE_CXX_FLAGS="-O1 -gline-tables-only $san -fsanitize=fuzzer-no-link" -DSEAMLESS_BUILD_BENCH=OFF \
    -DSEAMLESS_CLI_TEST_COMPILE_OPTIONS=-O0 -DSEAMLESS_FUZZ=ON -DSEAMLESS_FUZZ_LINK_LIBRARY=ON \
    "-DSEAMLESS_TEST_SPEC=~[heavy]~[native-allocator]" "${launcher[@]}" >/dev/null
  san_targets=(seamless seamless_cli test_base test_interval test_spline test_model test_tessellate
               test_mesh test_render test_tools fuzz)
  san_tests='^(base|interval|spline|model|tessellate|mesh|render|tools):'
  if cmake --build "$here/build-san" -j"$jobs" --target "${san_targets[@]}" >"$here/build-san/build.log" 2>&1; then
    report_time "sanitizer build"
    start_part
    cd "$here/build-san"
    # detect_leaks: LeakSanitizer too (OpenCASCADE's once-per-process tables
    # suppressed: tests/lsan.supp); halt_on_error: the first report fails the test.
    ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:abort_on_error=1 \
      LSAN_OPTIONS="suppressions=$here/tests/lsan.supp:print_suppressions=0" \
      UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
      ctest --output-on-failure -j"$jobs" --timeout 600 -R "$san_tests" 2>&1 | tee ctest.log || true
    count_ctest ctest.log
    report_time "sanitizer tests"

    # (b) fuzz smoke run: each target SEAMLESS_FUZZ_SECONDS (10) on a scratch copy of its
    # committed corpus (new inputs stay out of the source tree), two at a time.
    start_part
    fuzz_seconds=${SEAMLESS_FUZZ_SECONDS:-10}
    cd "$here/build-san/fuzz"
    run_fuzz() {
      local r=$1
      rm -rf "work-$r" && mkdir -p "work-$r" "crashes-$r"
      if "./fuzz_$r" -max_total_time="$fuzz_seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="crashes-$r/" "work-$r" "$here/tests/fuzz/corpus/$r" >"fuzz_$r.log" 2>&1; then
        echo "fuzz_$r: $(grep -E '^stat::number_of_executed_units' "fuzz_$r.log" | awk '{print $2}') runs, no crash"
        return 0
      fi
      echo "fuzz_$r: FAILED (reproducer in $PWD/crashes-$r/)"
      tail -n 40 "fuzz_$r.log"
      return 1
    }
    # fuzz_step_iges reads through the reader's process (docs/fuzzing.md,
    # "STEP and IGES"): OpenCASCADE's crashes and its slow paths (past the
    # harness's 5-s reader time limit) end there as clean results.
    readers=(model_json model_exchange bpt scene off obj ply stl gltf glb step_iges)
    for ((i = 0; i < ${#readers[@]}; i += 2)); do
      pids=()
      for r in "${readers[@]:i:2}"; do
        run_fuzz "$r" >"result-$r" 2>&1 &
        pids+=($!)
      done
      for k in "${!pids[@]}"; do
        r=${readers[i + k]}
        if wait "${pids[k]}"; then passed=$((passed + 1)); else failed=$((failed + 1)); fi
        cat "result-$r"
      done
    done
    report_time "fuzz smoke run"
  else
    tail -n 40 "$here/build-san/build.log"
    echo "test.sh: sanitizer build FAILED (log: build-san/build.log)"
    failed=$((failed + 1))
  fi
}

# SEAMLESS_TEST_PARTS chooses the parts: "release sanitize" (the default, what
# CI runs), or one alone ("release", or "sanitize" after scripts/setup.sh has
# run). Cold on an idle 2-core machine the two take the time docs/fuzzing.md
# records ("CI budget"), within the 20-minute budget.
for part in ${SEAMLESS_TEST_PARTS:-release sanitize}; do
  "${part}_part"
done

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
