"""What the zoo's FMU tests share: where the FMUs are built, and one co-simulation instance in
fmpy with its variables by name and the messages it logged (imported by the test files beside
it; needs fmpy)."""

import os
import pathlib

import numpy as np
import pytest

fmpy = pytest.importorskip("fmpy")
from fmpy import extract, read_model_description  # noqa: E402
from fmpy.fmi3 import FMU3Slave  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
TARGET = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
FMUS = TARGET / "fmu"


def fmu_path(file_name):
    """target/fmu/`file_name`; the test fails, saying how to build it, when it is missing."""
    path = FMUS / file_name
    if not path.exists():
        pytest.fail(f"{path} is missing: run bash scripts/build-fmu.sh")
    return path


def unzip_all(tmp_path_factory, file_names):
    """Each FMU of `file_names` ({key: file name}) unzipped once, by key."""
    return {key: extract(str(fmu_path(file)), unzipdir=str(tmp_path_factory.mktemp(key)))
            for key, file in file_names.items()}


class Host:
    """One co-simulation instance, its variables by name, the messages it logged."""

    def __init__(self, directory, instance):
        self.md = read_model_description(directory)
        self.vr = {v.name: v.valueReference for v in self.md.modelVariables}
        self.logs = []
        self.fmu = FMU3Slave(guid=self.md.guid, unzipDirectory=directory,
                             modelIdentifier=self.md.coSimulation.modelIdentifier, instanceName=instance)
        self.fmu.instantiate(logMessage=lambda env, status, category, message: self.logs.append(message.decode()))

    def set(self, name, value):
        self.fmu.setFloat64([self.vr[name]], [float(x) for x in np.atleast_1d(value)])

    def close(self):
        self.fmu.terminate()
        self.fmu.freeInstance()
