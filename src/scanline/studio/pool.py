"""The studio's worker processes: where its expensive requests run, so that one past
its time limit can be stopped.

A thread cannot be stopped from outside; a process can.  Each worker is a child
process (``python -m scanline.studio.worker``) that imports the explorer and the
device simulations, compiles (or loads from numba's cache) what they use, says it is
ready, then runs one task at a time sent over a socket pair.  A request takes an idle
worker, sends its task and waits for the answer until its deadline; past it the worker
is killed (SIGKILL: its CPU is free at once, whatever it was doing, numba kernels
included) and a fresh one is started in its place.

* At most :data:`WORKERS` expensive requests run at once; up to :data:`MAX_WAITING`
  more wait, each at most :data:`QUEUE_WAIT` seconds, in the order they came; the rest
  are answered 503 at once.  (While no worker has become ready, as when the studio has
  just started and compiles its kernels, requests wait up to :data:`START_WAIT`.)
* Each worker's address space is limited (``RLIMIT_AS``) to what it holds when ready
  plus :data:`ADDRESS_SPACE`: behind the requests' memory estimates, a wrong estimate
  ends in a ``MemoryError`` in the worker (answered 422, the worker replaced), not in a
  machine out of memory.
* Workers run in their own session, so Ctrl-C in the terminal reaches only the server,
  which kills them (:meth:`Pool.close`, safe to call from a signal handler); a worker
  whose server has gone (killed) notices within half a second and exits.
"""

from __future__ import annotations

import os
import pickle
import signal
import socket
import subprocess
import sys
import threading
import time
from multiprocessing.connection import Connection
from typing import Any

import anyio

#: Worker processes: the most expensive requests that run at once.
WORKERS = 2
#: Bytes of address space a worker may add to what it holds when ready (its
#: ``RLIMIT_AS``); 0: no limit.
ADDRESS_SPACE = 1 << 30
#: Seconds a request waits for a free worker before it is answered 503 (busy).
QUEUE_WAIT = 5.0
#: Requests that may wait for a worker at once; more are answered 503 at once.
MAX_WAITING = 16
#: Seconds a request waits while no worker is ready yet (the first start compiles the
#: kernels, on an empty numba cache).
START_WAIT = 180.0
#: Workers that fail to start in a row before the pool gives up (503 from then on).
MAX_START_FAILURES = 3


class PoolError(Exception):
    """A request the pool could not serve; ``status`` is the HTTP status to answer."""

    def __init__(self, status: int, message: str) -> None:
        super().__init__(message)
        self.status = status


class Refused(PoolError):
    """The task's own error (bad input): ``status`` 422, the API's message."""


def _package_root() -> str:
    import scanline

    return os.path.dirname(os.path.dirname(os.path.abspath(scanline.__file__)))


class _Worker:
    """One worker process and its end of the socket pair."""

    def __init__(self, address_space: int) -> None:
        ours, theirs = socket.socketpair()
        env = dict(os.environ)
        env["PYTHONPATH"] = os.pathsep.join(p for p in (_package_root(), env.get("PYTHONPATH"))
                                            if p)
        try:
            self.proc = subprocess.Popen(
                [sys.executable, "-m", "scanline.studio.worker", str(theirs.fileno()),
                 str(int(address_space))],
                pass_fds=(theirs.fileno(),), stdin=subprocess.DEVNULL,
                stdout=subprocess.DEVNULL, start_new_session=True, env=env)
        finally:
            theirs.close()
        self.conn = Connection(ours.detach())
        self.state = "starting"       # -> "idle" <-> "busy"; "dead" once killed
        self.started = time.monotonic()

    @property
    def pid(self) -> int:
        return self.proc.pid

    def ready(self) -> bool | None:
        """Whether a starting worker has said it is ready (True), is still starting
        (False) or failed (None)."""
        try:
            if not self.conn.poll(0):
                return None if self.proc.poll() is not None else False
            said: object = self.conn.recv()
            return said == ("ready", self.proc.pid) or None
        except (EOFError, OSError, pickle.UnpicklingError):
            return None

    def kill(self) -> None:
        """SIGKILL, without waiting or locking (safe in a signal handler)."""
        self.state = "dead"
        try:
            os.kill(self.proc.pid, signal.SIGKILL)
        except OSError:
            pass

    def reap(self) -> None:
        self.kill()
        try:
            self.proc.wait(5)
        except subprocess.TimeoutExpired:  # pragma: no cover - SIGKILL is not refused
            pass
        try:
            self.conn.close()
        except OSError:  # pragma: no cover
            pass

    def call(self, task: str, args: tuple[Any, ...], timeout: float) -> tuple[Any, ...] | None:
        """Run ``task(*args)`` in the worker; the reply, or None past ``timeout``
        seconds (the caller kills the worker)."""
        self.conn.send((task, args))
        if not self.conn.poll(max(timeout, 0.0)):
            return None
        reply: tuple[Any, ...] = self.conn.recv()
        return reply


