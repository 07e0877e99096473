"""Test-session setup shared by every test (and by the doctests of src/)."""

import json
import os
import tempfile

import pytest

# The suite tests the compiled kernels: first calls compile rather than run the
# kernels' Python twins (tests/test_first_use.py compares the two explicitly).
os.environ.setdefault("SCANLINE_COMPILE", "always")

#: Where the whole suite's first step recorded every kernel's specializations (read by
#: tests/test_compile_budget.py instead of compiling them again).
KERNELS = "SCANLINE_TEST_KERNELS"


@pytest.hookimpl(tryfirst=True)
def pytest_sessionstart(session):
    """The whole suite (``pytest`` without paths): compile every kernel first, two
    processes in parallel, into the cache that every test then loads from, and keep
    the specializations they counted for tests/test_compile_budget.py.  This runs in
    the main process before pytest-xdist starts its workers (``-n``), so no test
    waits for a compilation that another is doing, and none sees the first-use notice
    of a command that compiles."""
    config = session.config
    if (hasattr(config, "workerinput") or KERNELS in os.environ
            or config.args_source != pytest.Config.ArgsSource.TESTPATHS):
        return
    from tests.test_compile_budget import specializations

    reporter = config.pluginmanager.get_plugin("terminalreporter")
    if reporter is not None:
        reporter.write_line("compiling every kernel first (two processes) ...")
    record = tempfile.NamedTemporaryFile("w", prefix="scanline-kernels-", suffix=".json",
                                         delete=False)
    with record:
        json.dump(specializations(jobs=2), record)
    os.environ[KERNELS] = record.name
    config._scanline_kernels = record.name


def pytest_sessionfinish(session):
    """Remove the record :func:`pytest_sessionstart` wrote."""
    path = getattr(session.config, "_scanline_kernels", None)
    if path is not None:
        os.environ.pop(KERNELS, None)
        os.unlink(path)


def pytest_collection_modifyitems(items):
    """Run the compile-budget tests first when they compile the kernels themselves (a
    run given paths): two processes in parallel fill the cache that the rest of the
    suite then loads from."""
    first = [item for item in items if item.nodeid.startswith("tests/test_compile_budget.py")]
    items[:] = first + [item for item in items if item not in first]
