"""A studio worker process (``python -m scanline.studio.worker FD ADDRESS_SPACE``), started
by :class:`scanline.studio.pool.Pool`: it runs the studio's expensive requests, one at
a time, and is killed when one passes its time limit.

It ignores Ctrl-C (the server kills it), exits when its server has gone, warms up
the kernels the pages use, limits its address space to what it then holds plus
``ADDRESS_SPACE`` bytes, says ``("ready", pid)`` and answers each ``(task, args)``
with ``("ok", result)``, ``("bad", message)`` (the API refused the input),
``("memory", message)`` (then it exits: the pool starts a fresh one) or
``("error", text)`` (a bug; the traceback goes to stderr).  Results are bytes
(JSON, PNG, raw frames) so that the server only forwards them.
"""

from __future__ import annotations

import os
import re
import signal
import sys
import threading
import time
import traceback
from multiprocessing.connection import Connection
from typing import Any, Callable, Mapping

import orjson

from ..errors import ScanlineError


def explore(algorithm: str, args: list[str], limit_bytes: float | None) -> bytes:
    """The explorer's view, as JSON."""
    from . import explorer

    return orjson.dumps(explorer.explore(algorithm, args, limit_bytes=limit_bytes))


def device_info(kind: str, query: Mapping[str, str]) -> bytes:
    from . import devices

    return orjson.dumps(devices.info(devices.simulation(kind, query)))


def device_frame(kind: str, query: Mapping[str, str], t: float) -> tuple[bytes, Any]:
    from . import devices

    return devices.frame(devices.simulation(kind, query), t)


def device_plane(k: int) -> bytes:
    from . import devices

    return devices.plane_png(k)


def quiz(algorithm: str, seed: int) -> bytes:
    """Quiz case ``seed`` of ``algorithm``: the view with its questions, as JSON."""
    from . import quiz as quizzes

    return orjson.dumps(quizzes.quiz(algorithm, quizzes.case(algorithm, seed)))


#: The tasks a worker runs, by name: each returns what the server forwards.
TASKS: dict[str, Callable[..., Any]] = {"explore": explore, "quiz": quiz, "device_info": device_info, "device_frame": device_frame,
         "device_plane": device_plane}


def warm_up() -> None:
    """Compile (or load from numba's cache) what the pages reach first."""
    from . import devices, explorer

    devices.frame_buffer()
    devices.frame(devices.simulation("raster", {}), 0.0)
    for name in ("bresenham", "midpoint-circle", "cohen-sutherland", "flood-fill"):
        explorer.explore(name, explorer.DEFAULTS[name])


def _address_space() -> int | None:
    """This process's address space in bytes (None where /proc cannot tell)."""
    try:
        with open("/proc/self/status") as f:
            match = re.search(r"VmSize:\s+(\d+)\s*kB", f.read())
    except OSError:
        return None
    return int(match.group(1)) * 1024 if match else None


def limit_memory(extra: int) -> None:
    """Limit this process's address space to what it holds now plus ``extra`` bytes."""
    try:
        import resource
    except ImportError:  # pragma: no cover - not POSIX
        return
    now = _address_space()
    if extra > 0 and now:
        _, hard = resource.getrlimit(resource.RLIMIT_AS)
        soft = now + extra
        if hard != resource.RLIM_INFINITY:
            soft = min(soft, hard)
        resource.setrlimit(resource.RLIMIT_AS, (soft, hard))


def _watch(parent: int) -> None:
    """Exit as soon as the server that started this worker has gone."""
    while True:
        if os.getppid() != parent:
            os._exit(1)
        time.sleep(0.5)


def _bad() -> tuple[type[Exception], ...]:
    from .explorer import BadArguments

    return (ScanlineError, ValueError, TypeError, KeyError, BadArguments)


def serve(conn: Connection, address_space: int) -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    threading.Thread(target=_watch, args=(os.getppid(),), daemon=True,
                     name="scanline-worker-watch").start()
    warm_up()
    bad = _bad()
    limit_memory(address_space)
    try:
        conn.send(("ready", os.getpid()))
    except OSError:           # the server went away while this worker started
        return
    while True:
        try:
            task, args = conn.recv()
        except (EOFError, OSError):
            return
        done = False
        try:
            reply = ("ok", TASKS[task](*args))
        except MemoryError:
            reply, done = ("memory", "out of memory"), True
        except bad as error:
            message = error.args[0] if isinstance(error, KeyError) and error.args else error
            reply = ("bad", " ".join(str(message).split()))
        except Exception as error:  # noqa: BLE001 - a bug: reported, the worker goes on
            traceback.print_exc()
            reply = ("error", f"{type(error).__name__}: {error}")
        try:
            conn.send(reply)
        except MemoryError:
            conn.send(("memory", "out of memory"))
            done = True
        except OSError:       # the server went away (or gave up on this task)
            return
        if done:
            return


def main(argv: list[str] | None = None) -> None:
    argv = sys.argv[1:] if argv is None else argv
    conn = Connection(int(argv[0]))
    serve(conn, int(argv[1]) if len(argv) > 1 else 0)


if __name__ == "__main__":
    main()
