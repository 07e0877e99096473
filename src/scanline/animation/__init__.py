"""Computer animation (notes, chapter 6; Hearn & Baker, chapter 16).

The animation sequence as the notes lay it out — storyboard, object definitions,
key-frame specifications, in-between frames — and the tools of an animation package:

- timing: :func:`frames_needed`, :func:`duration_of`, :func:`inbetween_times` (Hearn
  & Baker's spacing laws for simulated accelerations), :func:`ease` and the Penner
  easing catalog;
- key frames: :class:`KeyFrames` for any numeric parameter (linear, step,
  Catmull–Rom, cardinal, Kochanek–Bartels in-betweens, per-segment easing),
  :class:`RotationKeyFrames` for orientations (quaternion slerp and squad) and
  :class:`Timeline`;
- motion specification: :func:`bouncing_ball` (direct motion), :class:`MotionPath`
  (any :mod:`scanline.curves` curve by arc length), :class:`Chain` (forward and
  inverse kinematics), :class:`Particles` (dynamics: forces, integrators, collisions,
  energy);
- morphing: :func:`equalize`, :func:`morph` and :func:`beier_neely`;
- output: :class:`Animation` (GIF, APNG, WebP, MP4; processes or a Dask cluster);
  :func:`contact_sheet` (the storyboard).

Raster animation (block transfers, raster operations, color-table animation) is in
:mod:`scanline.raster`.

>>> import scanline as sl
>>> sl.animation.frames_needed(60, 24, inbetweens=5).key_frames
241
>>> sl.animation.inbetween_times(0.0, 1.0, 4).tolist()
[0.2, 0.4, 0.6, 0.8]
"""

from .dynamics import (DynamicsError, Drag, Force, Gravity, Particles, Plane, Spring)
from .easing import EASINGS, SPACINGS, cubic_bezier, ease
from .keyframes import INTERPOLATIONS, KeyFrames, Timeline
from .kinematics import Chain, Reach, UnreachableTarget
from .morph import Equalization, beier_neely, equalization, equalize, morph, warp
from .motion import ballistic, bouncing_ball
from .output import Animation
from .paths import MotionPath
from .render import QUIET_WORKERS, SchedulerUnreachable, worker_environment
from .rotations import ROTATION_INTERPOLATIONS, RotationKeyFrames
from .storyboard import contact_sheet
from .timing import FramePlan, duration_of, frame_count, frames_needed, inbetween_times

__all__ = ["Animation", "Chain", "Drag", "DynamicsError", "EASINGS", "Equalization", "Force",
           "FramePlan", "Gravity", "INTERPOLATIONS", "KeyFrames", "MotionPath", "Particles",
           "Plane", "QUIET_WORKERS", "ROTATION_INTERPOLATIONS", "Reach", "RotationKeyFrames",
           "SPACINGS", "SchedulerUnreachable", "Spring", "Timeline",
           "UnreachableTarget", "ballistic", "beier_neely", "bouncing_ball", "contact_sheet",
           "cubic_bezier", "duration_of", "ease", "equalization", "equalize", "frame_count",
           "frames_needed", "inbetween_times", "morph", "warp", "worker_environment"]
