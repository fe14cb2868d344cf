"""The GIL is released while optimizing; Ctrl-C (SIGINT) stops a run within
one iteration with KeyboardInterrupt and leaves no thread behind."""

import subprocess
import sys
import textwrap
import threading
import time

import akvf
from conftest import bumpy_disk


def test_other_python_threads_run_during_an_optimization():
    V, F = bumpy_disk(60, 60)
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    ticker = threading.Thread(target=tick)
    ticker.start()
    started = time.perf_counter()
    r = akvf.parameterize(V, F, precond="identity", max_iters=2000, grad_tol=0)
    finished = time.perf_counter()
    done.set()
    ticker.join()
    during = [t for t in ticks if started < t < finished]
    assert r.iterations > 10
    # With the GIL held the ticker could not run at all during the call; it
    # ticks about once a millisecond otherwise (fewer on a loaded machine).
    assert len(during) >= 20


SCRIPT = textwrap.dedent("""
    import os, signal, sys, threading, time
    sys.path[:0] = %r
    import akvf
    from conftest import bumpy_disk
    V, F = bumpy_disk(80, 80)
    rows = []
    threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
    started = time.perf_counter()
    try:
        akvf.parameterize(V, F, precond="identity", max_iters=100000, grad_tol=0,
                          callback=lambda row, uv: rows.append(time.perf_counter()))
        print("not interrupted")
    except KeyboardInterrupt:
        gaps = [b - a for a, b in zip(rows, rows[1:])]
        stopped = time.perf_counter()
        print("interrupted", stopped - started, max(gaps), threading.active_count())
    # Python's own handler is back: a second SIGINT raises again.
    try:
        os.kill(os.getpid(), signal.SIGINT)
        time.sleep(0.5)
        print("no handler")
    except KeyboardInterrupt:
        print("handler restored")
""")


def test_ctrl_c_raises_keyboard_interrupt_within_one_iteration():
    import os
    here = os.path.dirname(os.path.abspath(__file__))
    run = subprocess.run([sys.executable, "-c", SCRIPT % [here] + ""], capture_output=True, text=True, timeout=120,
                         env=dict(os.environ))
    assert run.returncode == 0, run.stderr
    lines = run.stdout.split("\n")
    words = lines[0].split()
    assert words[0] == "interrupted", run.stdout
    elapsed, longest_iteration, threads = float(words[1]), float(words[2]), int(words[3])
    # The signal came after 1 s; the run ended within about one iteration of it.
    assert elapsed < 1.0 + 2 * longest_iteration + 0.5
    assert threads == 1
    assert lines[1] == "handler restored"
