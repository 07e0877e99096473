"""Every public name annotated and documented in numpydoc sections (issue 32, item 3).

``tests/api_surface.py`` walks what ``import scanline as sl`` offers; this test asserts
that every package of it lacks nothing: annotations of every parameter and
return value, and ``Parameters`` / ``Returns`` / ``Examples`` sections (the examples run
as doctests with the rest of the package's docstrings)."""

import pytest

from tests import api_surface

#: Every package of the public surface (``sl.draw``, ``sl.FrameBuffer``'s
#: ``scanline.framebuffer`` ...): each must lack nothing.
PACKAGES = sorted({".".join(m.split(".")[:2]) for m in api_surface.public_modules()})


def test_the_walker_finds_the_public_surface():
    modules = api_surface.public_modules()
    assert "scanline.draw" in modules and "scanline.framebuffer" in modules
    names = {name for module in modules for name, _, _ in api_surface._members(module)}
    assert {"scanline.draw.line", "scanline.framebuffer.FrameBuffer",
            "scanline.framebuffer.FrameBuffer.save", "scanline.mesh.cube",
            "scanline.mpl.Occlusion.draw"} <= names
    # matplotlib's Artist makes a `set` for each subclass: its own, documented there
    assert "scanline.mpl.Occlusion.set" not in names


def test_the_walker_reports_what_a_bare_function_lacks(tmp_path, monkeypatch):
    import sys
    import types
    module = types.ModuleType("scanline_probe")

    def bare(x, y=1):
        """One line only."""
        return x

    bare.__module__ = "scanline_probe"
    module.bare = bare
    monkeypatch.setitem(sys.modules, "scanline_probe", module)
    monkeypatch.setattr(bare, "__module__", "scanline.probe")
    monkeypatch.setitem(sys.modules, "scanline.probe", module)
    found = {item.what for item in api_surface.lacks("scanline.probe")}
    assert found == {"annotation of x", "annotation of y", "return annotation",
                     "Parameters section", "Examples section"}


@pytest.mark.parametrize("package", PACKAGES)
def test_package_lacks_nothing(package):
    assert [str(item) for item in api_surface.all_lacks((package,))] == []
