"""The public surface of scanline and what each public name's docstring and signature lack.

The public surface is what ``import scanline as sl`` offers: every function and class that
``sl`` and its packages (``sl.draw``, ``sl.mesh`` ... the lazy attributes of
``scanline/__init__.py``) export, and every public method, class method, static method and
property of those classes.  Each must
be annotated (every parameter, and the return value) and carry a numpydoc docstring:
``Parameters`` when it takes any, ``Returns`` (or ``Yields``) when it returns a value, and
``Examples`` (functions, classes and methods; properties are documented as attributes).

Run ``python -m tests.api_surface [PREFIX ...]`` to list what the modules under each
prefix (e.g. ``scanline.display``) still lack; ``tests/test_api_surface.py`` asserts that
nothing does.
"""

from __future__ import annotations

import importlib
import inspect
import sys
import warnings
from dataclasses import dataclass
from typing import Iterator

import scanline

@dataclass(frozen=True)
class Lack:
    name: str       # dotted name, e.g. scanline.draw.lines.line or scanline.FrameBuffer.save
    what: str       # e.g. "annotation of x", "Examples section"

    def __str__(self) -> str:
        return f"{self.name}: {self.what}"


def public_modules(prefixes: tuple[str, ...] = ("scanline",)) -> list[str]:
    """The modules of ``scanline``'s lazy attributes (``sl.draw``, ``sl.FrameBuffer``'s
    ``scanline.framebuffer`` ...) under the prefixes."""
    names = {module for module, _ in scanline._LAZY.values()}
    return sorted(n for n in names if n.startswith(prefixes))


def _exported(module: object) -> list[str]:
    names = getattr(module, "__all__", None)
    if names is None:
        names = [k for k in vars(module) if not k.startswith("_")]
    return list(names)


def _defined_here(value: object) -> bool:
    """Whether a class attribute's function is scanline's own: a base class from
    elsewhere may define methods in its subclasses (matplotlib's ``Artist`` gives each
    subclass a ``set`` listing its properties), which that library documents."""
    func = getattr(value, "__func__", value)
    if isinstance(value, property):
        func = value.fget
    return getattr(func, "__module__", "scanline").startswith("scanline")


def _members(module_name: str) -> Iterator[tuple[str, object, str]]:
    """(dotted name, object, kind) for each public name the module exports: the functions
    and classes of scanline it offers (``sl.draw.line`` is ``scanline.draw.line`` wherever
    it is defined), and the public methods and properties of those classes."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        module = importlib.import_module(module_name)
    for name in _exported(module):
        obj = getattr(module, name, None)
        if not (inspect.isclass(obj) or inspect.isfunction(obj)):
            continue
        if not getattr(obj, "__module__", "").startswith("scanline"):
            continue
        if inspect.isclass(obj):
            yield f"{module_name}.{name}", obj, "class"
            for attr, value in vars(obj).items():
                if attr.startswith("_") or not _defined_here(value):
                    continue
                if isinstance(value, property):
                    yield f"{module_name}.{name}.{attr}", value, "property"
                elif isinstance(value, (staticmethod, classmethod)):
                    yield f"{module_name}.{name}.{attr}", value.__func__, "method"
                elif inspect.isfunction(value):
                    yield f"{module_name}.{name}.{attr}", value, "method"
        else:
            yield f"{module_name}.{name}", obj, "function"


def _sections(doc: str) -> dict[str, object]:
    from numpydoc.docscrape import NumpyDocString
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return dict(NumpyDocString(doc))


def _signature_lacks(func: object, skip_first: bool) -> list[str]:
    lacks = []
    try:
        sig = inspect.signature(func)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        return lacks
    params = list(sig.parameters.values())
    if skip_first and params:
        params = params[1:]
    for p in params:
        if p.annotation is inspect.Parameter.empty:
            lacks.append(f"annotation of {p.name}")
    name = getattr(func, "__name__", "")
    if sig.return_annotation is inspect.Signature.empty and name != "__init__":
        lacks.append("return annotation")
    return lacks


def _returns_value(func: object) -> bool:
    ann = inspect.signature(func).return_annotation  # type: ignore[arg-type]
    return ann not in (None, "None", inspect.Signature.empty)


def lacks(module_name: str, seen: set[int] | None = None) -> list[Lack]:
    """What the public names of one module lack (a name already in ``seen``, the ids of
    objects reported under another module's name, is skipped)."""
    seen = set() if seen is None else seen
    found: list[Lack] = []
    for name, obj, kind in _members(module_name):
        if id(obj) in seen:
            continue
        seen.add(id(obj))
        def lack(what: str) -> None:
            found.append(Lack(name, what))
        if kind == "property":
            fget = obj.fget  # type: ignore[attr-defined]
            if fget is not None and inspect.signature(fget).return_annotation is inspect.Signature.empty:
                lack("return annotation")
            if not (fget.__doc__ or "").strip():
                lack("docstring")
            continue
        doc = inspect.getdoc(obj) or ""
        if not doc.strip():
            lack("docstring")
            continue
        sections = _sections(doc)
        if kind == "class":
            init = vars(obj).get("__init__")
            init_doc = inspect.getdoc(init) if init is not None else None
            init_sections = _sections(init_doc) if init_doc else {}
            if inspect.isfunction(init):
                for what in _signature_lacks(init, skip_first=True):
                    lack(f"__init__ {what}")
                takes = len(inspect.signature(init).parameters) > 1
                if takes and not (sections.get("Parameters") or init_sections.get("Parameters")):
                    lack("Parameters section")
            if not sections.get("Examples") and not issubclass(obj, BaseException):
                lack("Examples section")
            continue
        # functions and methods
        is_method = kind == "method"
        skip_first = is_method and _first_is_bound(obj)
        for what in _signature_lacks(obj, skip_first):
            lack(what)
        try:
            params = list(inspect.signature(obj).parameters.values())  # type: ignore[arg-type]
        except (TypeError, ValueError):
            params = []
        if skip_first and params:
            params = params[1:]
        if params and not sections.get("Parameters"):
            lack("Parameters section")
        try:
            returns = _returns_value(obj)
        except (TypeError, ValueError):
            returns = False
        if returns and not (sections.get("Returns") or sections.get("Yields")):
            lack("Returns section")
        if not sections.get("Examples"):
            lack("Examples section")
    return found


def _first_is_bound(func: object) -> bool:
    try:
        params = list(inspect.signature(func).parameters)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        return False
    return bool(params) and params[0] in ("self", "cls")


def all_lacks(prefixes: tuple[str, ...] = ("scanline",)) -> list[Lack]:
    seen: set[int] = set()
    return [item for module in public_modules(prefixes) for item in lacks(module, seen)]


def main(argv: list[str]) -> int:
    prefixes = tuple(argv) or ("scanline",)
    found = all_lacks(prefixes)
    for item in found:
        print(item)
    names = {item.name for item in found}
    print(f"{len(found)} lacks in {len(names)} public names", file=sys.stderr)
    return 1 if found else 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
