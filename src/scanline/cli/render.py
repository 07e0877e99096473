"""``scanline render SCENE -o OUT`` and ``scanline check SCENE...``: scene files.

``render`` draws a scene file (TOML or JSON, docs/scene-format.md) through the
display-file interpreter into a PNG, GIF or BMP (raster device), an SVG, or a ``.txt``
listing of the MOVE/LINE commands a random-scan display would refresh.  ``check``
reads and checks scene files without drawing.  Errors name the file, the line where
the parser knows it, and the key path of the bad value; the output file is written
atomically, so an error leaves none.
"""


from .examples import add_scene_argument, scene_path


def register(subparsers):
    """Add the ``render`` and ``check`` commands."""
    render = subparsers.add_parser(
        "render", help="draw a scene file (TOML or JSON) into PNG, GIF, SVG or a vector listing",
        description="Draw a scene file through the display-file interpreter. The output "
        "type follows the extension: .png, .gif, .bmp (raster), .svg (vector), .txt or "
        ".vec (the MOVE/LINE commands of a random-scan display).",
    )
    add_scene_argument(render)
    render.add_argument("-o", "--output", metavar="OUT", required=True,
                        help="the file to write (.png, .gif, .bmp, .svg, .txt, .vec)")
    render.add_argument("--format", choices=("toml", "json"),
                        help="the scene file's format (default: from its extension)")
    render.set_defaults(run=run_render)

    check = subparsers.add_parser(
        "check", help="check scene files without drawing them",
        description="Read and check scene files: syntax, schema version, keys, values. "
        "Prints one line per file; exits 2 at the first bad file.",
    )
    check.add_argument("scenes", metavar="SCENE", nargs="+", help="scene files, .toml or .json")
    check.add_argument("--format", choices=("toml", "json"),
                       help="the files' format (default: from each extension)")
    check.set_defaults(run=run_check)


def _summary(scene):
    df = scene.display_file
    prims = sum(len(s.primitives) for s in df.segments)
    return (f"{scene.canvas.width}x{scene.canvas.height}, {len(df)} segments, "
            f"{prims} primitives")


def run_render(args):
    """Load, check and render one scene."""
    from ..scene import load

    scene = load(scene_path(args), args.format)
    scene.render(args.output)
    print(f"scanline render: wrote {args.output} ({_summary(scene)})")


def run_check(args):
    """Load and check each scene."""
    from ..scene import load

    for name in args.scenes:
        scene = load(name, args.format)
        print(f"{name}: ok ({_summary(scene)})")
