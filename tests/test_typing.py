"""Types for editors and type checkers (issue 16, item 4): the lazy attributes are
visible to type checkers through ``import scanline as sl``, and the annotated entry
points flag wrong calls.  (``mypy`` on the stated --strict subset of pyproject.toml is
a step of .ci/run.)"""

import ast
import os
import subprocess
import sys
from pathlib import Path

import pytest

import scanline

ROOT = Path(scanline.__file__).resolve().parent


def test_type_checking_block_names_every_lazy_attribute():
    tree = ast.parse((ROOT / "__init__.py").read_text())
    block = next(node for node in tree.body if isinstance(node, ast.If)
                 and getattr(node.test, "id", None) == "TYPE_CHECKING")
    names = {alias.asname for node in block.body for alias in node.names}
    assert all(alias.asname == alias.name for node in block.body for alias in node.names)
    assert names == set(scanline._LAZY)


WRONG = '''
import scanline as sl
fb = sl.FrameBuffer(16, 16, mode="RGB")
sl.draw.circle(fb, 1, 2)
sl.draw.line(fb, 0, 0, 5, 5, method="midpoint")
sl.FrameBuffer(4, 4, mode="XYZ")
sl.draw.polygon(fb, [(0, 0), (4, 0), (0, 4)], rule="odd")
sl.draw.nosuch(fb)
cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0))
sl.render(fb, sl.mesh.cube(), cam, material=None)
sl.draw.rectangle(fb, 0, 0, 5)
fb.resize(8, 8, resample="cubic")
'''
RIGHT = '''
import math
import scanline as sl
fb = sl.FrameBuffer(16, 16, mode="L", background="white")
sl.draw.circle(fb, 8, 8, 5, color=(0.2, 0.4, 1.0), width=2, cap="round")
sl.draw.line(fb, 0, 0, 5, 5, method="dda", join="bevel")
sl.draw.polygon(fb, [(0, 0), (4, 0), (0, 4)], rule="nonzero")
image = fb.to_array()
rows: int = image.shape[0]
fb.save("out.png")
sl.draw.text(fb, 1, 1, "Hi", angle="30deg")
table = sl.trace.bresenham(0, 0, 3, 7)
print(math.pi, rows, table, sl.ScanlineError, sl.Camera, sl.AngleWarning)
cam = sl.Camera(eye=(3, 2, 4), target=(0, 0, 0),
                projection=sl.projection.perspective(fov=0.8, near=1))
meshes = [sl.mesh.cube(), sl.mesh.sphere(0.6, (0.8, 0.5, 0.8))]
r = sl.render(fb, meshes, cam, method="z-buffer", shading="phong",
              lights=[sl.lighting.AmbientLight(0.2)], materials=sl.lighting.Material())
faces: int = int(r.faces.max())
print(r.depth, faces, r.meshes)
sl.draw.rectangle(fb, 1, 1, 9, 9, color="red", fill=True, width=2, join="round")
sl.draw.rounded_rectangle(fb, 1, 1, 14, 14, 3, fill=(0.5, 0.5, 0.5),
                          fill_style=sl.FillStyle.hollow())
sl.draw.regular_polygon(fb, 8, 8, 6, 5, rotation="18deg", color="blue")
sl.draw.point(fb, 3, 3)
sl.draw.points(fb, [(1, 1), (2, 2)])
part = fb.crop(0, 0, 7, 7).resize(16, 16, resample="bilinear").copy()
part[2, 2] = "red"
font_file: str = sl.text.find_font("DejaVu Sans")
print(part[1, 1], sl.ColorScaleWarning, font_file)
'''


def mypy(source, tmp_path, cache):
    if subprocess.run([sys.executable, "-c", "import mypy"]).returncode != 0:
        if os.environ.get("CI") == "true":
            pytest.fail("mypy is not installed (it is in the test extra)")
        pytest.skip("mypy is not installed")
    (tmp_path / "usage.py").write_text(source)
    proc = subprocess.run([sys.executable, "-m", "mypy", "--follow-imports=silent",
                           "--cache-dir", str(cache), "--no-error-summary",
                           "usage.py"], cwd=tmp_path, capture_output=True, text=True, timeout=600)
    return proc.stdout.splitlines()


def test_mypy_flags_wrong_calls_and_accepts_right_ones(tmp_path):
    cache = tmp_path / "cache"           # one cache: the second run reuses the first's
    got = [g for g in mypy(WRONG, tmp_path, cache) if ": note: " not in g]   # errors only
    expected = [
        (4, 'Missing positional argument "r" in call to "circle"'),
        (5, 'Argument "method" to "line" has incompatible type "Literal[\'midpoint\']"'),
        (6, 'Argument "mode" to "FrameBuffer" has incompatible type "Literal[\'XYZ\']"'),
        (7, 'Argument "rule" to "polygon" has incompatible type "Literal[\'odd\']"'),
        (8, 'Module has no attribute "nosuch"'),
        (10, 'Unexpected keyword argument "material" for "render"'),
        (11, 'Missing positional argument "y1" in call to "rectangle"'),
        (12, 'Argument "resample" to "resize" of "FrameBuffer" has incompatible type '
             '"Literal[\'cubic\']"'),
    ]
    for line, message in expected:
        assert any(g.startswith(f"usage.py:{line}: error: {message}") for g in got), (message, got)
    assert len(got) == len(expected), got
    assert mypy(RIGHT, tmp_path, cache) == []
