"""Scene files: a picture described in TOML or JSON (one schema, ``version = 1``).

A scene gives the canvas, the world window and viewports (with view-up vectors), and
segments of primitives with attributes and transformations; :func:`load` checks it
and builds a :class:`~scanline.DisplayFile`, and :meth:`Scene.render` writes a PNG,
GIF, SVG or vector listing.  The format is documented in docs/scene-format.md.

>>> import scanline as sl
>>> scene = sl.scene.loads('''
... version = 1
... canvas = {width = 7, height = 5, background = "black"}
... [[segments]]
... name = "triangle"
... primitives = [{type = "polygon", points = [[0, 0], [6, 0], [3, 4]]}]
... ''')
>>> print(sl.text_image(scene.raster()))
-------
---#---
--###--
-#####-
-------
"""

from .files import SceneError, dumps, read
from .files import loads as parse
from .scene import Scene, load, loads
from .animated import AnimatedScene
from .animated import load as load_animated
from .animated import loads as loads_animated
from .examples import copy_examples, example, examples

__all__ = ["Scene", "SceneError", "load", "loads", "parse", "read", "dumps", "AnimatedScene",
           "load_animated", "loads_animated", "example", "examples", "copy_examples"]
