"""Surface detail (Hearn & Baker, sections 14-8 and 14-9): textures mapped by texture
coordinates with mipmaps and filters (:class:`Texture`), procedural textures
(checker, and marble and wood from Perlin's noise), and the maps the shading applies
through :class:`scanline.lighting.Material`: ``texture=`` (the diffuse color),
``bump=`` (Blinn's bump mapping) and ``environment=`` (a cube map, :class:`CubeMap`,
or a latitude-longitude map).  See docs/surface-rendering.md.
"""

from .cubemap import CubeMap
from .mipmap import halved, pyramid
from .noise import noise, turbulence
from .procedural import checker, marble, wood
from .texture import FILTERS, WRAPS, Texture

__all__ = ["CubeMap", "FILTERS", "Texture", "WRAPS", "checker", "halved", "marble", "noise", "pyramid",
           "turbulence", "wood"]
