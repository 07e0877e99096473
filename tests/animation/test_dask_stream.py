"""Dask rendering streams: chunks are sent as any comes back (not only the oldest),
frames still come out in order, and a dying worker fails the render naming the frames
lost, within a bounded time."""

import os
import threading
import time

import numpy as np
import pytest

from scanline.animation import Animation
from scanline.animation import render as render_module
from tests.reference import peer


class _Blocked:
    """Frame 0 waits until frame ``until`` (the last, by default) has been rendered (or
    60 s, recording that it never was), then ``linger`` seconds more: a render that
    only refills behind the oldest chunk never sends the last chunk while the first
    is out, a streaming one does."""

    def __init__(self, count, until=None, linger=0.0):
        self.until = count - 1 if until is None else until
        self.linger = linger
        self.last_done = threading.Event()
        self.saw_last = []

    def __call__(self, i):
        if i == 0:
            self.saw_last.append(self.last_done.wait(60))
            time.sleep(self.linger)
        if i == self.until:
            self.last_done.set()
        return np.full((4, 6), i, np.uint8)


def test_a_slow_first_chunk_does_not_hold_the_others_back():
    distributed = peer("distributed")
    count = 16
    # 2 workers: 15 chunks (iter_chunks), within the 16 a render holds in flight or
    # waiting, and more than the 8 it sends at first
    assert len(render_module.chunks(range(count), 2)) == 15
    render = _Blocked(count)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        images = list(Animation(render, frames=count, fps=10).images(client=client))
    assert render.saw_last == [True]
    # in order, whatever order they were rendered in
    assert [int(np.asarray(im)[0, 0]) for im in images] == list(range(count))


def test_chunks_left_when_the_window_fills_with_finished_ones_are_still_sent():
    """20 frames on 2 workers are 17 chunks, one more than the 16 a render holds in
    flight or waiting.  The first chunk comes back last, after chunks 1-15 (one
    worker of two threads: the second thread renders them while the first waits):
    then none is in flight and 16 wait for their turn, and the 17th must still be
    sent once they are out (CI, 2026-12-06: a GIF rendered on Dask lacked its last
    frame when the first chunk was slow)."""
    distributed = peer("distributed")
    count = 20
    parts = render_module.chunks(range(count), 2)
    assert len(parts) == 17 and list(parts[15]) == [18] and list(parts[16]) == [19]
    render = _Blocked(count, until=18, linger=0.5)
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        images = list(Animation(render, frames=count, fps=10).images(client=client))
    assert render.saw_last == [True]
    assert [int(np.asarray(im)[0, 0]) for im in images] == list(range(count))


def _dies_on_frame_3(i):
    if i == 3:
        os._exit(1)                       # the worker's process ends mid-render
    return np.full((4, 4), i, np.uint8)


def test_a_dying_worker_fails_the_render_naming_the_lost_frames(tmp_path):
    distributed = peer("distributed")
    dask = peer("dask")
    with dask.config.set({"distributed.scheduler.allowed-failures": 1}), \
            distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                     dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        with pytest.raises(render_module.WorkerLost,
                           match=r"frames [0-9, -]+ were lost: .*(died|cancelled)") as caught:
            Animation(_dies_on_frame_3, frames=12, fps=4).save(tmp_path / "x.gif",
                                                               client=client)
    named = str(caught.value).split(" were lost")[0].removeprefix("frames ")
    frames = set()
    for run in named.split(", "):
        first, _, last = run.partition("-")
        frames.update(range(int(first), int(last or first) + 1))
    assert frames and frames <= set(range(12))
    assert not (tmp_path / "x.gif").exists()


def test_frame_runs_in_messages():
    assert render_module._spans([3, 4, 5, 7, 9, 10]) == "3-5, 7, 9-10"
    assert render_module._span(range(8, 16)) == "8-15"
    assert render_module._span([7]) == "7"


def test_chunks_are_sized_to_the_workers_threads(monkeypatch):
    """One worker of three threads runs three chunks at once: the frames are cut for
    three, as for three one-thread workers."""
    distributed = peer("distributed")
    asked = []
    cut = render_module.iter_chunks

    def recorded(indices, parts):
        asked.append(parts)
        return cut(indices, parts)

    monkeypatch.setattr(render_module, "iter_chunks", recorded)
    with distributed.LocalCluster(n_workers=1, threads_per_worker=3, processes=False,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        images = list(Animation(lambda i: np.full((2, 2), i, np.uint8), frames=9,
                                fps=3).images(client=client))
    assert asked == [3]
    assert [int(np.asarray(im)[0, 0]) for im in images] == list(range(9))


def _slow(i):
    time.sleep(0.2)
    return np.full((2, 2), i, np.uint8)


def test_a_cluster_that_loses_its_workers_names_the_frames_still_out():
    """Every worker gone and none coming back (no nanny): the render function went
    with them, the tasks are cancelled, and the frames still out are named (not
    waited for for ever)."""
    distributed = peer("distributed")
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        images = Animation(_slow, frames=40, fps=3).images(client=client)
        assert int(np.asarray(next(images))[0, 0]) == 0
        cluster.scale(0)
        with pytest.raises(render_module.WorkerLost,
                           match=r"frames [0-9, -]+ were lost: their tasks were cancelled"):
            list(images)
