"""``scanline fonts [FILE ...] [--system]``: list the built-in fonts (name, kind,
glyph count, metrics, source and license), describe font files, or list the installed
font families that ``font=`` takes by name."""

import os


def register(subparsers):
    """Add the ``fonts`` command."""
    parser = subparsers.add_parser(
        "fonts", help="list the built-in fonts (bitmap, stroke, outline)",
        description="List the fonts scanline.draw.text can use by name, describe "
        "TrueType/OpenType files given as arguments, or (--system) list the installed "
        "font families, which font= also takes by name.",
    )
    parser.add_argument("files", metavar="FILE", nargs="*",
                        help="font files (.ttf, .otf) to describe instead")
    parser.add_argument("--system", action="store_true",
                        help="list the installed font families (found by fontconfig or "
                        "matplotlib) and the file each name picks")
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

    if args.system:
        return _system()

    # each FILE as given (two files of one base name are two rows)
    chosen = {p: load_font(p) for p in args.files} if args.files else fonts()
    print("\n".join(rows(chosen)))
    return 0


def _system():
    """Print the installed families, one ``family<TAB>file`` line each."""
    from ..text import system

    finder, _ = system._faces()
    if not finder:
        print("no installed fonts can be looked up by family name: install fontconfig "
              "(fc-list) or matplotlib; the bundled family is DejaVu Sans ('sans')")
        return 0
    found = system.families()
    width = max([6] + [len(name) for name in found])
    print(f"{'family':<{width}}  file  (by {finder}; bundled: DejaVu Sans = 'sans')")
    for name, file in found.items():
        print(f"{name:<{width}}  {file}")
    return 0
