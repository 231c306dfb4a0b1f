# Copyright (c) 2026 CGAL Polyvector Fields contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Author(s): CGAL Polyvector Fields developers
#
# This file is part of CGAL Polyvector Fields, a package that builds on CGAL.
# It is not part of CGAL.

# The GIL is released during the C++ work: two threads design fields at the
# same time, and the interpreter keeps running Python code meanwhile.

import threading
import time

import numpy as np

import polyvector_fields as pvf
from conftest import data_path


def test_two_threads_design_fields_at_the_same_time():
    V, F, _ = pvf.read_triangle_mesh(data_path("fandisk.off"))
    # One partial constraint, degree 8: about a second per call on these machines.
    b, bc = np.array([0]), (V[F[0, 1]] - V[F[0, 0]]).reshape(1, 3)
    expected, _ = pvf.design_field(V, F, b, bc, degree=8)
    barrier = threading.Barrier(3)
    calls = {}
    results = {}

    def work(name):
        barrier.wait()
        start = time.perf_counter()
        X, _ = pvf.design_field(V, F, b, bc, degree=8)
        calls[name] = (start, time.perf_counter())
        results[name] = X

    threads = [threading.Thread(target=work, args=(n,)) for n in ("a", "b")]
    for t in threads:
        t.start()
    # A heartbeat of the main thread: with the GIL held by a call, it stops
    # for the whole call; released, it beats every millisecond or so.
    barrier.wait()
    beats = []
    while any(t.is_alive() for t in threads):
        beats.append(time.perf_counter())
        time.sleep(0.001)
    for t in threads:
        t.join()
    (a0, a1), (b0, b1) = calls["a"], calls["b"]
    shortest = min(a1 - a0, b1 - b0)
    # Both calls started before either ended.
    assert max(a0, b0) < min(a1, b1), calls
    # The interpreter ran during the calls: no gap between heartbeats during
    # them is anywhere near a call's length (held, the gap would be all of it).
    inside = [t for t in beats if max(a0, b0) <= t <= min(a1, b1)]
    gaps = np.diff([max(a0, b0)] + inside + [min(a1, b1)])
    assert gaps.max() < 0.5 * shortest, (gaps.max(), shortest)
    # And both threads got the field of one call alone, bit for bit.
    assert np.array_equal(results["a"], expected) and np.array_equal(results["b"], expected)
