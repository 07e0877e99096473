"""``scanline trace ALGORITHM ARGS... [--format table|csv|json]``: print a step table.

The tables come from :mod:`scanline.trace`, which runs the same algorithm that
:mod:`scanline.draw` uses to draw.
"""

import argparse

#: CLI name -> (description, positional arguments with their help, takes --center).
#: The names are those of :data:`scanline.trace.ALGORITHMS` (a test checks this; the
#: list is spelled out here so that building the parser does not import numba).
ALGORITHMS = {
    "bresenham": (
        "Bresenham's line algorithm (notes, chapter 2, Q.2-Q.3)",
        {"X0": "x of the first endpoint", "Y0": "y of the first endpoint",
         "X1": "x of the second endpoint", "Y1": "y of the second endpoint"},
        False,
    ),
    "dda": (
        "the DDA line algorithm (notes, chapter 2, Q.1 and Q.7)",
        {"X0": "x of the first endpoint", "Y0": "y of the first endpoint",
         "X1": "x of the second endpoint", "Y1": "y of the second endpoint"},
        False,
    ),
    "midpoint-circle": (
        "the midpoint circle algorithm, one octant (notes, chapter 2, Q.4-Q.5)",
        {"R": "radius, >= 0"},
        True,
    ),
    "midpoint-ellipse": (
        "the midpoint ellipse algorithm, regions 1 and 2 (notes, chapter 2, Q.6)",
        {"RX": "semi-axis along x, >= 0", "RY": "semi-axis along y, >= 0"},
        True,
    ),
    "flood-fill": (
        "the scan-line seed fill with its stack (notes, chapter 2, Q.8)",
        {"X": "x of the seed (0 = left column of the grid)",
         "Y": "y of the seed (0 = bottom row of the grid)"},
        False,
    ),
    "boundary-fill": (
        "the scan-line boundary fill with its stack (notes, chapter 2, Q.8)",
        {"X": "x of the seed (0 = left column of the grid)",
         "Y": "y of the seed (0 = bottom row of the grid)"},
        False,
    ),
    "scan-line-fill": (
        "the scan-line polygon fill: edge table, active edge list, spans (notes, chapter 2, "
        "Q.8)", {}, False,
    ),
    "de-casteljau": (
        "de Casteljau's triangle for a Bezier curve (notes, chapter 5, Q.1)", {}, False,
    ),
    "cox-de-boor": (
        "the Cox-de Boor recursion of the B-spline blending functions (notes, chapter 5, Q.2)",
        {}, False,
    ),
    "cohen-sutherland": (
        "Cohen-Sutherland line clipping with region codes (notes, chapter 4, Q.3)", {}, False,
    ),
    "liang-barsky": (
        "Liang-Barsky line clipping: p_k, q_k, u1, u2 (notes, chapter 4, Q.4)", {}, False,
    ),
    "cyrus-beck": (
        "Cyrus-Beck line clipping against a convex polygon (notes, chapter 4, Q.4, Table 1)",
        {}, False,
    ),
    "sutherland-hodgman": (
        "Sutherland-Hodgman polygon clipping, boundary by boundary (notes, chapter 4)",
        {}, False,
    ),
    "cohen-sutherland-3d": (
        "3-D Cohen-Sutherland clipping with six-bit region codes (Hearn & Baker 12-5)", {},
        False,
    ),
    "liang-barsky-3d": (
        "3-D Liang-Barsky clipping: p_k, q_k, u1, u2 for six planes (Hearn & Baker 12-5)",
        {}, False,
    ),
    "z-buffer": (
        "the depth-buffer method along one scan line: depths compared, the winner "
        "(Hearn & Baker 13-3)", {}, False,
    ),
    "depth-sort": (
        "depth sorting: the five overlap tests, reordering and splitting (Hearn & Baker 13-6)",
        {}, False,
    ),
    "floating-horizon": (
        "the floating horizon: upper and lower horizons per curve (Rogers 4-2)", {}, False,
    ),
    "ray-tracing": (
        "recursive ray tracing: one pixel's ray tree, reflected, refracted and shadow rays "
        "and the intensities summed (Whitted 1980, Hearn & Baker 14-6)",
        {"X": "x of the pixel (0..31 of the built-in 32 x 24 scene)",
         "Y": "y of the pixel (0..23, bottom row 0)"}, False,
    ),
    "back-face": (
        "the back-face test: V . N for each face of a cube (Hearn & Baker 13-2)", {}, False,
    ),
    "bsp-tree": (
        "the BSP tree: splitting planes, front and back lists, splits, then the traversal "
        "back to front from the eye (Hearn & Baker 13-7)", {}, False,
    ),
    "warnock": (
        "Warnock's area subdivision: each area, the class of each polygon (surrounding, "
        "overlapping, inside, outside) and the decision (Hearn & Baker 13-8)", {}, False,
    ),
    "scan-line-visible": (
        "the scan-line method of visible surfaces: active edges, polygon flags, depths "
        "compared where spans overlap (Hearn & Baker 13-5)", {}, False,
    ),
    "ray-casting": (
        "ray casting along one scan line: per pixel the triangles its ray meets, their "
        "depths and the nearest (Hearn & Baker 13-10)", {}, False,
    ),
    "inbetween-spacing": (
        "in-betweens of two key frames spaced by a law of motion: constant, accelerate, "
        "decelerate, both, or an easing (notes, chapter 6; Hearn & Baker 16-5)", {}, False,
    ),
    "morph-equalize": (
        "morphing: two key-frame polygons given equal vertex counts, the vertices added, "
        "the in-between shape (notes, chapter 6, Q4; Hearn & Baker 16-5)", {}, False,
    ),
    "gouraud": (
        "Gouraud shading along one scan line: vertex intensities interpolated (Hearn & "
        "Baker 14-5)", {}, False,
    ),
    "phong": (
        "Phong shading along one scan line: normals interpolated, the model per pixel "
        "(Hearn & Baker 14-5)", {}, False,
    ),
}


