"""Ctrl-C (SIGINT, KeyboardInterrupt) stops a long Model.simulate between steps."""
import os
import signal
import threading
import time

import pytest

import sinew
from conftest import RESOURCES


def test_keyboard_interrupt_stops_simulate():
    model = sinew.load(RESOURCES / "DoublePendulum3D.osim")
    # 10,000 s at a tight accuracy would run for minutes.
    timer = threading.Timer(0.3, os.kill, args=(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    try:
        with pytest.raises(KeyboardInterrupt):  # the timer starts inside: no signal escapes
            timer.start()
            model.simulate(1e4, accuracy=1e-10, report_interval=1.0)
    finally:
        timer.cancel()
    assert time.monotonic() - start < 30.0
