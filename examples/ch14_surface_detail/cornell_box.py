"""Draw docs/images/cornell-box.png: the Cornell box (its published geometry and
colors, ``sl.radiosity.cornell_box``) solved by radiosity -- 10 x 10 patches a face
(1,900 patches), hemicube form factors, Gauss-Seidel -- and rendered through
``sl.render`` by Gouraud shading of the node radiosities, seen from the published
camera.  Run: ``python examples/ch14_surface_detail/cornell_box.py``."""

import os

from scanline.gallery.surface_rendering import cornell_box_image

DOCS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs", "images")


def main():
    image, solution = cornell_box_image(480, subdivisions=10)
    print(solution, f"history: {[f'{x:.1e}' for x in solution.history]}")
    image.save(os.path.join(DOCS, "cornell-box.png"))


if __name__ == "__main__":
    main()
