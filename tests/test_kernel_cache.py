"""numba's on-disk cache of the kernels is keyed by every kernel module's source
(:func:`scanline._kernels._jit.sources_stamp`), so that editing a helper in one
module recompiles the kernels of the others that inline or link it, instead of
loading their stale machine code."""

import importlib
import os
import pkgutil
import shutil

from numba.core.dispatcher import Dispatcher

import scanline._kernels as package
from scanline._kernels import _jit


def kernels():
    for info in pkgutil.iter_modules(package.__path__):
        module = importlib.import_module(f"{package.__name__}.{info.name}")
        for value in vars(module).values():
            if isinstance(value, Dispatcher) and value.__module__ == module.__name__:
                yield value


def test_every_kernel_is_cached_under_the_digest_of_all_kernel_modules():
    found = list(kernels())
    assert len(found) > 100
    stamp = _jit.sources_stamp()
    for kernel in found:
        locator = kernel._cache._impl.locator
        assert type(locator).__name__.startswith("Kernels"), kernel
        assert locator.get_source_stamp() == stamp, kernel


def test_the_digest_follows_any_module_s_source_not_its_time(tmp_path):
    folder = tmp_path / "kernels"
    shutil.copytree(os.path.dirname(_jit.__file__), folder,
                    ignore=shutil.ignore_patterns("__pycache__"))
    _jit.sources_stamp.cache_clear()
    try:
        before = _jit.sources_stamp(str(folder))
        helper = folder / "raster3d.py"
        os.utime(helper, (1, 1))                                  # the time alone
        _jit.sources_stamp.cache_clear()
        assert _jit.sources_stamp(str(folder)) == before
        helper.write_text(helper.read_text() + "\n# an edit\n")   # one helper module
        _jit.sources_stamp.cache_clear()
        assert _jit.sources_stamp(str(folder)) != before
        (folder / "notes.txt").write_text("not a module")         # not a source
        helper.write_text(helper.read_text()[:-len("\n# an edit\n")])
        _jit.sources_stamp.cache_clear()
        assert _jit.sources_stamp(str(folder)) == before
    finally:
        _jit.sources_stamp.cache_clear()


def test_functions_elsewhere_keep_numba_s_own_cache_key(tmp_path):
    # a function outside the kernels' folder: numba's locators, its own file's key
    module = tmp_path / "elsewhere.py"
    module.write_text("def f(x):\n    return x + 1\n")
    namespace = {"__file__": str(module)}
    exec(compile(module.read_text(), str(module), "exec"), namespace)
    ours = [c for c in _jit._numba("CacheImpl")._locator_classes
            if c.__name__.startswith("Kernels")]
    assert len(ours) == 3
    for locator in ours:
        assert locator.from_function(namespace["f"], str(module)) is None
