#!/usr/bin/env bash
# circledist's one entry point for people and CI:
#   bash tools/run.sh demo   install what is missing, build the package, run the demo
#   bash tools/run.sh test   install what is missing, build the package, run pytest and the C++ tests (ctest)
#   bash tools/run.sh bench  install what is missing, build, run the benchmarks
#   bash tools/run.sh fuzz [N]  install what is missing, build, run the crash-isolating fuzz's long
#                            mode over N cases (default 10^7; docs/fuzz_report.json), then the
#                            differential accuracy test's long mode over N library answers (every
#                            solver x precision x entry point, both orders; 168 per case)
#                            (docs/differential_report.json)
# Works as root on a fresh Debian machine with Python 3: Debian's Eigen, compiler and venv come
# from apt when missing; Python packages go into ./.venv (which sees the system's site-packages).
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
if [ ${#missing[@]} -gt 0 ]; then
  echo "== installing from Debian: ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi

if [ ! -x .venv/bin/python ]; then
  echo "== creating .venv"
  "$python" -m venv --system-site-packages .venv
fi
py=.venv/bin/python
export PATH="$PWD/.venv/bin:$PATH"

pip_install() { "$py" -m pip install -q --disable-pip-version-check "$@"; }
have() { "$py" -c "import $1" >/dev/null 2>&1; }
need=()
for req in numpy:numpy pybind11:pybind11 scikit_build_core:scikit-build-core cmake:cmake ninja:ninja; do
  have "${req%%:*}" || need+=("${req#*:}")
done
case "$task" in
  demo) have matplotlib || need+=(matplotlib) ;;
  test) for req in pytest:pytest hypothesis:hypothesis mpmath:mpmath matplotlib:matplotlib; do have "${req%%:*}" || need+=("${req#*:}"); done ;;
  bench) for req in mpmath:mpmath matplotlib:matplotlib distance3d:distance3d; do have "${req%%:*}" || need+=("${req#*:}"); done ;;
  fuzz) for req in mpmath:mpmath; do have "${req%%:*}" || need+=("${req#*:}"); done ;;
esac
[ ${#need[@]} -eq 0 ] || { echo "== installing from PyPI: ${need[*]}"; pip_install "${need[@]}"; }

echo "== building the circledist package"
pip_install --no-build-isolation .

cpp_build() {  # cpp_build [extra cmake definitions]
  cmake -S . -B build/cpp -G Ninja -DCMAKE_BUILD_TYPE=Release -DCIRCLEDIST_BUILD_TESTS=ON "$@" >/dev/null
  cmake --build build/cpp -j 2
}

case "$task" in
  demo)
    "$py" examples/demo.py
    ;;
  test)
    echo "== pytest"
    status=0
    "$py" -m pytest -q -p no:cacheprovider || status=$?
    echo "== C++ tests (ctest)"
    cpp_build
    ctest --test-dir build/cpp --output-on-failure || status=1
    echo "== C++ tests under AddressSanitizer and UndefinedBehaviorSanitizer"
    cmake -S . -B build/sanitize -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCIRCLEDIST_BUILD_TESTS=ON \
      -DCMAKE_CXX_FLAGS="-O1 -g -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer" >/dev/null
    cmake --build build/sanitize -j 2
    timeout 600 ctest --test-dir build/sanitize -E consumer --output-on-failure || status=1
    exit $status
    ;;
  fuzz)
    status=0
    "$py" tools/fuzz_crash.py --cases "${2:-10000000}" --chunk 200000 --batched --timeout 1800 \
      --report docs/fuzz_report.json || status=$?
    "$py" tools/differential.py --answers "${2:-10000000}" --seed 1 --report docs/differential_report.json || status=$?
    exit $status
    ;;
  bench)
    cpp_build -DCIRCLEDIST_BUILD_BENCH=ON
    cmake --build build/cpp --target accuracy_vs_time
    "$py" bench/bench_queries.py          # docs/benchmark.md
    "$py" bench/accuracy_vs_time.py       # docs/accuracy_vs_time.md, .png, docs/stability_sweeps.png
    "$py" bench/bench_scene.py            # docs/scene_scaling.md, .png
    "$py" bench/figures.py                # docs/line_disk.png
    ;;
  *)
    echo "usage: bash tools/run.sh demo|test|bench|fuzz [N]" >&2
    exit 2
    ;;
esac
