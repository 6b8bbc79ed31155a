#!/usr/bin/env bash
# Builds lugre's FMI 3.0 FMUs: target/fmu/lugre-friction.fmu (the friction element) and
# target/fmu/lugre-mass.fmu (a mass with friction), each a zip of its modelDescription.xml
# (crates/lugre-fmu/fmu/NAME.xml) and binaries/x86_64-linux/<modelIdentifier>.so, the one
# library of crates/lugre-fmu (release). No FMI tooling needed.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet -p lugre-fmu
target=${CARGO_TARGET_DIR:-target}
python3 - "$target" <<'PY'
import os, sys, zipfile
target = sys.argv[1]
out = os.path.join(target, "fmu")
os.makedirs(out, exist_ok=True)
for name, identifier in (("lugre-friction", "lugre_friction"), ("lugre-mass", "lugre_mass")):
    path = os.path.join(out, name + ".fmu")
    tmp = path + ".tmp"
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as z:
        z.write(f"crates/lugre-fmu/fmu/{name}.xml", "modelDescription.xml")
        z.write(os.path.join(target, "release", "liblugre_fmu.so"), f"binaries/x86_64-linux/{identifier}.so")
    os.replace(tmp, path)  # never a half-written FMU
    print("built", path)
PY
