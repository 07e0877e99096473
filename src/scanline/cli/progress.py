"""What long commands show while they work: a progress bar (tqdm) on a terminal, one
plain line per item otherwise, and a notice when numba compiles for a while.

Also the worker pool that ``scanline demo`` and ``scanline warmup`` share: numba
compiles kernels one at a time in a process, so both commands spread their work
over processes, each taking whole groups of work (kernels of one group are then
compiled by one process), largest groups first.
"""

import contextlib
import multiprocessing
import os
import queue
import sys
import threading
import time

#: Seconds of compilation after which the notice is printed.
NOTICE_AFTER = 2.0

NOTICE = ("scanline: compiling kernels for first use (numba caches them: later runs "
          "start at once)...")


@contextlib.contextmanager
def announce_compilation(stream=None, after=NOTICE_AFTER):
    """While in this context, print :data:`NOTICE` once on ``stream`` (default: the
    current stderr) if a numba compilation lasts longer than ``after`` seconds.
    Imports numba."""
    from numba.core import event

    listener = _listener(stream, after)
    event.register("numba:compile", listener)
    try:
        yield
    finally:
        event.unregister("numba:compile", listener)
        listener.stop()


def _listener(stream, after):
    """The numba event listener of :class:`announce_compilation`."""
    from numba.core import event

    state = {"depth": 0, "timer": None, "said": False}
    lock = threading.Lock()

    def say():
        with lock:
            if state["depth"] and not state["said"]:
                state["said"] = True
                print(NOTICE, file=sys.stderr if stream is None else stream, flush=True)

    class Listener(event.Listener):
        def on_start(self, ev):
            with lock:
                state["depth"] += 1
                if state["depth"] == 1 and not state["said"]:
                    state["timer"] = threading.Timer(after, say)
                    state["timer"].daemon = True
                    state["timer"].start()

        def on_end(self, ev):
            with lock:
                state["depth"] -= 1
                if state["depth"] == 0:
                    self.stop()

        def stop(self):
            if state["timer"] is not None:
                state["timer"].cancel()
                state["timer"] = None

    return Listener()


class Progress:
    """``update(name)`` after each of ``total`` items: a tqdm bar on a terminal
    (item k of n, its name, elapsed time), else one line per item on ``stream``."""

    def __init__(self, total, label, stream=None):
        self.stream = sys.stderr if stream is None else stream
        self.total = total
        self.label = label
        self.done = 0
        self.start = time.perf_counter()
        self.bar = None
        if getattr(self.stream, "isatty", lambda: False)():
            from tqdm import tqdm
            self.bar = tqdm(total=total, desc=label, unit="", file=self.stream,
                            bar_format="{desc}: {n}/{total} {bar} {elapsed} {postfix}")

    def update(self, name):
        self.done += 1
        if self.bar is not None:
            self.bar.set_postfix_str(name, refresh=False)
            self.bar.update(1)
        else:
            print(f"{self.label}: {self.done}/{self.total} {name} "
                  f"({time.perf_counter() - self.start:.1f} s)", file=self.stream, flush=True)

    def close(self):
        if self.bar is not None:
            self.bar.close()


def kernels_cached(kernels):
    """Whether numba's on-disk cache has an index for each compiled function of
    ``kernels`` (a guess that a run will load rather than compile them: in a warm
    cache one process is quicker than several, which each import numba and
    scanline).  False where the cache cannot be inspected."""
    try:
        return all(os.path.exists(k._cache._cache_file._index_path) for k in kernels)
    except AttributeError:        # uncached, or numba's internals moved
        return False


def cpu_jobs():
    """The default number of worker processes: the cores this process may use."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:          # not on Linux
        return os.cpu_count() or 1


def _worker(work, groups, results):
    """Run ``work(group, report)`` for the groups taken from the queue ``groups`` until
    it is empty; ``report(message)`` puts one message on ``results``."""
    while True:
        try:
            group = groups.get_nowait()
        except queue.Empty:
            results.put(("finished", None))
            return
        try:
            work(group, lambda message: results.put(("item", message)))
        except BaseException as exc:     # reported to the parent, which stops
            results.put(("error", f"{type(exc).__name__}: {exc}"))
            return


def run_groups(work, groups, jobs, on_item):
    """Run ``work(group, report)`` for every group, in ``jobs`` processes (or in this
    one for ``jobs == 1``), the groups in the order given (largest first is best);
    ``on_item(message)`` gets each message a group reports, as it comes.

    ``work`` must be a module-level function (it runs in spawned processes).  An
    error in a worker is raised here as a RuntimeError naming it, after the other
    workers are stopped."""
    if jobs == 1 or len(groups) == 1:
        for group in groups:
            work(group, on_item)
        return
    context = multiprocessing.get_context("spawn")
    todo, results = context.Queue(), context.Queue()
    for group in groups:
        todo.put(group)
    workers = [context.Process(target=_worker, args=(work, todo, results), daemon=True)
               for _ in range(min(jobs, len(groups)))]
    for w in workers:
        w.start()
    running = len(workers)
    try:
        while running:
            try:
                kind, message = results.get(timeout=1.0)
            except queue.Empty:
                if not any(w.is_alive() for w in workers):
                    raise RuntimeError("a worker process stopped without reporting") from None
                continue
            if kind == "item":
                on_item(message)
            elif kind == "finished":
                running -= 1
            else:
                raise RuntimeError(f"a worker failed: {message}")
    finally:
        for w in workers:
            if w.is_alive():
                w.terminate()
            w.join()
