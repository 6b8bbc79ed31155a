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

        def work():
            t0 = time.perf_counter()
            call()
            duration.append(time.perf_counter() - t0)
            done.set()

        ticks = []
        th = threading.Thread(target=work)
        th.start()
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)
        th.join()
        gaps = np.diff(ticks) if len(ticks) > 1 else np.array([duration[0]])
        assert len(ticks) >= 5, (len(ticks), duration)
        assert gaps.max() < 0.6 * duration[0], (gaps.max(), duration[0])

    return check
