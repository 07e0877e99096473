"""``scanline studio [--port N] [--host H]``: start the local web application."""


def register(subparsers):
    """Add the ``studio`` command."""
    parser = subparsers.add_parser(
        "studio", help="start the interactive studio (a local web page) and print its address",
        description="Start the studio: the algorithm explorer, the display-device "
        "simulations and the workstation with logical input devices, served on "
        "127.0.0.1 (this machine only) unless --host says otherwise.",
    )
    parser.add_argument("--port", type=int, default=8765, help="the port (default 8765; 0: any free)")
    parser.add_argument("--host", default="127.0.0.1",
                        help="the address to listen on (default 127.0.0.1, this machine only)")
    parser.set_defaults(run=run)


def run(args):
    """Serve until interrupted."""
    from ..studio.server import serve

    serve(args.host, args.port)
