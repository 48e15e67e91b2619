#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs what is missing, builds (Release) and runs every test through ctest;
# then (a) an ASan+UBSan build with assertions on (build-asan/) runs the fast
# tests, and (b) every libFuzzer target (build-fuzz/) runs 20 s on its seed
# corpus. Any failure, sanitizer report or fuzzer crash fails the script. The
# last line is "N passed, N failed" over all three parts.
#
# Time: .ci/run must stay under 20 minutes on 2 cores. Measured parts and the
# estimate for an idle machine are in docs/fuzzing.md ("CI budget"); the
# fuzz smoke run is 9 targets x 20 s, two at a time (about 2 minutes).
# Parts (a) and (b) run only with SEAMLESS_SANITIZERS=1 and SEAMLESS_FUZZ_SMOKE=1:
# they have not yet run end to end within the CI budget (issue 12 stays open
# until they do); the script says in its last lines which parts it left out.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
jobs=$(nproc)
passed=0
failed=0
# ccache, when there, makes the second run of the sanitizer and fuzz builds cheap.
launcher=()
if command -v ccache >/dev/null 2>&1; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
stamp() { date +%s; }
report_time() { echo "test.sh: $1 took $(($(stamp) - $2)) s" >&2; }

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
t0=$(stamp)
"$here/scripts/setup.sh" "$here/build"
cd "$here/build"
ctest --output-on-failure -j"$jobs" --timeout 600 2>&1 | tee ctest.log || true
count_ctest ctest.log
report_time "Release build and ctest" "$t0"

# --- (a) ASan + UBSan, assertions enabled ----------------------------------
# The library and the fast test executables: intervals, models (readers), meshes
# (IO and check) and the CLI; together 35 s in the Release run. The spline
# enclosure sweeps (300 s in Release) and the render and tessellation sweeps
# are left to the Release run: under ASan they would take most of an hour.
asan_targets=(seamless seamless_cli test_interval test_model test_mesh test_tools)
asan_tests='^(interval|model|mesh|tools):'
if [ "${SEAMLESS_SANITIZERS:-0}" = 1 ]; then
  t0=$(stamp)
  san="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
  cmake -S "$here" -B "$here/build-asan" -DCMAKE_BUILD_TYPE=Sanitize \
    -DCMAKE_CXX_FLAGS_SANITIZE="-O1 -g $san" \
    -DCMAKE_EXE_LINKER_FLAGS_SANITIZE="$san" -DCMAKE_SHARED_LINKER_FLAGS_SANITIZE="$san" \
    -DSEAMLESS_BUILD_BENCH=OFF "${launcher[@]}" >/dev/null
  cmake --build "$here/build-asan" -j"$jobs" --target "${asan_targets[@]}"
  cd "$here/build-asan"
  # detect_leaks: LeakSanitizer too; halt_on_error: the first report fails the test.
  ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:abort_on_error=1 \
    UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
    ctest --output-on-failure -j"$jobs" --timeout 600 -R "$asan_tests" 2>&1 | tee ctest.log || true
  count_ctest ctest.log
  report_time "sanitizer build and tests" "$t0"
else
  echo "test.sh: sanitizer build left out (SEAMLESS_SANITIZERS=1 runs it)"
fi

# --- (b) fuzz smoke run ----------------------------------------------------
if [ "${SEAMLESS_FUZZ_SMOKE:-0}" = 1 ]; then
  t0=$(stamp)
  cmake -S "$here" -B "$here/build-fuzz" -DCMAKE_CXX_COMPILER=clang++ -DSEAMLESS_FUZZ=ON \
    -DSEAMLESS_BUILD_TESTS=OFF -DSEAMLESS_BUILD_TOOLS=OFF -DSEAMLESS_BUILD_BENCH=OFF "${launcher[@]}" >/dev/null
  cmake --build "$here/build-fuzz" -j"$jobs" --target fuzz
  cd "$here/build-fuzz/fuzz"
  # Each target: 20 s on a scratch copy of its committed corpus (new inputs
  # stay out of the source tree); two at a time on two cores.
  run_fuzz() {
    local r=$1
    rm -rf "work-$r" && mkdir -p "work-$r" "crashes-$r"
    if "./fuzz_$r" -max_total_time=20 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
      -artifact_prefix="crashes-$r/" "work-$r" "$here/tests/fuzz/corpus/$r" >"fuzz_$r.log" 2>&1; then
      echo "fuzz_$r: $(grep -E '^stat::number_of_executed_units' "fuzz_$r.log" | awk '{print $2}') runs, no crash"
      return 0
    fi
    echo "fuzz_$r: FAILED (reproducer in $PWD/crashes-$r/)"
    tail -n 40 "fuzz_$r.log"
    return 1
  }
  readers=(model_json bpt scene off obj ply stl gltf glb)
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
  report_time "fuzz build and smoke run" "$t0"
else
  echo "test.sh: fuzz smoke run left out (SEAMLESS_FUZZ_SMOKE=1 runs it)"
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
