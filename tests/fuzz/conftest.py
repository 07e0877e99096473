"""Profiles of the fuzz suite (tests/fuzz/README.md).

``ci`` (the default) runs a bounded number of generated cases per test, so that the
whole suite stays within the CI budget (the same cases on every run when ``CI`` is set,
as in tests/reference.py, so that CI's verdict does not depend on the draw; a new
case is found by a plain or a long run); ``long`` runs a hundred times more, by hand:
``SCANLINE_FUZZ=long pytest tests/fuzz``; ``boundscheck`` a few, for the run of
.ci/run with NUMBA_BOUNDSCHECK=1 (every kernel compiled again, with bounds checks).
"""

import os

from hypothesis import HealthCheck, settings

settings.register_profile("ci", max_examples=40, deadline=None, database=None,
                          derandomize=bool(os.environ.get("CI")),
                          suppress_health_check=[HealthCheck.too_slow,
                                                 HealthCheck.filter_too_much])
settings.register_profile("long", max_examples=4000, deadline=None, database=None,
                          suppress_health_check=[HealthCheck.too_slow,
                                                 HealthCheck.filter_too_much])
settings.register_profile("boundscheck", max_examples=8, deadline=None, database=None,
                          derandomize=bool(os.environ.get("CI")),
                          suppress_health_check=[HealthCheck.too_slow,
                                                 HealthCheck.filter_too_much])
settings.load_profile(os.environ.get("SCANLINE_FUZZ", "ci"))
