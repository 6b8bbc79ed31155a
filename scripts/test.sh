#!/usr/bin/env bash
# Every test of the project, on a fresh machine: installs what it needs, then runs the suites.
#
#   0. what a reviewer checks: formatting (cargo fmt), lints (clippy, warnings denied, with the
#      declared MSRV enforced by its incompatible_msrv lint; also with every optional feature
#      and with none), the dependencies' own MSRVs (scripts/check-msrv.py), rustdoc with
#      warnings denied, the benchmarks and the fuzz targets built;
#   1. the Rust tests of every crate except the Python extension module (it takes its
#      symbols from the interpreter that imports it, so it has no Rust test harness), and the
#      zoo's full-fit coverage in a release build;
#   2. the MATLAB/Octave MEX functions (scripts/build-mex.sh, matlab/tests/test_lugre.m against
#      the CLI's JSON); Octave is installed from Debian when run as root, else skipped loudly;
#      (the C ABI's example program is built and run by the Rust tests of crates/lugre-ffi;)
#   3. the Python package: a virtual environment (.venv, or $LUGRE_VENV) with maturin, numpy,
#      pytest, dask[distributed,dataframe] (lugre.dask's tests, one on a 2-worker
#      LocalCluster) and hysteresis 2.0.5 (loop areas), the package built from crates/lugre-py
#      and installed into it, its pytest suite;
#   4. the FMI 3.0 FMUs (scripts/build-fmu.sh) validated and simulated by fmpy (PyPI, installed
#      into the same environment): tests/fmu;
#   5. the conformance table (tests/conformance/cases.json: one input, the same answer from
#      every front end): through the CLI and the C ABI in step 1 (crates/lugre-cli/tests/
#      conformance.rs), the MEX functions in step 2, Python and the FMUs last.
#
# Needs cargo and python3 (>= 3.9, with venv); the first run downloads maturin, numpy, pytest,
# dask and hysteresis from PyPI. Re-runs reuse the environment and cargo's build cache.
set -euo pipefail
cd "$(dirname "$0")/.."

step() { printf '\n== %s ==\n' "$*"; }
# Suites that could not run here (named again at the end).
skipped=()

step "format, lints, MSRV, docs"
cargo fmt --all --check
cargo clippy --workspace --all-targets -- -D warnings
cargo clippy -p lugre --all-targets --features bench-internals -- -D warnings
cargo clippy -p lugre --all-targets --no-default-features -- -D warnings
python3 scripts/check-msrv.py
RUSTDOCFLAGS="-D warnings" cargo doc --workspace --no-deps --quiet
RUSTDOCFLAGS="-D warnings" cargo doc -p lugre --no-deps --document-private-items --quiet

step "benchmarks and fuzz targets build"
cargo bench -p lugre --features bench-internals --no-run --quiet
# The fuzz crate is its own workspace; its targets build on stable (running them needs nightly
# and cargo-fuzz, see CONTRIBUTING.md).
cargo build --manifest-path fuzz/Cargo.toml --bins --quiet

step "Rust tests"
cargo test --workspace --exclude lugre-py --no-fail-fast
# The coverage of the zoo's full-fit intervals refits each record some hundred simulations:
# too slow unoptimised, so it runs here in the release build the benchmarks made.
cargo test --release -p lugre --test zoo_full_fit intervals_cover_the_truth -- --exact

step "MATLAB/Octave: the MEX functions (the C example runs in the Rust tests)"
# Octave from Debian when run as root (CI); elsewhere the suite is skipped, loudly.
if ! command -v mkoctfile >/dev/null && [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq octave liboctave-dev >/dev/null
fi
if command -v mkoctfile >/dev/null && command -v octave >/dev/null; then
    bash scripts/build-mex.sh
    cargo build --release --quiet -p lugre-cli
    octave --no-gui --quiet --eval "addpath('matlab', 'matlab/tests'); exit(test_lugre())"
    # The conformance table through the MEX functions (the same cases as the Rust and Python
    # runners: tests/conformance/).
    octave --no-gui --quiet --eval "addpath('matlab', 'tests/conformance'); exit(conformance())"
else
    echo "!!! SKIPPED the Octave/MEX tests: octave and liboctave-dev are not installed (apt-get install octave liboctave-dev, as root) !!!" >&2
    skipped+=("Octave/MEX")
fi

venv=${LUGRE_VENV:-.venv}
case "$venv" in /*) ;; *) venv="$PWD/$venv" ;; esac
if ! "$venv/bin/python" -c 'import sys' 2>/dev/null; then
    if [ -e "$venv" ] && [ ! -f "$venv/pyvenv.cfg" ]; then
        echo "scripts/test.sh: $venv exists and is not a virtual environment" >&2
        exit 1
    fi
    "${PYTHON:-python3}" -m venv --clear "$venv"
fi
# The environment's tools first on PATH: maturin's build backend runs the `maturin` it installed.
export VIRTUAL_ENV="$venv"
export PATH="$VIRTUAL_ENV/bin:$PATH"
py="$VIRTUAL_ENV/bin/python"
pip=("$py" -m pip install --quiet --disable-pip-version-check)
# dask[distributed,dataframe]: lugre.dask's tests (one on a 2-worker LocalCluster);
# hysteresis: the loop areas every loop's work is checked against (test_zoo_areas.py).
"${pip[@]}" 'maturin==1.16.*' numpy pytest 'dask[distributed,dataframe]>=2024.1' 'hysteresis==2.0.5'
# The venv's maturin builds the wheel (no isolated build environment to download each time);
# cargo rebuilds only what changed.
"${pip[@]}" --no-build-isolation --force-reinstall --no-deps ./crates/lugre-py
step "Python tests"
# pytest exits non-zero (5) when it collects no test, so an empty run fails here too.
"$py" -m pytest -q -p no:cacheprovider crates/lugre-py/tests

step "FMI 3.0: the FMUs in fmpy"
"${pip[@]}" fmpy
bash scripts/build-fmu.sh
# The CLI is the reference of the zoo's mass FMUs (test_zoo_mass_fmu.py).
cargo build --release --quiet -p lugre-cli
"$py" -m pytest -q -p no:cacheprovider tests/fmu

step "The conformance table through Python and the FMUs"
# The CLI is the reference (built above with the Octave tests; cargo does nothing if so).
cargo build --release --quiet -p lugre-cli
"$py" -m pytest -q -p no:cacheprovider tests/conformance
if [ ${#skipped[@]} -gt 0 ]; then
    echo "!!! scripts/test.sh: SKIPPED suites: ${skipped[*]} (CI runs them all) !!!" >&2
fi
