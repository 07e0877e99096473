"""``scanline studio [--port N] [--host H]``: start the local web application."""


def register(subparsers):
    """Add the ``studio`` command."""
    parser = subparsers.add_parser(
        "studio", help="start the interactive studio (a local web page) and print its address",
        description="Start the studio: the algorithm explorer, the display-device "
        "simulations and the workstation with logical input devices, served on "
        "127.0.0.1 (this machine only) unless --host says otherwise.",
    )
    parser.add_argument("--port", type=port, default=8765,
                        help="the port (default 8765; 0: any free)")
    parser.add_argument("--host", default="127.0.0.1",
                        help="the address to listen on (default 127.0.0.1, this machine only)")
    parser.set_defaults(run=run)


def port(text):
    """A TCP port number 0-65535 (argparse type: a bad one is a one-line error)."""
    import argparse

    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"invalid port {text!r}: give an integer") from None
    if not 0 <= value <= 65535:
        raise argparse.ArgumentTypeError(f"invalid port {value}: ports are 0 to 65535")
    return value


def run(args):
    """Serve until interrupted."""
    from ..studio.server import serve

    serve(args.host, args.port)