def fill_options(sub):
    """``--grid`` and ``--connectivity`` of ``flood-fill`` (and ``--boundary`` of
    ``boundary-fill``); returns their names."""
    sub.add_argument("--grid", help="rows of characters, top row first, separated by '/' "
                     "(e.g. '#####/#..##/#...#/#####'); each character is a color; "
                     "default: a built-in example with two rooms")
    sub.add_argument("--connectivity", type=integer, choices=(4, 8), default=4,
                     help="4 (default): edge neighbors; 8: edge and corner neighbors")
    if sub.prog.endswith("boundary-fill"):
        sub.add_argument("--boundary", default="#", help="the boundary color(s): grid "
                         "characters (default '#')")
        return ["grid", "connectivity", "boundary"]
    return ["grid", "connectivity"]


#: Algorithms with options of their own: CLI name -> function that adds them to the
#: sub-command's parser and returns their names (passed on as keywords).
OPTIONS = {"flood-fill": fill_options, "boundary-fill": fill_options}


def numbers(text):
    """argparse type: numbers separated by commas or spaces, such as ``0,0,1,2``."""
    try:
        return [float(t) for t in text.replace(",", " ").split()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a list of numbers") from None


def de_casteljau_options(sub):
    """The control points and ``--u`` of ``de-casteljau``."""
    sub.add_argument("points", metavar="X,Y", nargs="+", type=numbers,
                     help="control points P0 ... Pn, each 'x,y' or 'x,y,z' (put '--' before "
                     "the points if the first starts with '-')")
    sub.add_argument("--u", type=float, default=0.5, help="the parameter, 0 <= u <= 1 "
                     "(default 0.5)")
    return ["points", "u"]


def cox_de_boor_options(sub):
    """``--knots``, ``--order`` and ``--u`` of ``cox-de-boor``."""
    sub.add_argument("--knots", type=numbers, required=True,
                     help="the knot vector, e.g. 0,0,0,0,1,2,2,2,2")
    sub.add_argument("--order", type=integer, required=True, help="d (degree d - 1)")
    sub.add_argument("--u", type=float, required=True, help="the parameter")
    return ["knots", "order", "u"]


OPTIONS.update({"de-casteljau": de_casteljau_options, "cox-de-boor": cox_de_boor_options})


def clip_options(sub):
    """The segment X0 Y0 X1 Y1, ``--window`` and (cyrus-beck) ``--window-polygon``."""
    for name, text in (("x0", "x of P0"), ("y0", "y of P0"), ("x1", "x of P1"),
                       ("y1", "y of P1")):
        sub.add_argument(name, metavar=name.upper(), type=float, help=text)
    sub.add_argument("--window", nargs=4, type=float, metavar=("XMIN", "YMIN", "XMAX", "YMAX"),
                     help="the clip rectangle (default 0 0 10 10)")
    names = ["x0", "y0", "x1", "y1", "window"]
    if sub.prog.endswith("cyrus-beck"):
        sub.add_argument("--window-polygon", type=numbers, metavar="X,Y,X,Y,...",
                         help="a convex clip polygon instead, e.g. 0,0,10,0,5,8 (either "
                         "orientation)")
        names.append("window_polygon")
    return names


OPTIONS.update({"cohen-sutherland": clip_options, "liang-barsky": clip_options,
                "cyrus-beck": clip_options})


def polygon_options(sub):
    """The polygon's vertices and ``--rule`` (scan-line-fill) or ``--window`` /
    ``--window-polygon`` (sutherland-hodgman)."""
    sub.add_argument("points", metavar="X,Y", nargs="+", type=numbers,
                     help="the polygon's vertices, each 'x,y' (put '--' before them if the "
                     "first starts with '-')")
    if sub.prog.endswith("scan-line-fill"):
        sub.add_argument("--rule", choices=("even-odd", "nonzero"), default="even-odd",
                         help="the inside-outside rule (default even-odd)")
        return ["points", "rule"]
    sub.add_argument("--window", nargs=4, type=float, metavar=("XMIN", "YMIN", "XMAX", "YMAX"),
                     help="the clip rectangle (default 0 0 10 10)")
    sub.add_argument("--window-polygon", type=numbers, metavar="X,Y,X,Y,...",
                     help="a convex clip polygon instead (either orientation)")
    return ["points", "window", "window_polygon"]


OPTIONS.update({"scan-line-fill": polygon_options, "sutherland-hodgman": polygon_options})


def clip3d_options(sub):
    """The segment X0 Y0 Z0 X1 Y1 Z1, ``--volume``, ``--frustum`` and ``--w``."""
    for name in ("x0", "y0", "z0", "x1", "y1", "z1"):
        sub.add_argument(name, metavar=name.upper(), type=float,
                         help=f"{name[0]} of P{name[1]}")
    group = sub.add_mutually_exclusive_group()
    group.add_argument("--volume", nargs=6, type=float,
                       metavar=("XMIN", "YMIN", "ZMIN", "XMAX", "YMAX", "ZMAX"),
                       help="the clip box (default 0 0 0 10 10 10; z is the depth: zmin "
                       "is the front plane)")
    group.add_argument("--frustum", type=float, metavar="ZMIN",
                       help="clip against the canonical perspective volume z <= x, y <= -z, "
                       "-1 <= z <= ZMIN instead (-1 < ZMIN < 0)")
    sub.add_argument("--w", nargs=2, type=float, metavar=("W0", "W1"),
                     help="homogeneous endpoints (x, y, z, w), clipped against the unit "
                     "cube 0 <= x, y, z <= w before the divide (w may be negative: "
                     "behind the eye)")
    sub.set_defaults(adapt=_clip3d_arguments)
    return ["x0", "y0", "z0", "x1", "y1", "z1", "volume", "frustum", "w"]


def _clip3d_arguments(values, options):
    """The command line's numbers as the tracer's arguments."""
    from ..clip.volumes import box, frustum

    p = [options.pop(n) for n in ("x0", "y0", "z0", "x1", "y1", "z1")]
    if "volume" in options:
        b = options.pop("volume")
        options["volume"] = box(b[:3], b[3:])
    if "frustum" in options:
        options["volume"] = frustum(options.pop("frustum"))
    return [p[:3], p[3:]], options


OPTIONS.update({"cohen-sutherland-3d": clip3d_options, "liang-barsky-3d": clip3d_options})


def z_buffer_options(sub):
    """``--row`` of ``z-buffer`` and ``ray-casting``."""
    sub.add_argument("--row", type=integer, default=4, help="the scan line (default 4)")
    return ["row"]


OPTIONS.update({"z-buffer": z_buffer_options, "ray-casting": z_buffer_options})


def depth_sort_options(sub):
    """``--scene`` and ``--no-split`` of ``depth-sort``."""
    sub.add_argument("--scene", choices=("painter", "cyclic", "intersecting"),
                     default="cyclic", help="the built-in scene (default cyclic)")
    sub.add_argument("--no-split", dest="split_cycles", action="store_false",
                     help="stop with an error on a cycle instead of splitting")
    return ["scene", "split_cycles"]


def horizon_options(sub):
    """``--nx``, ``--ny``, ``--width`` and ``--height`` of ``floating-horizon``."""
    for name, default in (("nx", 6), ("ny", 4), ("width", 24), ("height", 16)):
        sub.add_argument(f"--{name}", type=integer, default=default,
                         help=f"(default {default})")
    return ["nx", "ny", "width", "height"]


OPTIONS.update({"depth-sort": depth_sort_options, "floating-horizon": horizon_options})


def ray_tracing_options(sub):
    """``--max-depth`` and ``--seed`` of ``ray-tracing``."""
    sub.add_argument("--max-depth", type=integer, default=5,
                     help="levels of the ray tree, 1..64 (default 5)")
    sub.add_argument("--seed", type=integer, default=0,
                     help="seed of the distributed rays' random numbers (default 0)")
    return ["max_depth", "seed"]


OPTIONS["ray-tracing"] = ray_tracing_options


def back_face_options(sub):
    """``--eye`` of ``back-face``."""
    sub.add_argument("--eye", nargs=3, type=float, metavar=("X", "Y", "Z"), default=[3, 2, 4],
                     help="the eye, looking at the cube's center (default 3 2 4)")
    return ["eye"]


OPTIONS["back-face"] = back_face_options


def shading_options(sub):
    """``--row`` of ``gouraud`` and ``phong``."""
    sub.add_argument("--row", type=integer, default=12,
                     help="the scan line, 0..23 of the built-in 32 x 24 sphere (default 12)")
    return ["row"]


OPTIONS.update({"gouraud": shading_options, "phong": shading_options})


def bsp_options(sub):
    """``--eye`` of ``bsp-tree``."""
    sub.add_argument("--eye", nargs=2, type=float, metavar=("X", "Y"), default=[6, 22],
                     help="the eye in plan, half way up the walls (default 6 22)")
    return ["eye"]


OPTIONS["bsp-tree"] = bsp_options


def warnock_options(sub):
    """``--scene`` of ``warnock`` and ``scan-line-visible``."""
    sub.add_argument("--scene", choices=("overlap", "surrounding"), default="overlap",
                     help="the built-in scene on a 16 x 12 device (default overlap)")
    return ["scene"]


OPTIONS.update({"warnock": warnock_options, "scan-line-visible": warnock_options})

def inbetween_options(sub):
    """``--n``, ``--spacing``, ``--t1`` and ``--t2`` of ``inbetween-spacing``."""
    sub.add_argument("--n", type=integer, default=7, help="in-betweens, 1..200 (default 7)")
    sub.add_argument("--spacing", default="accelerate", help="constant, accelerate, "
                     "decelerate, accelerate-decelerate, or an easing such as ease-out-bounce "
                     "(default accelerate)")
    sub.add_argument("--t1", type=float, default=0.0, help="the first key frame's time "
                     "(default 0)")
    sub.add_argument("--t2", type=float, default=1.0, help="the second key frame's time "
                     "(default 1)")
    return ["n", "spacing", "t1", "t2"]


def morph_options(sub):
    """``--a``, ``--b`` and ``--t`` of ``morph-equalize``."""
    sub.add_argument("--a", type=numbers, metavar="X,Y,X,Y,...",
                     help="the first key frame's polygon (default a triangle)")
    sub.add_argument("--b", type=numbers, metavar="X,Y,X,Y,...",
                     help="the second key frame's polygon (default a pentagon)")
    sub.add_argument("--t", type=float, default=0.5, help="the in-between's fraction, 0..1 "
                     "(default 0.5)")
    return ["a", "b", "t"]


OPTIONS.update({"inbetween-spacing": inbetween_options, "morph-equalize": morph_options})

FORMATS = ("table", "csv", "json")


def integer(text):
    """argparse type: an integer such as ``20`` or ``-5``."""
    try:
        return int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not an integer") from None


def register(subparsers):
    """Add the ``trace`` command, with one sub-command per algorithm."""
    parser = subparsers.add_parser(
        "trace", help="print an algorithm's step table, as the notes tabulate it",
        description="Run one of the notes' algorithms step by step and print its table:\n"
        "decision parameters and pixels, region codes and clipping parameters,\n"
        "de Casteljau's triangle or the B-spline blending functions.",
        epilog="Examples:\n  scanline trace bresenham 20 10 30 18\n"
        "  scanline trace midpoint-circle 10 --center 5 5 --format csv\n"
        "  scanline trace midpoint-ellipse 8 6 --format json\n"
        "  scanline trace flood-fill 1 2 --connectivity 8\n"
        "Negative numbers work as arguments: scanline trace dda -5 3 10 -2",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    for sub in add_algorithms(parser, run).values():
        sub.add_argument("--format", choices=FORMATS, default="table",
                         help="table (default): aligned text with the set-up notes; "
                         "csv: a header and one line per row; json: a list of row objects")


def add_algorithms(parser, run):
    """One sub-command per algorithm under ``parser``, each taking the algorithm's
    arguments and running ``run(args)`` (``scanline trace`` and ``scanline explain``
    share them); returns them by name."""
    algorithms = parser.add_subparsers(title="algorithms", metavar="ALGORITHM", required=True)
    subs = {}
    for name, (description, params, centered) in ALGORITHMS.items():
        sub = algorithms.add_parser(name, help=description, description=f"Trace {description}.")
        for param, text in params.items():
            sub.add_argument(param.lower(), metavar=param, type=integer, help=text)
        if centered:
            sub.add_argument("--center", nargs=2, metavar=("XC", "YC"), type=integer,
                             help="center; adds the plotted pixel (xc + x, yc + y) to each row")
        extra = OPTIONS[name](sub) if name in OPTIONS else []
        sub.set_defaults(run=run, algorithm=name, params=[p.lower() for p in params],
                         options=extra)
        subs[name] = sub
    return subs


def table_of(args):
    """The step table the parsed arguments of an algorithm sub-command ask for."""
    from ..trace import ALGORITHMS as functions

    values = [getattr(args, p) for p in args.params]
    options = {"center": args.center} if "center" in vars(args) else {}
    options.update({o: getattr(args, o) for o in args.options if getattr(args, o) is not None})
    if getattr(args, "adapt", None) is not None:
        values, options = args.adapt(values, options)
    return functions[args.algorithm](*values, **options)


def run(args):
    """Print the table of ``args.algorithm`` in ``args.format``."""
    table = table_of(args)
    if args.format == "json":
        print(table.to_json(indent=2))
    elif args.format == "csv":
        print(table.to_csv(), end="")
    else:
        print(table)
