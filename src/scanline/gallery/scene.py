"""
Scene files
===========

Figures of ``scanline demo`` drawn from the scene files in ``examples/scenes``.

Each figure renders one example scene through the display-file interpreter (raster
device) and shows the display file's segment table beside it.  The scene files are
package data (``scanline/data/scenes``; ``examples/scenes`` in the source tree links
to them), so the figures come with every installation.
"""

import os
from importlib import resources

from scanline.gallery.primitives import Figure

#: The folder of example scene files.
EXAMPLES = str(resources.files("scanline") / "data" / "scenes")


def segment_table(scene):
    """The display file's segments as a text table, in drawing order."""
    rows = [("segment", "priority", "visible", "highlighted", "primitives")]
    segments = sorted(scene.display_file.segments, key=lambda s: s.priority)
    for s in segments:
        kinds = ", ".join(p.kind for p in s.primitives)
        rows.append((s.name, f"{s.priority:g}", "yes" if s.visible else "no",
                     "yes" if s.highlighted else "no", kinds))
    widths = [max(len(r[i]) for r in rows) for i in range(4)]
    return "\n".join("  ".join(c.ljust(w) for c, w in zip(r[:4], widths)) + "  " + r[4]
                     for r in rows)


def _figure(stem, title, caption, source):
    def make():
        from scanline.scene import load

        path = os.path.join(EXAMPLES, f"{stem}.toml")
        scene = load(path)
        return Figure(f"scene-{stem}", title,
                      f"{caption} Rendered by 'scanline render examples/scenes/{stem}.toml'.",
                      source, scene.raster().to_pil(), segment_table(scene))

    make.__name__ = f"figure_scene_{stem}"
    make.__doc__ = f"The example scene {stem}.toml: {title}."
    return make


#: The figures, in gallery order.
FIGURES = (
    _figure("translation", "A polygon moved by a translation",
            "The blue polygon's segment is drawn again with the segment transformation "
            "T(-5.5, 3.75): every vertex moves by the translation vector (dashed).",
            "Notes, chapter 3, Q.1"),
    _figure("rotation", "Rotation about a pivot",
            "The triangle turned by 60 degrees about the pivot (6, 4) (asterisk) with the "
            "segment transformation T(xr, yr) R(60) T(-xr, -yr).",
            "Notes, chapter 3, Q.2"),
    _figure("line_clipping", "Lines against a clip window",
            "Left: P1-P2 (below, and left of and above, the window), P3-P4 (crossing "
            "the top and right edges), a line inside and one left of the window. "
            "Right: the viewport that shows only the window clips them.",
            "Notes, chapter 4, Q.3"),
    _figure("polygon_clipping", "Polygon clipping",
            "A concave polygon and the clip window; right, the fill area clipped to the "
            "window by Sutherland-Hodgman (hatched).",
            "Notes, syllabus of chapter 4 (Sutherland-Hodgman)"),
    _figure("viewports", "One world, several viewports",
            "The same segments through three windows: the whole world, a zoom on the "
            "door, and a window with view-up vector (1, 2); the chimney's segment is "
            "highlighted.",
            "Notes, syllabus of chapter 4 (window to viewport)"),
)


if __name__ == "__main__":
    from scanline.gallery import main

    main(FIGURES)
