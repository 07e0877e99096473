"""The display file, its interpreter and its devices (notes, chapter 1, Q.3; syllabus
of chapter 2: display file, display-file interpreter, normalized device coordinates).

A :class:`DisplayFile` stores named segments of primitives in normalized device
coordinates; :func:`interpret` walks it and drives a device: :class:`RasterDevice`
(a frame buffer, saved as PNG or GIF), :class:`VectorDevice` (the MOVE/LINE commands
of a random-scan display) or :class:`SVGDevice`.

>>> import scanline as sl
>>> df = sl.DisplayFile()
>>> df.set_viewing(window=(0, 0, 10, 10))
>>> df.create_segment("square")
>>> df.polyline([(2, 2), (8, 2), (8, 8), (2, 8)], closed=True)
>>> df.close_segment()
>>> vector = sl.display.VectorDevice(101, 101)
>>> sl.display.interpret(df, vector)
>>> print(vector.listing(), end="")
; random-scan display file, 101 x 101 device units
COLOR 255 255 255 255
MOVE 20 20
LINE 80 20
LINE 80 80
LINE 20 80
LINE 20 20
"""

from .devices import RasterDevice, SVGDevice, VectorDevice
from .file import DisplayFile, Segment
from .interpreter import interpret

__all__ = ["DisplayFile", "Segment", "interpret", "RasterDevice", "VectorDevice", "SVGDevice"]
