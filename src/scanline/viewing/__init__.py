"""Two-dimensional viewing (notes, syllabus "2-D Viewing"): the window in a viewing
frame with a view-up vector, normalized device coordinates, viewports and the
window-to-viewport transformation, as 3x3 matrices (column vectors).

Pipeline: world --(viewing_matrix = R.T)--> viewing coordinates --(clip against the
window; window_to_viewport)--> normalized device coordinates --(ndc_to_device)-->
device coordinates.  :class:`View` does all of it for one window and viewport.
"""

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


def window_to_ndc(window, keep_aspect=False, align="center"):
    """Viewing coordinates in ``window`` -> normalized device coordinates (the unit
    square); :func:`window_to_viewport` with the viewport (0, 0, 1, 1).

    >>> import scanline as sl
    >>> sl.transform.apply(window_to_ndc((0, 0, 4, 2)), (1, 1)).tolist()
    [0.25, 0.5]
    """
    return window_to_viewport(window, (0.0, 0.0, 1.0, 1.0), keep_aspect, align)


__all__ = ["ALIGNS", "View", "Viewport", "Window", "device_viewport", "ndc_to_device",
           "tile", "viewing_matrix", "window_to_ndc", "window_to_viewport"]
