#!/usr/bin/env bash
# circledist's one entry point for people and CI:
#   bash tools/run.sh demo   install what is missing, build the package, run the demo (its picture:
#                            build/demo_scene.png)
#   bash tools/run.sh check  the quick loop: install what is missing, rebuild and reinstall the package if a
#                            file it is built from changed since its last install, run pytest on every
#                            core except the tests marked slow (pyproject.toml's markers)
#   bash tools/run.sh test   install what is missing, build the package's wheel and install it, run pytest
#                            (every test: on every core, then the ones marked serial alone) and the
#                            wheel's tests in a venv of its own with no compiler on PATH; beside them,
#                            at low priority, the C++ tests (ctest): the suites under the sanitizers,
#                            the headers alone, the LTO build, the find_package consumer, and one
#                            C++ test built against cmeel-eigen's Eigen (the fallback)
#   bash tools/run.sh bench  install what is missing, build, run the benchmarks
#   bash tools/run.sh lint   ruff and clang-format (pinned in pyproject.toml's lint extra) over every
#                            tracked source file; builds nothing
#   bash tools/run.sh docs   install what is missing, build the package, build the documentation and
#                            API reference (docs/, Sphinx) into build/docs/index.html, warnings as errors
#   bash tools/run.sh fuzz [N]  install what is missing, build, run the crash-isolating fuzz's long
#                            mode over N cases (default 10^7; build/reports/fuzz_report.json), its thread
#                            class over N/10^4 scenarios of a Scene shared by threads that add and
#                            query it (build/reports/fuzz_threads_report.json), its argument class over N/100
#                            calls of every entry point with hostile scalar arguments
#                            (build/reports/fuzz_arguments_report.json), then the differential accuracy
#                            test's long mode over N library answers (every solver x precision x
#                            entry point, both orders; 168 per case) (build/reports/differential_report.json);
#                            then computes every recorded 50-digit reference of tests/references/
#                            again (python -m tools.references verify), and rewrites
#                            docs/reports/fuzz.md and differential.md from those records
# Works as root on a fresh Debian machine with Python 3: Debian's Eigen, compiler and venv (and
# for the test task Chromium and its driver) come from apt when missing; the Python packages
# pyproject.toml lists (build requires, dependencies, the task's extras) go into ./.venv (which
# sees the system's site-packages).
set -euo pipefail
cd "$(dirname "$0")/.."
task="${1:-test}"

python=${PYTHON:-python3}
missing=()
[ -f /usr/include/eigen3/Eigen/Core ] || missing+=(libeigen3-dev)
command -v g++ >/dev/null 2>&1 || missing+=(g++)
"$python" -c "import ensurepip" >/dev/null 2>&1 || missing+=(python3-venv)
"$python" -c "import os, sysconfig; assert os.path.exists(os.path.join(sysconfig.get_paths()['include'], 'Python.h'))" \
  >/dev/null 2>&1 || missing+=(python3-dev)
