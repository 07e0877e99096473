"""``scanline warmup [--jobs N] [--modes ...]``: compile every kernel ahead of time.

Makes every call of :data:`scanline.warmup.CALLS`, spread over N processes (whole
groups of calls per process, so that two processes rarely compile the same kernel),
so that numba's on-disk cache holds every kernel: for images built for containers,
CI caches, or a classroom's machines before the first lesson.
"""

import argparse
import time

from .progress import Progress, cpu_jobs, run_groups


def jobs_argument(text):
    """``--jobs``: a whole number of processes, at least 1."""
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value < 1 or str(value) != text.strip():
        raise argparse.ArgumentTypeError(
            f"--jobs must be a whole number of processes, 1 or more, got {text!r}")
    return value


def register(subparsers):
    """Add the ``warmup`` command."""
    from ..warmup import MODES

    parser = subparsers.add_parser(
        "warmup", help="compile every kernel ahead of time (into numba's cache)",
        description="Compile every numba kernel that the drawing functions reach, in every "
        "frame-buffer mode, into numba's on-disk cache, so that later processes start at "
        "once. Useful when building a container image or a CI cache.",
    )
    parser.add_argument("--jobs", type=jobs_argument, default=None, metavar="N",
                        help="worker processes (default: the number of cores)")
    parser.add_argument("--modes", default=",".join(MODES), metavar="M,M",
                        help="frame-buffer modes to compile for, comma-separated "
                        f"(default: all, {','.join(MODES)})")
    parser.set_defaults(run=run)


def warm_group(names, report):
    """Make the warm-up calls ``names`` (one worker's share), reporting each."""
    import os

    from .. import warmup

    modes = tuple(os.environ["SCANLINE_WARMUP_MODES"].split(","))
    warmup.run(names, modes, progress=lambda done, total, name: report(name))


def run(args):
    """Compile every kernel, then say how long it took."""
    import os

    from .. import warmup
    from ..errors import ArgumentValueError

    modes = tuple(m.strip() for m in args.modes.split(",") if m.strip())
    bad = [m for m in modes if m not in warmup.MODES]
    if bad or not modes:
        raise ArgumentValueError(
            f"--modes must name frame-buffer modes among {', '.join(warmup.MODES)}, "
            f"got {args.modes!r}")
    jobs = args.jobs or cpu_jobs()
    os.environ["SCANLINE_WARMUP_MODES"] = ",".join(modes)   # inherited by the workers
    total = sum(1 for _ in warmup.cases(None, modes))
    progress = Progress(total, "scanline warmup")
    t0 = time.perf_counter()
    try:
        run_groups(warm_group, warmup.by_group(modes), jobs, progress.update)
    finally:
        progress.close()
    print(f"scanline warmup: {total} calls compiled or loaded in "
          f"{time.perf_counter() - t0:.1f} s with {jobs} process{'es' if jobs > 1 else ''}")