class Pool:
    """:data:`WORKERS` worker processes serving tasks by name (see
    :mod:`scanline.studio.worker`); see the module's description."""

    def __init__(self, size: int | None = None, address_space: int | None = None) -> None:
        self.size = WORKERS if size is None else int(size)
        self.address_space = ADDRESS_SPACE if address_space is None else int(address_space)
        self._lock = threading.Lock()
        self._workers: list[_Worker] = []
        self._queue: list[object] = []    # waiting requests, first come first served
        self._closed = False
        self._started = False
        self._failures = 0
        self.replaced = 0             # workers killed and replaced (timeouts, crashes)

    # -- life cycle ---------------------------------------------------------------------
    def start(self) -> None:
        """Start the workers (they get ready in the background)."""
        with self._lock:
            if self._started or self._closed:
                return
            self._started = True
            for _ in range(self.size):
                self._workers.append(_Worker(self.address_space))

    def close(self) -> None:
        """Kill every worker and refuse new tasks.  Takes no lock, so that a signal
        handler may call it while the interrupted thread holds one; :meth:`reap`
        collects the processes afterwards."""
        self._closed = True
        for w in list(self._workers):
            w.kill()

    def reap(self) -> None:
        """Close, then wait for the killed workers."""
        self.close()
        with self._lock:
            workers, self._workers = self._workers, []
        for w in workers:
            w.reap()

    @property
    def closed(self) -> bool:
        return self._closed

    def pids(self) -> list[int]:
        """The process ids of the live workers (for tests and the curious)."""
        return [w.pid for w in list(self._workers) if w.state != "dead"]

    def busy_pids(self) -> list[int]:
        return [w.pid for w in list(self._workers) if w.state == "busy"]

    def _replace(self, worker: _Worker) -> None:
        """Kill ``worker`` (if alive) and start another in its place."""
        worker.reap()
        with self._lock:
            if worker in self._workers:
                self._workers.remove(worker)
            if not self._closed:
                self._workers.append(_Worker(self.address_space))
                self.replaced += 1

    # -- taking a worker ------------------------------------------------------------------
    def _take(self, ticket: object) -> tuple[_Worker | None, bool]:
        """An idle worker for the request holding ``ticket`` if it is first in line;
        starting workers that have become ready turn idle; failed ones are replaced."""
        failed: list[_Worker] = []
        with self._lock:
            for w in self._workers:
                if w.state == "starting":
                    ok = w.ready()
                    if ok:
                        w.state = "idle"
                        self._failures = 0
                    elif ok is None:
                        failed.append(w)
            for w in failed:
                self._failures += 1
                self._workers.remove(w)
                w.kill()
                if self._failures < MAX_START_FAILURES and not self._closed:
                    self._workers.append(_Worker(self.address_space))
            taken = None
            if self._queue and self._queue[0] is ticket:
                taken = next((w for w in self._workers if w.state == "idle"), None)
                if taken is not None:
                    taken.state = "busy"
                    self._queue.pop(0)
            working = any(w.state in ("idle", "busy") for w in self._workers)
        for w in failed:
            w.reap()
        return taken, working

    async def _acquire(self) -> _Worker:
        if self._closed:
            raise PoolError(503, "the studio is stopping")
        self.start()
        ticket = object()
        with self._lock:
            idle = sum(1 for w in self._workers if w.state == "idle")
            if len(self._queue) >= MAX_WAITING + idle:
                raise PoolError(503, f"the studio is busy: {self.size} requests are running "
                                     f"and {MAX_WAITING} are waiting; try again shortly")
            self._queue.append(ticket)
        t0 = time.monotonic()
        try:
            while True:
                worker, working = self._take(ticket)
                if worker is not None:
                    return worker
                if self._closed:
                    raise PoolError(503, "the studio is stopping")
                if self._failures >= MAX_START_FAILURES:
                    raise PoolError(503, "the studio's worker processes failed to start; "
                                         "see the server's error output")
                waited = time.monotonic() - t0
                if (working and waited > QUEUE_WAIT) or waited > START_WAIT:
                    raise PoolError(503, f"the studio is busy (waited {waited:.1f} s for one of "
                                         f"its {self.size} workers); try again shortly")
                await anyio.sleep(0.005 if waited < 0.1 else 0.02)
        finally:
            with self._lock:
                if ticket in self._queue:
                    self._queue.remove(ticket)

    # -- running a task -------------------------------------------------------------------
    async def run(self, task: str, args: tuple[Any, ...], timeout: float) -> Any:
        """The result of ``task(*args)`` in a worker, within ``timeout`` seconds of
        work (waiting for a worker not counted).  Raises :class:`Refused` (the task's
        own error: 422), or :class:`PoolError` 503 (past the time limit: the worker is
        killed; busy; stopping) or 500 (a bug, printed by the worker)."""
        worker = await self._acquire()
        reply: tuple[Any, ...] | None = None
        try:
            reply = await anyio.to_thread.run_sync(worker.call, task, args, timeout,
                                                   abandon_on_cancel=True)
        except (EOFError, OSError, pickle.PicklingError, pickle.UnpicklingError):
            reply = ("died",)
        finally:
            if reply is None or reply[0] in ("died", "memory"):
                # past the deadline, cancelled, crashed or out of memory: never reuse it
                with anyio.CancelScope(shield=True):
                    await anyio.to_thread.run_sync(self._replace, worker)
            else:
                worker.state = "idle"
        if reply is None:
            raise PoolError(503, f"the request took longer than {timeout:g} s and was "
                                 "stopped; ask for a smaller case")
        kind = reply[0]
        if kind == "ok":
            return reply[1]
        if kind == "bad":
            raise Refused(422, reply[1])
        if kind == "memory":
            raise Refused(422, "the request needs more memory than the studio allows one "
                               f"request ({self.address_space:,} bytes more per worker); "
                               "ask for a smaller case")
        if kind == "died":
            if self._closed:
                raise PoolError(503, "the studio is stopping")
            raise PoolError(503, "the worker process stopped unexpectedly; try again")
        raise PoolError(500, f"internal error in the studio's worker: {reply[1]}")
