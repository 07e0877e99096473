"""``scanline fonts [FILE ...]``: list the built-in fonts (name, kind, glyph count,
metrics, source and license), or describe font files."""

import os


def register(subparsers):
    """Add the ``fonts`` command."""
    parser = subparsers.add_parser(
        "fonts", help="list the built-in fonts (bitmap, stroke, outline)",
        description="List the fonts scanline.draw.text can use by name, or describe "
        "TrueType/OpenType files given as arguments.",
    )
    parser.add_argument("files", metavar="FILE", nargs="*",
                        help="font files (.ttf, .otf) to describe instead")
    parser.set_defaults(run=run)


def rows(fonts):
    """One line of text per font (cap/em: cap height and em size in font units)."""
    w = max([10] + [len(name) for name in fonts])
    out = [f"{'name':<{w}} {'kind':<8} {'glyphs':>6}  {'cap/em':>9}  source; license"]
    for name, f in fonts.items():
        out.append(f"{name:<{w}} {f.kind:<8} {f.glyph_count:>6}  "
                   f"{f'{f.cap_height:g}/{f.units_per_em:g}':>9}  {os.path.basename(f.source)}; "
                   f"{f.license}")
    return out


def run(args):
    from ..text import fonts, load_font

    # each FILE as given (two files of one base name are two rows)
    chosen = {p: load_font(p) for p in args.files} if args.files else fonts()
    print("\n".join(rows(chosen)))
    return 0
