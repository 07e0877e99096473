"""The direct-view storage tube (Hearn & Baker, section 2-1; the notes' chapter 1,
whose quiz asks where "selective or part erasing of screen is not possible": in the
DVST).

A DVST "stores the picture information as a charge distribution just behind the
phosphor-coated screen".  A *primary gun* writes the picture pattern, line by line
as a random-scan beam does; a *flood gun* then keeps the whole stored pattern
glowing.  So there is no refresh: "very complex pictures can be displayed at very
high resolutions without flicker", and what is written stays lit at full intensity
for as long as the tube holds it.  But "selected parts of a picture cannot be
erased": to remove one part, "the entire screen must be erased and the modified
picture redrawn", the erase showing as a flash of the whole screen, and the
redrawing of a complex picture taking seconds.

:class:`StorageTube` simulates that sequence: the writing of the display file,
the picture held; with ``remove=`` a segment's name, the whole-screen erase (its
flash) and the writing of the picture without that segment.  Asking the tube to
erase one segment by itself (:meth:`StorageTube.erase_segment`) is an error that
says so.
"""

from typing import TYPE_CHECKING, Optional

import numpy as np
from numpy.typing import NDArray

from .. import _validate as v
from ..errors import ArgumentValueError
from .crt import MAX_PIXELS, Beam, RandomScan, _Simulation

if TYPE_CHECKING:
    from .file import DisplayFile

#: The green of a storage tube's P1 phosphor.
STORED = (90, 255, 120)


class SelectiveEraseError(ArgumentValueError):
    """A direct-view storage tube cannot erase part of its picture."""


