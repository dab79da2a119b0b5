#!/usr/bin/env bash
# Build the library, CLI and tests, run the test suite with CTest, then compile the benchmarks
# (they run in scripts/bench.sh, not here: timing goals live in bench/, never in tests).
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
bash scripts/build.sh
# The sweep tests (issue 26) run in this ctest: `mpirun -np 2` among them when SOMA_MPI is on (Open MPI from
# bootstrap.sh; as root mpirun needs --allow-run-as-root, which tests/sweep/rows.sh passes). Cost measured
# 2026-12-02 on this 2-core machine at load average ~13: test_sweep 6 s, the row comparisons 4 s, the
# resume after SIGKILL 7 s, the 8 bad sweep files 0.3 s each: about 20 s of wall, 6 s of CPU.
# The Python module (README "Python"; built by `all`) installed into Debian's python3 before its tests.
if grep -q '^SOMA_PYTHON:BOOL=ON' build/release/CMakeCache.txt; then cmake --install build/release --component python; fi
ctest --preset release "$@"
tests_done=$(date +%s)
echo "soma tests: built and ran in $(( tests_done - start )) s"
cmake --build --preset release --target soma_benchmarks
echo "soma benchmarks: compiled in $(( $(date +%s) - tests_done )) s"

# Sanitizers and fuzzing (issue 24, tests/fuzz/README.md): the `fuzz` build (build/fuzz: clang 14,
# ASan + UBSan, a report aborts; -O1 -gline-tables-only, the other four scalars at -O0, the general-6R,
# closed-form IK and dynamics instantiations for double only; spatial inertia, which the scene
# reader's rigid bodies build in every scalar, in all five) of the readers' libraries, the seven
# libFuzzer harnesses and the sanitized unit tests (SOMA_SANITIZE_TESTS, CTest regex areas); CTest replays every
# harness's corpus and runs those tests (0 reports), then scripts/fuzz.sh fuzzes each harness for
# SOMA_FUZZ_SECONDS (default 20, two at a time). SOMA_SANITIZE=0 skips the phase (e.g. locally).
# Cost measured (2026-12-02, this 2-core machine shared with three other builds, CCACHE_DISABLE=1, -j2,
# `time`): the cold fuzz build of the 7 harnesses and test_io is 1,146 s of CPU (1,082 user + 64 sys;
# 86 steps), so about 9.5 min of wall on a clean 2-core machine; the corpus replays and the 58
# sanitized io tests 19 s wall (6 s CPU), the fuzzing 7 x 20 s / 2 = 70 s: about 11 min in all, inside
# the ~12 min budget. Without SOMA_INSTANTIATE_DOUBLE_ONLY the build needed 96 objects instead of 69
# (the dynamics ladder alone is 28 TUs).
# The sanitized tests (SOMA_SANITIZE_TESTS, CTest areas) are the readers' (io), algebra's, the line
# geometry's, the serial robots' (geometry/serial) and the CLI contract tests (cli: every `soma`
# command's exit code, message and output, on a sanitized `soma` built without the studies,
# SOMA_CLI_STUDIES=OFF). The preset instantiates for double only the concepts that neither these tests
# nor `soma` call in another scalar (SOMA_INSTANTIATE_DOUBLE_ONLY in CMakePresets.json: the tree and
# constrained dynamics, the dynamics models, statics, the Riemannian controllers and metrics, planar
# kinematics, the Study-quadric ladder); the link of `soma` and the tests is the proof that nothing
# else is needed (with fewer, it names the missing symbol: the scene outputs call serial and Clifford
# dynamics and screw-system identification in every scalar, the cusp search escalates to float128 and
# mpfr). Asking for another area (e.g. geometry/dynamics) configures the whole ladder.
# SOMA_SANITIZE_EXCLUDE leaves out, by CTest regex:
# - the five self-motion tests (131-412 s each at -O0 under ASan, mpfr the longest);
# - the Stewart CLI tests that solve an ordinary platform (each builds the 128-path start system at
#   -O1 under ASan: ~6 s of CPU, ~100 s for the 17; measured 2026-12-04, all pass sanitized); the
#   Stewart refusals (bad files, unknown method, --complex without the homotopy, collinear joints,
#   the platform scaled by 1e200) run, and the platform reader is fuzzed;
# - the two mpirun tests (Open MPI's dlopen'd components leak at exit, unloaded before LeakSanitizer
#   can name them).
# Leaks of Mesa's off-screen renderer are suppressed (tests/fuzz/lsan.supp, set by the fuzz test preset).
# Cost measured 2026-12-04 on this 2-core machine (loaded by four other builds: CPU times): the 191 CLI
# contract tests 99 s of CPU (0 reports), the 27 Stewart CLI tests 166 s of CPU (0 reports). This
# phase cold on a clean clone (3cf99a7, CCACHE_DISABLE=1, /usr/bin/time): 194 build steps, the 808
# corpus replays and sanitized tests (0 reports) and 20 s of fuzzing per harness (no finding): 2,658 s
# of CPU (2,446 user + 212 sys) against 1,866 s for the phase without the CLI tests, so about 22 min
# of wall on a quiet 2-core machine (the wall measured, 52 min, was shared with three other builds).
# Before 2026-12-04 the CLI tests needed the whole ladder (2,230 s of CPU cold, projected ~50 min
# for CI), so they ran on request only.
if [ "${SOMA_SANITIZE:-1}" != 0 ]; then
  fuzz_start=$(date +%s)
  default_tests="io algebra geometry/lines geometry/serial cli"
  sanitize_tests=${SOMA_SANITIZE_TESTS:-$default_tests}
  stewart_solves='cli: ?stewart( --png|: (general|--json|float128|Dietmaier|6-3|6-4|impossible|at the boundary|--complex (--json|text)|a general|a double root|standard planar))|stewart_irregular|stewart_leg'
  sanitize_exclude=${SOMA_SANITIZE_EXCLUDE:-self-motion answers a continuum|mpirun|$stewart_solves}
  targets=(soma_fuzz)
  for area in $sanitize_tests; do targets+=("test_${area//\//_}"); done
  fuzz_args=()
  for area in $sanitize_tests; do
    case " $default_tests " in *" $area "*) ;; *) fuzz_args=(-DSOMA_INSTANTIATE_DOUBLE_ONLY=) ;; esac
  done
  cmake --preset fuzz "${fuzz_args[@]}" >/dev/null
  cmake --build --preset fuzz --target "${targets[@]}"
  fuzz_built=$(date +%s)
  ctest --preset fuzz -R "^(fuzz|${sanitize_tests// /|}):" -E "${sanitize_exclude}"
  fuzz_tested=$(date +%s)
  bash scripts/fuzz.sh "${SOMA_FUZZ_SECONDS:-20}"
  echo "soma sanitizers and fuzzing: built in $(( fuzz_built - fuzz_start )) s, corpus and sanitized tests" \
       "in $(( fuzz_tested - fuzz_built )) s, fuzzed in $(( $(date +%s) - fuzz_tested )) s"
fi
