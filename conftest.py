"""Test-session setup shared by every test (and by the doctests of src/)."""

import os

# The suite tests the compiled kernels: first calls compile rather than run the
# kernels' Python twins (tests/test_first_use.py compares the two explicitly).
os.environ.setdefault("SCANLINE_COMPILE", "always")


def pytest_collection_modifyitems(items):
    """Run the compile-budget tests first: they compile every kernel, two processes in
    parallel, into the cache that the rest of the suite then loads from."""
    first = [item for item in items if item.nodeid.startswith("tests/test_compile_budget.py")]
    items[:] = first + [item for item in items if item not in first]
