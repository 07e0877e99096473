"""Two-dimensional viewing (notes, syllabus "2-D Viewing"): the window in a viewing
frame with a view-up vector, normalized device coordinates, viewports and the
window-to-viewport transformation, as 3x3 matrices (column vectors).

Pipeline: world --(viewing_matrix = R.T)--> viewing coordinates --(clip against the
window; window_to_viewport)--> normalized device coordinates --(ndc_to_device)-->
device coordinates.  :class:`View` does all of it for one window and viewport.
"""

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .pipeline import (
    ALIGNS,
    View,
    Viewport,
    Window,
    device_viewport,
    ndc_to_device,
    tile,
    viewing_matrix,
    window_to_viewport,
)


def window_to_ndc(window: Window | ArrayLike, keep_aspect: bool = False,
                  align: str = "center") -> NDArray[np.float64]:
    """Viewing coordinates in ``window`` -> normalized device coordinates (the unit
    square); :func:`window_to_viewport` with the viewport (0, 0, 1, 1).

    Parameters
    ----------
    window : Window or (xmin, ymin, xmax, ymax)
        The window in viewing coordinates, with xmin < xmax and ymin < ymax.
    keep_aspect : bool, default False
        Keep the window's proportions (letterbox) instead of filling the unit square.
    align : {"center", "lower-left"}, default "center"
        Where a letterboxed window sits in the unit square.

    Returns
    -------
    ndarray of float64, shape (3, 3)

    Raises
    ------
    ArgumentTypeError, ArgumentValueError
        As :func:`window_to_viewport`: a degenerate window or an unknown ``align``.

    Notes
    -----
    Normalized device coordinates: Hearn & Baker, section 6-2.

    Examples
    --------
    >>> import scanline as sl
    >>> sl.transform.apply(window_to_ndc((0, 0, 4, 2)), (1, 1)).tolist()
    [0.25, 0.5]
    """
    return window_to_viewport(window, (0.0, 0.0, 1.0, 1.0), keep_aspect, align)


__all__ = ["ALIGNS", "View", "Viewport", "Window", "device_viewport", "ndc_to_device",
           "tile", "viewing_matrix", "window_to_ndc", "window_to_viewport"]
