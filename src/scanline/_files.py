"""Reading input files safely: regular files only, of a bounded size, with errors
that name the file (issue 11: a FIFO, a device such as /dev/zero or a folder given
as an input must be refused before anything is read or allocated)."""

import os
import stat
from typing import Any, cast

from . import _validate as v
from .errors import ArgumentTypeError, ArgumentValueError


def _error(error: type[Exception], what: str, name: str, message: str) -> Exception:
    """``error(message)`` naming the file: as ``file=`` where the class keeps it (a
    SceneError prints ``FILE: MESSAGE``), else in the message."""
    code = getattr(error.__init__, "__code__", None)
    if code is not None and "file" in code.co_varnames:
        keeps_file: Any = error     # a class whose __init__ takes file= (checked above)
        return cast(Exception, keeps_file(f"cannot read the file: {message}", file=name))
    return error(f"{what} {name!r}: {message}")


def input_path(path: object, what: str = "file", limit: int | None = None,
               error: type[Exception] = ArgumentValueError) -> str:
    """``path`` as a str, checked: a str or os.PathLike naming an existing regular
    file of at most ``limit`` bytes (None: any size).  ``error`` is the exception
    class raised."""
    if not isinstance(path, (str, os.PathLike)):
        raise ArgumentTypeError(f"the {what} must be a file name (str or os.PathLike), got "
                                f"{v._show(path)}")
    name = os.fsdecode(os.fspath(path))
    if "\0" in name:
        raise _error(error, what, name, "the name has a NUL character")
    try:
        info = os.stat(name)
    except FileNotFoundError:
        raise _error(error, what, name, "it does not exist (No such file or directory)") from None
    except OSError as exc:
        raise _error(error, what, name, f"{exc.strerror or exc}") from None
    if stat.S_ISDIR(info.st_mode):
        raise _error(error, what, name, f"it is a folder, which is not a {what}")
    if not stat.S_ISREG(info.st_mode):
        raise _error(error, what, name,
                     "it is not a regular file (a device, FIFO or socket); give a file on disk")
    if limit is not None and info.st_size > limit:
        raise _error(error, what, name,
                     f"it is {info.st_size:,} bytes, more than the {limit:,} a {what} may have")
    return name


def read_limited(path: object, what: str = "file", limit: int | None = None,
                 error: type[Exception] = ArgumentValueError) -> bytes:
    """The bytes of the regular file ``path`` (see :func:`input_path`); at most
    ``limit`` + 1 bytes are read, so a file that grows meanwhile is still refused."""
    name = input_path(path, what, limit, error)
    try:
        with open(name, "rb") as f:
            data = f.read() if limit is None else f.read(limit + 1)
    except OSError as exc:
        raise _error(error, what, name, f"{exc.strerror or exc}") from None
    if limit is not None and len(data) > limit:
        raise _error(error, what, name, f"it has more than the {limit:,} bytes a {what} may have")
    return data
