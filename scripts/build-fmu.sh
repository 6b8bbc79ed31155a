#!/usr/bin/env bash
# Builds lugre's FMI 3.0 FMUs into target/fmu/: lugre-friction.fmu (the friction element),
# lugre-mass.fmu (a mass with friction), lugre-NAME.fmu for every model NAME of the core's
# zoo table (crates/lugre-fmu/fmu/zoo/NAME.xml) and lugre-mass-NAME.fmu for every model of the
# table with a finite-rate form (crates/lugre-fmu/fmu/mass/NAME.xml), both written from the
# table by scripts/write-tables.sh. Each is a zip of its modelDescription.xml and
# binaries/x86_64-linux/<modelIdentifier>.so, the one library of crates/lugre-fmu (release).
# No FMI tooling needed.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet -p lugre-fmu
target=${CARGO_TARGET_DIR:-target}
python3 - "$target" <<'PY'
import glob, os, re, sys, zipfile
target = sys.argv[1]
out = os.path.join(target, "fmu")
os.makedirs(out, exist_ok=True)
descriptions = ["crates/lugre-fmu/fmu/lugre-friction.xml", "crates/lugre-fmu/fmu/lugre-mass.xml"]
descriptions += sorted(glob.glob("crates/lugre-fmu/fmu/zoo/*.xml"))
descriptions += sorted(glob.glob("crates/lugre-fmu/fmu/mass/*.xml"))
for xml in descriptions:
    text = open(xml, encoding="utf-8").read()
    name = re.search(r'modelName="([^"]+)"', text).group(1)
    identifier = re.search(r'modelIdentifier="([^"]+)"', text).group(1)
    path = os.path.join(out, name + ".fmu")
    tmp = path + ".tmp"
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as z:
        z.write(xml, "modelDescription.xml")
        z.write(os.path.join(target, "release", "liblugre_fmu.so"), f"binaries/x86_64-linux/{identifier}.so")
    os.replace(tmp, path)  # never a half-written FMU
    print("built", path)
PY
