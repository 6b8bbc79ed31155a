"""Helpers shared by the test modules."""

import threading
import time

import numpy as np
import pytest


@pytest.fixture
def assert_gil_released():
    """`assert_gil_released(call)` runs `call()` in another thread and checks that this thread
    keeps running meanwhile (it ticks every millisecond): the call releases the GIL while it
    computes. With the GIL held for the whole call this thread could not tick at all."""

    def check(call):
        done = threading.Event()
        duration = []
        failed = []

        def work():
            t0 = time.perf_counter()
            try:
                call()
            except BaseException as e:  # raised below, in the test's thread
                failed.append(e)
            finally:
                # Set even when the call raises: the loop below would wait forever.
                duration.append(time.perf_counter() - t0)
                done.set()

        ticks = []
        th = threading.Thread(target=work)
        th.start()
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)
        th.join()
        if failed:
            raise failed[0]
        gaps = np.diff(ticks) if len(ticks) > 1 else np.array([duration[0]])
        assert len(ticks) >= 5, (len(ticks), duration)
        assert gaps.max() < 0.6 * duration[0], (gaps.max(), duration[0])

    return check


@pytest.fixture(scope="session")
def lugre_exe():
    """The `lugre` command built from this checkout: $LUGRE_EXE if set, else the newest of the
    debug and release builds (scripts/test.sh runs the Rust tests, which build it, first)."""
    import os
    import pathlib

    if os.environ.get("LUGRE_EXE"):
        return os.environ["LUGRE_EXE"]
    root = pathlib.Path(__file__).resolve().parents[3]
    target = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", root / "target"))
    builds = [p for p in (target / "debug" / "lugre", target / "release" / "lugre") if p.exists()]
    if not builds:
        pytest.fail(f"no lugre binary under {target}: run `cargo build -p lugre-cli` first")
    return str(max(builds, key=lambda p: p.stat().st_mtime))


@pytest.fixture(scope="session")
def lugre_cli(lugre_exe):
    """`lugre_cli(args)` runs the `lugre` command ([`lugre_exe`]) and returns its JSON output:
    for checks that Python and the command line give the same answer."""
    import json
    import subprocess

    def run(args):
        out = subprocess.run([lugre_exe, *args], capture_output=True, text=True, check=True)
        return json.loads(out.stdout)

    return run


@pytest.fixture(scope="session")
def lugre_cli_error(lugre_exe):
    """`lugre_cli_error(args)` runs the `lugre` command on arguments it must refuse and returns
    its one line of error (after "lugre: error: "), having checked the exit status 2."""
    import subprocess

    def run(args):
        out = subprocess.run([lugre_exe, *args], capture_output=True, text=True)
        assert out.returncode == 2, (args, out.returncode, out.stderr)
        lines = out.stderr.strip().splitlines()
        assert len(lines) == 1, out.stderr
        return lines[0].removeprefix("lugre: error: ")

    return run
