"""``scanline simulate raster|random SCENE -o out.gif``: the refresh displays of the
notes' chapter 1 as animated GIFs (:mod:`scanline.display.crt`).

``raster`` renders the scene into its frame buffer and shows the beam sweeping it
(``--interlaced``, ``--refresh-rate``); ``random`` shows the beam following the
scene's display file, MOVE/LINE command by command.
"""


from .examples import add_scene_argument, scene_path


def register(subparsers):
    """Add the ``simulate`` command."""
    parser = subparsers.add_parser(
        "simulate", help="animate a raster-scan or random-scan refresh display as a GIF",
        description="Simulate a refresh CRT showing a scene file: 'raster' sweeps the beam "
        "over the frame buffer, scan line by scan line with horizontal and vertical "
        "retrace (interlaced or not); 'random' follows the display file's MOVE/LINE "
        "commands. The phosphor fades between refreshes. Writes an animated GIF.",
        epilog="Example: scanline simulate raster --example rotation -o r.gif "
        "--interlaced --frames 24",
    )
    parser.add_argument("kind", choices=("raster", "random"), help="the display type")
    add_scene_argument(parser)
    parser.add_argument("-o", "--output", metavar="OUT.gif", required=True,
                        help="the GIF to write")
    parser.add_argument("--frames", type=int, default=24,
                        help="frames per refresh cycle (default 24)")
    parser.add_argument("--refreshes", type=int, default=2,
                        help="refresh cycles shown (default 2)")
    parser.add_argument("--scale", type=int, default=1, help="enlarge each pixel (default 1)")
    parser.add_argument("--fps", type=float, default=12, help="GIF frames per second (default 12)")
    parser.add_argument("--persistence", type=float, default=0.02,
                        help="seconds for the phosphor to fade to a tenth (default 0.02)")
    parser.add_argument("--refresh-rate", type=float, default=60.0,
                        help="raster: frames per second; random: the highest rate (default 60)")
    parser.add_argument("--interlaced", action="store_true",
                        help="raster: even scan lines in one field, odd in the next")
    parser.add_argument("--writing-speed", type=float, default=2e5,
                        help="random: device units per second the beam draws (default 2e5)")
    parser.set_defaults(run=run)


def run(args):
    """Load the scene, simulate and write the GIF."""
    from ..display.crt import RandomScan, RasterScan
    from ..errors import ArgumentValueError
    from ..scene import load

    if not args.output.lower().endswith(".gif"):
        raise ArgumentValueError(f"-o {args.output!r}: the simulation is written as a .gif")
    scene = load(scene_path(args))
    if args.kind == "raster":
        sim = RasterScan(scene.raster(), refresh_rate=args.refresh_rate,
                         interlaced=args.interlaced, persistence=args.persistence)
    else:
        sim = RandomScan(scene.display_file, scene.canvas.width, scene.canvas.height,
                         writing_speed=args.writing_speed, max_rate=args.refresh_rate,
                         persistence=args.persistence)
    sim.save(args.output, args.frames, args.refreshes, args.scale, args.fps)
    print(f"scanline simulate: wrote {args.output} ({args.frames * args.refreshes} frames, "
          f"refresh period {sim.period * 1e3:.3g} ms)")
