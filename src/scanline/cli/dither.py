"""``scanline dither IN OUT [--method M] [--levels N | --palette P]``: show an image
with fewer gray levels or colors (:func:`scanline.color.dither`).

IN is any image Pillow reads; OUT's extension (.png, .jpg, .webp, .gif, .bmp ...) picks the format and
is written atomically.
"""

import os

from ..errors import ArgumentValueError

METHODS = ("floyd-steinberg", "bayer2", "bayer4", "bayer8", "none", "ordered")   # as color.dither.METHODS

PALETTE_HELP = (
    "dither to a color table instead of gray levels (the result is mode P): "
    "'web' (216 web-safe colors), 'rgb332' (256 colors, 3-3-2 bits), 'gray:N' (N gray "
    "levels), 'median-cut:N' (N colors fitted to the image by median cut), or a "
    "comma-separated list of colors such as 'black,white,red,#0000ff'")


def register(subparsers):
    """Add the ``dither`` command."""
    parser = subparsers.add_parser(
        "dither", help="dither an image to a bitmap, a few gray levels or a color table",
        description="Read IN, dither it and write OUT.  By default Floyd-Steinberg to 1 "
        "bit per pixel (a black-and-white bitmap).",
    )
    parser.add_argument("input", metavar="IN", help="the image to read (any format Pillow reads)")
    parser.add_argument("output", metavar="OUT", help="the image to write (any format Pillow writes: .png, .jpg, .webp, .tif, "
                        ".gif, .bmp ...)")
    parser.add_argument("--method", choices=METHODS, default="floyd-steinberg",
                        help="floyd-steinberg (error diffusion, default), bayer2, bayer4, "
                        "bayer8 (ordered dithering; ordered is bayer4) or none (round to the nearest)")
    parser.add_argument("--levels", metavar="N", type=int, default=None,
                        help="gray levels, 2 to 256 (default 2: a bitmap; 4 = 2 bits per pixel)")
    parser.add_argument("--color", action="store_true",
                        help="with --levels: N levels of red, green and blue each "
                        "(an RGB image) instead of N gray levels")
    parser.add_argument("--palette", metavar="P", default=None, help=PALETTE_HELP)
    parser.add_argument("--serpentine", action="store_true",
                        help="floyd-steinberg: scan every other row right to left")
    parser.add_argument("--scale", metavar="N", type=int, default=1,
                        help="enlarge each pixel to an N x N block in the saved image")
    parser.set_defaults(run=run)


def palette_table(text, image):
    """The color table that ``--palette text`` names (``image`` for median cut)."""
    import scanline as sl

    name, _, count = text.partition(":")
    if name in ("web", "rgb332") and not count:
        return sl.color.web_safe_table() if name == "web" else sl.color.rgb332_table()
    if name in ("gray", "median-cut"):
        try:
            n = int(count)
        except ValueError:
            raise ArgumentValueError(
                f"--palette {text!r}: say how many entries, e.g. '{name}:16'") from None
        if name == "gray":
            return sl.color.gray_table(n)
        return sl.color.median_cut_table(image, n)
    return sl.color.color_table([c.strip() for c in text.split(",")], "--palette")


def run(args):
    """Read, dither and save atomically."""
    from PIL import Image

    import scanline as sl
    from .._files import input_path
    from ..framebuffer import check_image_size

    if args.palette is not None and (args.levels is not None or args.color):
        raise ArgumentValueError("give --levels (and --color) or --palette, not both")
    if os.path.isdir(args.output):
        raise ArgumentValueError(f"OUT {args.output!r} is a folder; give a file name")
    input_path(args.input, "readable image")
    try:
        with Image.open(args.input) as image:
            image.load()
            source = sl.FrameBuffer.from_pil(image)
    except Image.DecompressionBombError as exc:
        raise ArgumentValueError(f"IN {args.input!r}: {exc}") from None
    except OSError as exc:
        raise ArgumentValueError(
            f"IN {args.input!r} is not a readable image: {exc.strerror or exc}") from None
    check_image_size(source.width, source.height, args.scale,
                     f"IN's {source.width} x {source.height} pixels with --scale {args.scale}",
                     "use a smaller --scale")
    if args.palette is not None:
        fb = sl.color.dither(source, args.method, palette=palette_table(args.palette, source),
                             serpentine=args.serpentine)
    else:
        fb = sl.color.dither(source, args.method, levels=args.levels,
                             mode="RGB" if args.color else None, serpentine=args.serpentine)
    fb.save(args.output, scale=args.scale)
    print(f"wrote {args.output} ({fb.width} x {fb.height}, mode {fb.mode})")
