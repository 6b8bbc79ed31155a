#!/usr/bin/env bash
# Builds the MEX file of lugre into matlab/ for Octave (mkoctfile, from the Debian packages
# octave and liboctave-dev): the C ABI as a static library (cargo), linked into one
# self-contained matlab/lugre_mex.mex. For MATLAB, see matlab/README.md.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v mkoctfile >/dev/null || {
    echo "build-mex.sh: mkoctfile not found (apt-get install octave liboctave-dev)" >&2
    exit 1
}
cargo build --release --quiet -p lugre-ffi
target=${CARGO_TARGET_DIR:-target}
# A failed build must not leave the previous MEX file to be tested.
rm -f matlab/lugre_mex.mex matlab/lugre_mex.o
# Octave 7 aborts on mxGetDoubles without the interleaved-complex API; the gateway uses mxGetPr.
mkoctfile --mex -DMX_HAS_INTERLEAVED_COMPLEX=1 -Icrates/lugre-ffi/include \
    -o matlab/lugre_mex.mex matlab/lugre_mex.c "$target/release/liblugre_c.a" -lpthread -ldl -lm
echo "built matlab/lugre_mex.mex"
