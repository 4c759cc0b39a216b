"""Time limit, progress, cancellation and Ctrl-C from Python; the GIL is released during a run."""
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import pytest

import cmx
from conftest import grid_ball

# A run that takes tens of seconds: a 20^3-cell ball shrunk whole and re-expanded onto a star,
# with every invariant asserted after every step (check=True).
SLOW = dict(shape="star", init="shrink", check=True, threads=1)


@pytest.fixture(scope="module")
def slow_ball():
    return grid_ball(20, jitter=0.15)


def test_time_limit_returns_a_result_and_raise_for_status_raises(slow_ball):
    V, T = slow_ball
    start = time.monotonic()
    r = cmx.map(V, T, time_limit=0.5, **SLOW)
    assert time.monotonic() - start < 10
    assert r.status == "time_limit" and not r.ok and not r
    assert r.tets.shape == (0, 4) and r.target_exact == []
    with pytest.raises(cmx.TimeLimit) as e:
        r.raise_for_status()
    assert e.value.result is r


def test_progress_returning_true_cancels(slow_ball):
    V, T = slow_ball
    calls = []

    def progress(p):
        calls.append(p)
        return p.seconds > 0.3

    r = cmx.map(V, T, progress=progress, **SLOW)
    assert r.status == "cancelled"
    assert calls and calls[-1].seconds > 0.3 and calls[-1].seconds < 10
    with pytest.raises(cmx.Cancelled):
        r.raise_for_status()


def test_an_exception_in_progress_stops_the_run_and_propagates(slow_ball):
    V, T = slow_ball

    class Stop(Exception):
        pass

    def progress(p):
        if p.seconds > 0.3:
            raise Stop(p.phase)

    start = time.monotonic()
    with pytest.raises(Stop, match="expansion"):
        cmx.map(V, T, progress=progress, **SLOW)
    assert time.monotonic() - start < 10


def test_the_gil_is_released_during_a_run(slow_ball):
    V, T = slow_ball
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.01)

    t = threading.Thread(target=tick)
    t.start()
    try:
        start = time.monotonic()
        r = cmx.map(V, T, time_limit=1.0, **SLOW)
        end = time.monotonic()
    finally:
        done.set()
        t.join()
    assert r.status == "time_limit"
    during = [x for x in ticks if start + 0.1 < x < end - 0.1]
    assert len(during) > 20, f"{len(during)} ticks of another thread during a {end - start:.2f} s run"


def test_ctrl_c_interrupts_a_run_with_keyboard_interrupt(tmp_path):
    script = tmp_path / "long_run.py"
    script.write_text(textwrap.dedent(f"""
        import sys, time
        sys.path.insert(0, {os.path.dirname(__file__)!r})
        import cmx
        from conftest import grid_ball
        V, T = grid_ball(20, jitter=0.15)
        started = []
        def progress(p):
            if not started:
                started.append(1)
                print("started", flush=True)
        try:
            r = cmx.map(V, T, progress=progress, **{SLOW!r})
            print("finished", r.status, flush=True)
        except KeyboardInterrupt:
            print("interrupted", flush=True)
            raise
    """))
    p = subprocess.Popen([sys.executable, str(script)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         env=dict(os.environ))
    try:
        assert p.stdout.readline().strip() == "started"
        time.sleep(0.5)
        sent = time.monotonic()
        p.send_signal(signal.SIGINT)
        out, err = p.communicate(timeout=30)
        elapsed = time.monotonic() - sent
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()
    assert "interrupted" in out, (out, err)
    assert "finished" not in out
    assert "KeyboardInterrupt" in err
    assert p.returncode != 0
    assert elapsed < 5, f"{elapsed:.2f} s from SIGINT to exit"
