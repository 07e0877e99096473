"""``scanline examples [--copy FOLDER]``: the scene files shipped with scanline, and
``--example NAME``, the option by which ``render``, ``simulate``, ``animate`` and
``storyboard`` read one of them from any folder."""


def register(subparsers):
    """Add the ``examples`` command."""
    parser = subparsers.add_parser(
        "examples", help="list the bundled example scene files, or copy them into a folder",
        description="List the example scene files shipped with scanline (name and what it "
        "shows). Any command that reads a scene takes --example NAME instead of a file; "
        "--copy FOLDER copies them all, to edit.",
        epilog="Example: scanline render --example rotation -o rotation.png",
    )
    parser.add_argument("--copy", metavar="FOLDER",
                        help="copy every example into FOLDER (created if needed)")
    parser.set_defaults(run=run)


def run(args):
    """List or copy the examples."""
    from ..scene import copy_examples, examples

    if args.copy is not None:
        for path in copy_examples(args.copy):
            print(path)
        return
    found = examples()
    width = max(map(len, found))
    for name, summary in found.items():
        print(f"{name:<{width}}  {summary}")


def add_scene_argument(parser):
    """SCENE, a file, or ``--example NAME``, a bundled scene (one of the two)."""
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("scene", metavar="SCENE", nargs="?",
                       help="the scene file, .toml or .json")
    group.add_argument("--example", metavar="NAME",
                       help="a bundled example scene instead of a file (see 'scanline examples')")


def scene_path(args):
    """The scene file the arguments name."""
    if args.example is None:
        return args.scene
    from ..scene import example

    return str(example(args.example))
