#!/usr/bin/env bash
# Rewrites the checked-in files written from the core's parameter table
# (crates/lugre/src/model/parameter.rs): the C header's LugreParams and LUGRE_MAX_PARAMETERS
# (crates/lugre-ffi/include/lugre.h), the FMUs' parameter variables (crates/lugre-fmu/fmu/*.xml),
# the zoo FMUs' model descriptions, one per model of the zoo's table (lugre::zoo::MODELS), all
# of each (crates/lugre-fmu/fmu/zoo/NAME.xml; a model gone from the table loses its file), the
# mass FMUs' of the finite-rate models (crates/lugre-fmu/fmu/mass/NAME.xml, likewise),
# and the Python stub's keywords and properties (crates/lugre-py/python/lugre/__init__.pyi).
# Their tests fail, naming this, until a change of the table is written to them. The stub is
# written by the installed package's lugre.PARAMETERS: $PYTHON (default python3) must import the
# package built from this tree (scripts/test.sh's venv, or pip install ./crates/lugre-py).
set -euo pipefail
cd "$(dirname "$0")/.."
export LUGRE_BLESS=1
# One thread: the header is written by one test and read by the other.
cargo test --quiet -p lugre-ffi --test header -- --test-threads=1
cargo test --quiet -p lugre-fmu --lib the_parameters_are_written_from_the_table
cargo test --quiet -p lugre-fmu --lib the_zoo_model_descriptions_are_written_from_the_table
cargo test --quiet -p lugre-fmu --lib the_mass_model_descriptions_are_written_from_the_table
"${PYTHON:-python3}" -m pytest -p no:cacheprovider -q crates/lugre-py/tests/test_tables.py \
    -k the_stubs_parameters_are_written_from_the_table