sudo=""
[ "$(id -u)" -eq 0 ] || sudo=sudo
if [ ${#missing[@]} -gt 0 ]; then
  echo "== installing from Debian: ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi
# The browser tests (tests/api/test_view_browser.py: the pages circledist.figure writes, opened
# in headless Chromium) run in the test task only; the other tasks do without the browser. Its
# install is mostly download and unpacking, so it runs in the background while the wheel builds
# (browser_wait, before pytest). Without the recommended packages (printing, notifications,
# power management) but with what a headless page needs: Mesa (WebGL in software) and the fonts.
browser=()
if [ "$task" = test ]; then
  command -v chromium >/dev/null 2>&1 || browser+=(chromium)
  command -v chromedriver >/dev/null 2>&1 || browser+=(chromium-driver)
fi
browser_pid=""
if [ ${#browser[@]} -gt 0 ]; then
  echo "== installing from Debian, in the background: ${browser[*]} (log: build/browser-install.log)"
  mkdir -p build
  ( $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends \
      "${browser[@]}" libgl1-mesa-dri fonts-liberation ) >build/browser-install.log 2>&1 &
  browser_pid=$!
fi
browser_wait() {
  [ -n "$browser_pid" ] || return 0
  wait "$browser_pid" || { echo "!! the browser's install failed:"; cat build/browser-install.log; }
  browser_pid=""
}

if [ ! -x .venv/bin/python ]; then
  echo "== creating .venv"
  "$python" -m venv --system-site-packages .venv
fi
py=.venv/bin/python
export PATH="$PWD/.venv/bin:$PATH"

pip_install() { "$py" -m pip install -q --disable-pip-version-check "$@"; }
# What .venv needs is read from pyproject.toml, the one list: its build requires (the build below
# runs without pip's build isolation, so .venv gets what an isolated build would install,
# cmeel-eigen too: the Eigen CMake takes where the system has none), the package's dependencies
# and the task's extras; then the tools this script runs itself (after --). Prints the ones not
# installed yet, or installed in a version that does not satisfy pyproject.toml.
missing_requirements() {  # missing_requirements EXTRA... -- TOOL... (tools/pyproject.py)
  "$py" tools/pyproject.py missing "$@"
}
case "$task" in
  demo) extras=(plot) ;;
  test|check) extras=(test plot docs dask view browser) ;;  # docs: the stubs' check and the docs build (tests/package/test_stubs.py, test_docs.py); dask: tests/api/test_dask.py on a LocalCluster; view, browser: tests/api/test_view*.py
  docs) extras=(docs) ;;
  fuzz) extras=(test) ;;  # the fuzz and the differential test check against the tests' mpmath references
  bench) extras=(bench) ;;
  lint) extras=(lint) ;;
  *) extras=() ;;
