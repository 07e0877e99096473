"""Test-session setup shared by every test module."""


def pytest_collection_modifyitems(items):
    """Run the compile-budget tests first: they compile every kernel, two processes in
    parallel, into the cache that the rest of the suite then loads from."""
    first = [item for item in items if item.nodeid.startswith("tests/test_compile_budget.py")]
    items[:] = first + [item for item in items if item not in first]
