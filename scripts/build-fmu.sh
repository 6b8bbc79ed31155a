#!/usr/bin/env bash
# Builds the FMI 3.0 FMU of lugre's friction element: target/fmu/lugre-friction.fmu, a zip of
# modelDescription.xml (crates/lugre-fmu/fmu/lugre-friction.xml) and
# binaries/x86_64-linux/lugre_friction.so (crates/lugre-fmu, release). No FMI tooling needed.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet -p lugre-fmu
target=${CARGO_TARGET_DIR:-target}
python3 - "$target" <<'PY'
import os, sys, zipfile
target = sys.argv[1]
out = os.path.join(target, "fmu")
os.makedirs(out, exist_ok=True)
path = os.path.join(out, "lugre-friction.fmu")
tmp = path + ".tmp"
with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as z:
    z.write("crates/lugre-fmu/fmu/lugre-friction.xml", "modelDescription.xml")
    z.write(os.path.join(target, "release", "liblugre_fmu.so"), "binaries/x86_64-linux/lugre_friction.so")
os.replace(tmp, path)  # never a half-written FMU
print("built", path)
PY