esac
# cmake 3.23 for CMAKE_IGNORE_PREFIX_PATH (the test task's Eigen fallback build).
need_text=$(missing_requirements "${extras[@]}" -- "cmake>=3.23" ninja)
read -ra need <<<"$need_text"
[ ${#need[@]} -eq 0 ] || { echo "== installing from PyPI: ${need[*]}"; pip_install "${need[@]}"; }

# The formatters (versions pinned in pyproject.toml's lint extra; configured by .clang-format and
# pyproject.toml's [tool.ruff]) check every tracked source file; nothing is built.
if [ "$task" = lint ]; then
  status=0
  echo "== ruff check, ruff format --check"
  "$py" -m ruff check --quiet . || status=1
  "$py" -m ruff format --check --quiet . || status=1
  echo "== clang-format --dry-run --Werror"
  git ls-files -z '*.hpp' '*.cpp' '*.h' | xargs -0 .venv/bin/clang-format --dry-run --Werror || status=1
  [ $status -eq 0 ] && echo "lint: clean"
  exit $status
fi

# pytest on every core: the tests not marked serial spread over one worker process per core
# (pytest-xdist), a test file to one worker (--dist loadfile: the references a file caches and its
# module fixtures are computed once, as in one process), then the serial ones in one process with
# nothing beside them (collected from the files that mark any). Exit status 5 (no test selected)
# of a pass is no failure.
pytest_on_every_core() {  # pytest_on_every_core [MARKER EXPRESSION]
  local only="${1:+ and ($1)}" status=0 rc=0 serial_files
  "$py" -m pytest -q -p no:cacheprovider -n "$(nproc)" --dist loadfile -m "not serial$only" || rc=$?
  [ "$rc" -eq 0 ] || [ "$rc" -eq 5 ] || status=$rc
  serial_files=$(grep -rl --include='test_*.py' "pytest.mark.serial" tests | sort || true)
  if [ -n "$serial_files" ]; then
    rc=0
    # shellcheck disable=SC2086
    "$py" -m pytest -q -p no:cacheprovider -m "serial$only" $serial_files || rc=$?
    [ "$rc" -eq 0 ] || [ "$rc" -eq 5 ] || status=$rc
  fi
  return "$status"
}

# The wheel on a machine without a compiler, Eigen or any build requirement: a fresh venv (not
# seeing the system's site-packages) gets the wheel and the test extra only, and runs the tests
# cibuildwheel runs on every wheel (pyproject.toml) with nothing but that venv on PATH.
wheel_alone() {
  local venv=build/wheel-alone wheel test_files
  wheel=$(ls build/wheel/circledist-*.whl)
  rm -rf "$venv"
  "$python" -m venv "$venv" || return 1
  "$venv/bin/python" -m pip install -q --disable-pip-version-check "$wheel[test]" || return 1
  test_files=$("$py" tools/pyproject.py wheel-tests) || return 1
  (cd "$venv" && env -i HOME="$HOME" PATH="$PWD/bin" CIRCLEDIST_WHEEL_ALONE=1 bin/python -m pytest -q \
    -p no:cacheprovider -n "$(nproc)" --dist loadfile -c "$OLDPWD/pyproject.toml" --rootdir "$OLDPWD" \
    $(for t in $test_files tests/package/test_packaging.py; do echo "$OLDPWD/$t"; done))
}

cpp_build() {  # cpp_build [extra cmake definitions]
  cmake -S . -B build/cpp -G Ninja -DCMAKE_BUILD_TYPE=Release -DCIRCLEDIST_BUILD_TESTS=ON "$@" >/dev/null
  cmake --build build/cpp -j 2
}

# Eigen from cmeel-eigen, as a machine without Debian's libeigen3-dev gets it: with the system prefix
# /usr hidden from CMake, configure must take Eigen from the cmeel-eigen wheel on .venv's Python
# (the lookup an isolated pip build makes with its own Python); then the smallest C++ test is built
# and run. Fails unless the Eigen headers the compiler read are cmeel's and none is /usr's.
eigen_fallback() {
  local dir=build/eigen-fallback object=cpp/tests/CMakeFiles/test_line_circle.dir/test_line_circle.cpp.o found deps
  rm -rf "$dir"
  found=$(cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCIRCLEDIST_BUILD_TESTS=ON \
    -DCMAKE_IGNORE_PREFIX_PATH=/usr -DPython_EXECUTABLE="$PWD/$py" | grep "circledist: Eigen") || return 1
  echo "$found"
  [[ "$found" == *cmeel.prefix* ]] || { echo "!! CMake did not take cmeel-eigen's Eigen"; return 1; }
  cmake --build "$dir" --target test_line_circle || return 1
  deps=$(ninja -C "$dir" -t deps "$object") || return 1
  if ! grep -q "cmeel.prefix/include/eigen3/Eigen/Core" <<<"$deps" || grep -q "/usr/include/eigen3" <<<"$deps"; then
    echo "!! the Eigen fallback build did not compile against cmeel-eigen's Eigen:"
    grep -i "eigen" <<<"$deps" | head -5
    return 1
  fi
  echo "Eigen headers of $object: $(grep -c "cmeel.prefix/include/eigen3/" <<<"$deps") from cmeel-eigen, none from /usr"
  "$dir/cpp/tests/test_line_circle"  # the test on its own (cpp/tests/CMakeLists.txt)
}

# The C++ suites, once, built at -Og with address and undefined-behaviour checks and Eigen's and
# the library's assertions on; every suite runs in full. Their answers are those of an optimized
# build: optimization does not change IEEE arithmetic without -ffast-math or FMA contraction,
# which x86-64's baseline has no instructions for. -Og, not -O1: a quarter less to compile for a
# few seconds more of running (the compile is most of the time). Line tables only: -g1 as the Debug
# configuration's flags, which come after CMAKE_CXX_FLAGS (its default, a full -g, was most of the
# compile time); the reports' stacks still name file and line. Not the UB checks that find nothing
# here and cost much of the rest: vptr (no polymorphic type in the library), alignment (Eigen
# asserts its types' alignment in this build; nothing else is cast), null and pointer-overflow (a
# null or wild pointer that is used is AddressSanitizer's report).
cpp_sanitized() {
  echo "== C++ suites under AddressSanitizer and UndefinedBehaviorSanitizer (ctest -L suite)"
  cmake -S . -B build/sanitize -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-g1 -DCIRCLEDIST_BUILD_TESTS=ON \
    -DCMAKE_CXX_FLAGS="-Og -fsanitize=address,undefined -fno-sanitize=vptr,alignment,null,pointer-overflow -fno-sanitize-recover=undefined -fno-omit-frame-pointer" \
    >/dev/null || return 1
  cmake --build build/sanitize -j 2 || return 1
  ctest --test-dir build/sanitize -j 2 -L suite --timeout 600 --output-on-failure
}

# What only an optimized build shows: each header compiles on its own, the link-time optimization
# build's suites (cpp/tests/CMakeLists.txt: target optimized_checks), the installed CMake package
# (consumer); then the Eigen fallback.
cpp_optimized() {
  local status=0
  echo "== C++ headers alone, link-time optimization build, find_package consumer (ctest -L 'lto|install')"
  cmake -S . -B build/cpp -G Ninja -DCMAKE_BUILD_TYPE=Release -DCIRCLEDIST_BUILD_TESTS=ON >/dev/null || return 1
  cmake --build build/cpp -j 1 --target optimized_checks || return 1
  ctest --test-dir build/cpp -L "lto|install" --timeout 600 --output-on-failure || status=1
  echo "== C++ test against cmeel-eigen's Eigen (the fallback where the system has none)"
  eigen_fallback || status=1
  return $status
}

# The test task's C++ side runs beside its Python side, at the lowest priority: it takes the cores
# pytest leaves idle (its single-process pass, the last files of its parallel one) and all of
# them once pytest is done. Its output goes to build/test-logs/ and is printed when it is done.
cpp_lane_start() {
  echo "== C++ tests: built and run at low priority beside the Python side (output: build/test-logs/)"
  (renice -n 19 "$BASHPID" >/dev/null && timed cpp_sanitized) >build/test-logs/cpp_sanitized.log 2>&1 &
  cpp_sanitized_pid=$!
  (renice -n 19 "$BASHPID" >/dev/null && timed cpp_optimized) >build/test-logs/cpp_optimized.log 2>&1 &
  cpp_optimized_pid=$!
  trap cpp_lane_stop EXIT
}
# An early exit (a failed build of the wheel) stops the C++ side with it.
cpp_lane_stop() {
  [ -z "${cpp_lane_waited:-}" ] || return 0
  local pid
  for pid in "$cpp_sanitized_pid" "$cpp_optimized_pid"; do kill_tree "$pid"; done
}
kill_tree() {  # kill_tree PID: the process and every descendant
  local child
  for child in $(cat /proc/"$1"/task/*/children 2>/dev/null || true); do kill_tree "$child"; done
  kill "$1" 2>/dev/null || true
}
# timed COMMAND...: runs it, then prints how long it took (seconds of wall time) and adds that to
# build/test-logs/times (the test task's summary at the end).
timed() {
  local start=$SECONDS status=0
  "$@" || status=$?
  echo "$1: $((SECONDS - start)) s" | tee -a build/test-logs/times
  return $status
}
cpp_lane_wait() {
  local status=0
  cpp_lane_waited=1
  wait "$cpp_sanitized_pid" || status=1
  cat build/test-logs/cpp_sanitized.log
  wait "$cpp_optimized_pid" || status=1
  cat build/test-logs/cpp_optimized.log
  return $status
}

if [ "$task" = test ]; then
  test_start=$SECONDS
  mkdir -p build/test-logs
  : >build/test-logs/times
  cpp_lane_start
fi

# The package is built as a wheel, which is installed: the tests then run on what a user installs.
# The check task skips both while no file the wheel is built from is newer than the last install
# (a stamp taken before that build started; a folder's time changes when a file in it is removed).
built_from=(CMakeLists.txt pyproject.toml README.md LICENSE src cpp/include cpp/cmake python)
stamp=.venv/circledist-installed.stamp
if [ "$task" = check ] && [ -f "$stamp" ] && [ -z "$(find "${built_from[@]}" -newer "$stamp" -print -quit)" ]; then
  echo "== circledist is installed from these sources already"
else
  echo "== building the circledist wheel, and installing it"
  rm -f "$stamp"
  mkdir -p build
  touch build/installed.stamp
  rm -rf build/wheel
  wheel_start=$SECONDS
  "$py" -m pip wheel -q --disable-pip-version-check --no-build-isolation --no-deps -w build/wheel .
  pip_install --force-reinstall --no-deps build/wheel/circledist-*.whl
  [ "$task" != test ] || echo "wheel: $((SECONDS - wheel_start)) s" >>build/test-logs/times
  mv build/installed.stamp "$stamp"
fi

case "$task" in
  demo)
    "$py" examples/demo.py  # picture: build/demo_scene.png (`examples/demo.py PATH` writes it elsewhere)
    ;;
  test)
    status=0
    browser_wait
    echo "== pytest"
    timed pytest_on_every_core || status=$?
    echo "== the wheel alone: a fresh venv with the wheel and the test extra, no compiler or Eigen on PATH"
    timed wheel_alone || status=1
    cpp_lane_wait || status=1
    # Where the time went (the C++ side ran beside the rest, from the wheel's build on).
    echo "== time (s): $(paste -sd, build/test-logs/times | sed 's/,/, /g'); in all $((SECONDS - test_start)) s"
    exit $status
    ;;
  check)
    echo "== pytest, the tests not marked slow"
    pytest_on_every_core "not slow"
    ;;
  fuzz)
    status=0
    "$py" tools/fuzz_crash.py --cases "${2:-10000000}" --chunk 200000 --batched --timeout 1800 \
      --report build/reports/fuzz_report.json || status=$?
    "$py" tools/fuzz_crash.py --threads $(( ${2:-10000000} / 10000 + 1 )) --report build/reports/fuzz_threads_report.json \
      || status=$?
    "$py" tools/fuzz_crash.py --arguments $(( ${2:-10000000} / 100 + 1 )) --chunk 5000 --timeout 600 \
      --report build/reports/fuzz_arguments_report.json || status=$?
    "$py" -m tools.differential --answers "${2:-10000000}" --seed 1 --report build/reports/differential_report.json || status=$?
    # Every recorded 50-digit reference the tests read, computed again (tests/references/).
    "$py" -m tools.references verify || status=$?
    # The report pages, rewritten whole from these records (commit them when the run is worth keeping).
    "$py" -m tools.report_pages fuzz build/reports/fuzz_report.json build/reports/fuzz_threads_report.json \
      build/reports/fuzz_arguments_report.json || status=$?
    "$py" -m tools.report_pages differential build/reports/differential_report.json || status=$?
    exit $status
    ;;
  docs)
    # Read from the package just installed: its docstrings are the reference. -E: no stale pages.
    "$py" -m sphinx -W --keep-going -E -q -b html docs build/docs
    echo "API reference: build/docs/index.html"
    ;;
  bench)
    cpp_build -DCIRCLEDIST_BUILD_BENCH=ON
    cmake --build build/cpp --target accuracy_vs_time
    "$py" -m bench.bench_queries          # docs/reports/benchmark.md
    "$py" -m bench.accuracy_vs_time       # docs/reports/accuracy_vs_time.md, .png, stability_sweeps.png
    "$py" -m bench.bench_scene            # docs/reports/scene_scaling.md, .png
    "$py" -m bench.bench_motion           # docs/reports/motion.md
    "$py" -m bench.figures                # docs/derivations/line_disk.png
    ;;
  *)
    echo "usage: bash tools/run.sh demo|check|test|lint|bench|docs|fuzz [N]" >&2
    exit 2
    ;;
esac
