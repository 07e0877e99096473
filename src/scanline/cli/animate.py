"""``scanline animate SCENE -o OUT`` and ``scanline storyboard SCENE -o BOARD``:
animated scene files (schema version 2, docs/animation.md).

``animate`` renders every frame of the scene's ``[animation]`` and writes a GIF,
animated PNG, WebP or MP4 (by the extension), or numbered PNG files into a folder
(an OUT ending in ``/``); ``--jobs N`` renders in N processes and ``--scheduler
ADDRESS`` on a Dask cluster, with byte-identical output.  ``storyboard`` draws the
storyboard's panels (or the key frames) as a labeled contact sheet.
"""

import os
import re

from .examples import add_scene_argument, scene_path


def register(subparsers):
    """Add the ``animate`` and ``storyboard`` commands."""
    animate = subparsers.add_parser(
        "animate", help="render an animated scene file into GIF, APNG, WebP or MP4",
        description="Render the frames of a version-2 scene file's [animation] (key "
        "frames, motion paths, morphs) and encode them; the output type follows the "
        "extension: .gif, .png or .apng (animated PNG), .webp, .mp4 (H.264). An OUT "
        "ending in '/' receives one PNG per frame instead.",
    )
    add_scene_argument(animate)
    animate.add_argument("-o", "--output", metavar="OUT", required=True,
                         help="the file to write (.gif, .png, .apng, .webp, .mp4) or a folder/")
    animate.add_argument("--fps", type=float, metavar="N",
                         help="frames per second (default: the scene's animation.fps)")
    animate.add_argument("--frames", metavar="A:B",
                         help="render frames A to B - 1 only (Python slice style; A or B may "
                         "be left out)")
    animate.add_argument("--jobs", type=int, default=1, metavar="N",
                         help="render in N processes (default 1)")
    animate.add_argument("--scheduler", metavar="ADDRESS",
                         help="render on the Dask cluster of this scheduler (tcp://HOST:PORT)")
    animate.add_argument("--quality", type=int, metavar="Q",
                         help="MP4: x264 CRF 0-51 (default 18); WebP: lossy quality 0-100 "
                         "(default lossless)")
    animate.add_argument("--progress", action="store_true", default=None,
                         help="always show the progress bar (default: on a terminal)")
    animate.add_argument("--no-progress", dest="progress", action="store_false",
                         help="never show the progress bar")
    animate.add_argument("--format", choices=("toml", "json"),
                         help="the scene file's format (default: from its extension)")
    animate.set_defaults(run=run_animate)

    board = subparsers.add_parser(
        "storyboard", help="draw an animated scene's storyboard as a contact sheet",
        description="Draw the storyboard of a version-2 scene file: the frames at the "
        "times of its [[animation.storyboard]] captions, or at its key times, as a "
        "labeled contact sheet (PNG, GIF or BMP).",
    )
    add_scene_argument(board)
    board.add_argument("-o", "--output", metavar="BOARD", required=True,
                       help="the image to write (.png, .gif, .bmp)")
    board.add_argument("--columns", type=int, default=4, metavar="N",
                       help="panels per row (default 4)")
    board.add_argument("--panel", default="240x180", metavar="WxH",
                       help="the size of a panel (default 240x180)")
    board.add_argument("--format", choices=("toml", "json"),
                       help="the scene file's format (default: from its extension)")
    board.set_defaults(run=run_storyboard)


def frame_range(text, count):
    """``"A:B"`` (either may be empty) -> a slice object, checked against ``count``.

    >>> frame_range("2:5", 10), frame_range(":3", 10), frame_range("7:", 10)
    (slice(2, 5, None), slice(0, 3, None), slice(7, 10, None))
    """
    from ..errors import ArgumentValueError

    m = re.fullmatch(r"\s*(\d*)\s*:\s*(\d*)\s*", text or "")
    if m is None:
        raise ArgumentValueError(f"--frames {text!r} must be A:B, frame numbers (0-based; B "
                                 "excluded; either may be left out)")
    a = int(m.group(1)) if m.group(1) else 0
    b = int(m.group(2)) if m.group(2) else count
    if not 0 <= a < b <= count:
        raise ArgumentValueError(f"--frames {text!r} must satisfy 0 <= A < B <= {count} (the "
                                 "scene's frame count)")
    return slice(a, b)


