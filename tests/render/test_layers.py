"""The 3-D packages depend on one another in one direction (docs/architecture.md):
geometry (mesh, transform3d, projection, clip) knows nothing of rendering; the
preparation (screen) comes before the visible-surface methods (visible), which come
before the shading (shading); the renderer (rendering) orders them all.  Every import
counts, the lazy ones inside functions too."""

import ast
from pathlib import Path

import pytest

import scanline

ROOT = Path(scanline.__file__).resolve().parent

#: The packages of the 3-D half, in the order they may depend on one another.
LAYERS = ["transform3d", "mesh", "projection", "clip", "lighting", "screen", "visible",
          "shading", "rendering"]
#: Imports allowed against that order: none.
GEOMETRY = {"transform3d", "mesh", "projection", "clip"}


def imports_of(package):
    """The scanline packages that the modules of ``package`` import (at any depth)."""
    out = set()
    for path in (ROOT / package).rglob("*.py"):
        tree = ast.parse(path.read_text())
        parts = ("scanline." + str(path.relative_to(ROOT).with_suffix("")).replace("/", ".")
                 ).split(".")
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom):
                if node.level:
                    base = parts[:len(parts) - node.level]
                    name = ".".join(base + ([node.module] if node.module else []))
                else:
                    name = node.module or ""
                names = [name] + [f"{name}.{a.name}" for a in node.names]
            elif isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            else:
                continue
            for n in names:
                bits = n.split(".")
                if len(bits) > 1 and bits[0] == "scanline" and bits[1] in LAYERS:
                    out.add(bits[1])
    out.discard(package)
    return out


@pytest.mark.parametrize("package", LAYERS)
def test_each_package_imports_only_those_before_it(package):
    before = set(LAYERS[:LAYERS.index(package)])
    assert imports_of(package) <= before, imports_of(package) - before


def test_geometry_knows_nothing_of_rendering():
    for package in GEOMETRY:
        assert not imports_of(package) & {"lighting", "screen", "visible", "shading",
                                          "rendering"}, package