class StorageTube(_Simulation):
    """A direct-view storage tube writing a display file.

    Parameters
    ----------
    display_file : DisplayFile
        The picture, written by the primary gun along its MOVE / LINE commands
        (:class:`~scanline.display.crt.RandomScan`'s beam path, drawn once).
    width, height : int
        The addressable area, in device units.
    writing_speed, jump_speed, settle_time : float
        The writing beam's speeds and settling (as for the random-scan display).
    hold : float
        Seconds the finished picture is held (shown) before what follows.
    remove : str, optional
        A segment to take out of the picture: the tube then erases the whole screen
        (a flash lasting ``erase_time``) and writes the picture again without it.
    erase_time : float
        Seconds of the erase flash.

    Attributes
    ----------
    period : float
        The length of the whole sequence (the frames cover it): writing, holding,
        and with ``remove`` the erase and the second writing and holding.
    phases : list of (name, start, end)
        The sequence's phases: ``"writing"``, ``"holding"``, ``"erasing"``,
        ``"rewriting"``, ``"holding"``.

    Examples
    --------
    >>> import scanline as sl
    >>> df = sl.DisplayFile()
    >>> df.set_viewing(window=(0, 0, 100, 100))
    >>> for name, y in (("a", 20), ("b", 80)):
    ...     df.create_segment(name)
    ...     df.polyline([(10, y), (90, y)])
    ...     df.close_segment()
    >>> tube = StorageTube(df, 101, 101, writing_speed=1e4, hold=1.0, remove="b")
    >>> [p[0] for p in tube.phases]
    ['writing', 'holding', 'erasing', 'rewriting', 'holding']
    >>> tube.erase_segment("b")
    Traceback (most recent call last):
    ...
    scanline.display.storage_tube.SelectiveEraseError: a direct-view storage tube cannot erase segment 'b' by itself: its picture is one stored charge pattern, so erasing clears the whole screen (with a flash); give StorageTube(..., remove='b') to erase everything and write the picture again without it
    """

    def __init__(self, display_file: "DisplayFile", width: int, height: int,
                 writing_speed: float = 2e5, jump_speed: float = 2e6, settle_time: float = 2e-6,
                 hold: float = 0.5, remove: Optional[str] = None, erase_time: float = 0.3) -> None:
        import copy

        beam = dict(writing_speed=writing_speed, jump_speed=jump_speed, settle_time=settle_time)
        self._first = RandomScan(display_file, width, height, **beam)
        self.width, self.height = self._first.width, self._first.height
        self.hold = v.number("hold", hold)
        self.erase_time = v.number("erase_time", erase_time)
        for name, x in (("hold", self.hold), ("erase_time", self.erase_time)):
            if not 0 < x < 1e6:
                raise ArgumentValueError(f"{name}={x} must be a positive number of seconds")
        d1 = self._first.drawing_time
        self.phases = [("writing", 0.0, d1), ("holding", d1, d1 + self.hold)]
        self._second: Optional[RandomScan] = None
        self.remove = remove
        if remove is not None:
            display_file.segment(remove)          # a clear error if there is none
            rest = copy.deepcopy(display_file)
            rest.delete_segment(remove)
            self._second = RandomScan(rest, width, height, **beam)
            t = d1 + self.hold
            d2 = self._second.drawing_time
            self.phases += [("erasing", t, t + self.erase_time),
                            ("rewriting", t + self.erase_time, t + self.erase_time + d2),
                            ("holding", t + self.erase_time + d2,
                             t + self.erase_time + d2 + self.hold)]
        self.period = self.phases[-1][2]
        if self.width * self.height > MAX_PIXELS:
            raise ArgumentValueError(f"the screen is {self.width} x {self.height}; at most "
                                     f"{MAX_PIXELS} pixels")

    def erase_segment(self, name: str) -> None:
        """Always an error: a storage tube has no selective erase (the notes' chapter
        1; Hearn & Baker 2-1)."""
        raise SelectiveEraseError(
            f"a direct-view storage tube cannot erase segment {name!r} by itself: its picture "
            "is one stored charge pattern, so erasing clears the whole screen (with a flash); "
            f"give StorageTube(..., remove={name!r}) to erase everything and write the picture "
            "again without it")

    def phase(self, t: float) -> tuple[str, float]:
        """The phase at time ``t`` (``t`` taken within the sequence, repeating)."""
        t = v.number("t", t) % self.period
        for name, start, end in self.phases:
            if start <= t < end:
                return name, start
        return self.phases[-1][0], self.phases[-1][1]

    @staticmethod
    def _written(scan: RandomScan, elapsed: float) -> NDArray[np.uint8]:
        """The stored pattern after ``elapsed`` seconds of writing: every spot the
        beam has passed, at full intensity (no decay: the flood gun holds it)."""
        img = np.zeros((scan.height, scan.width, 3), np.uint8)
        done = scan._times <= elapsed
        spots = scan._spots[done]
        img[scan.height - 1 - spots[:, 1], spots[:, 0]] = STORED
        return img

    def screen(self, t: float) -> NDArray[np.uint8]:
        """The screen at time ``t``: the stored pattern written so far, or the erase
        flash (the whole screen bright, fading out)."""
        name, start = self.phase(t)
        t = v.number("t", t) % self.period
        if name == "erasing":
            level = 1.0 - (t - start) / self.erase_time
            flash: NDArray[np.uint8] = np.broadcast_to(
                np.rint(np.array(STORED) * level).astype(np.uint8),
                (self.height, self.width, 3)).copy()
            return flash
        after = any(p[0] == "erasing" and p[2] <= t for p in self.phases)
        scan = self._second if after and self._second is not None else self._first
        first = self.phases[3][1] if after else 0.0
        return self._written(scan, t - first)

    def beam(self, t: float) -> Beam:
        """The writing beam: where it is while writing (``"drawing"`` or
        ``"moving"``); ``"off"`` while the picture is held (the flood gun alone) and
        during the erase."""
        name, start = self.phase(t)
        t = v.number("t", t) % self.period
        if name == "writing":
            return self._first.beam(t)
        if name == "rewriting" and self._second is not None:
            return self._second.beam(t - start)
        return (0.0, 0.0, "off")