def run_animate(args):
    """Load the animated scene, render and encode it."""
    from ..animation import Animation
    from ..animation.output import FORMATS, check_frames_memory
    from ..animation.render import check_jobs, scheduler_address
    from ..errors import ArgumentValueError
    from ..scene import load_animated

    # the arguments first, before the scene is read and drawn
    check_jobs(args.jobs, "--jobs")
    if args.scheduler is not None:
        scheduler_address(args.scheduler, "--scheduler")
        if args.jobs != 1:
            raise ArgumentValueError("give --jobs (processes here) or --scheduler (a Dask "
                                     "cluster), not both")
    if args.fps is not None:
        from ..animation.timing import _fps

        _fps(args.fps, "--fps")
    scene = load_animated(scene_path(args), args.format)
    if args.fps is not None:
        scene.set_fps(args.fps)
    fps = scene.fps
    anim = Animation(scene, fps=fps)
    frames = None if args.frames is None else frame_range(args.frames, len(anim))
    count = len(range(len(anim))[frames]) if frames is not None else len(anim)
    where = dict(jobs=args.jobs, client=args.scheduler, progress=args.progress, frames=frames)
    if args.output.endswith(("/", os.sep)):
        if args.quality is not None:
            raise ArgumentValueError("--quality is for .mp4 and .webp files; frames written "
                                     "into a folder are lossless PNG files")
        paths = anim.write_frames(args.output, **where)
        print(f"scanline animate: wrote {len(paths)} frames to {args.output}")
        return
    kind = FORMATS.get(os.path.splitext(args.output)[1].lower())
    c = scene.canvas
    if kind in ("GIF", "APNG", "WebP"):         # writers that hold every frame
        check_frames_memory(count, c.width, c.height, "RGBA" if c.mode == "RGBA" else "RGB",
                            kind, "--frames",
                            hint=f"the scene's {count} frames do not fit: write .mp4 (encoded "
                                 "as the frames come), or one PNG per frame into a folder/, "
                                 "or give --frames A:B")
    anim.save(args.output, quality=args.quality, **where)
    print(f"scanline animate: wrote {args.output} ({count} frames, {c.width}x{c.height}, "
          f"{fps:g} fps, {count / fps:g} s)")


def run_storyboard(args):
    """Load the animated scene and draw its storyboard."""
    from ..animation.storyboard import check_sheet
    from ..errors import ArgumentValueError
    from ..framebuffer import FrameBuffer
    from ..scene import load_animated

    m = re.fullmatch(r"(\d{1,9})x(\d{1,9})", args.panel)
    if m is None:
        raise ArgumentValueError(f"--panel {args.panel!r} must be WxH, e.g. 240x180")
    panel = (int(m.group(1)), int(m.group(2)))
    if min(panel) < 16:
        raise ArgumentValueError(f"--panel {args.panel!r}: a panel must be at least 16x16 "
                                 "pixels")
    if args.columns < 1:
        raise ArgumentValueError(f"--columns must be >= 1, got {args.columns}")
    # the sheet's size for one panel a row, refused before the scene is read
    check_sheet(1, 1, panel, name="--panel", copies=1)
    scene = load_animated(scene_path(args), args.format)
    panels = scene.storyboard_frames()
    # the sheet, and the frame buffer it is saved from
    check_sheet(len(panels), min(args.columns, len(panels)), panel, [c for *_, c in panels],
                title="storyboard", name="--panel", copies=1)
    sheet = scene.storyboard_sheet(columns=args.columns, panel=panel)
    FrameBuffer.from_pil(sheet).save(args.output)
    print(f"scanline storyboard: wrote {args.output} ({len(panels)} panels)")
