"""QUIET_WORKERS and worker_environment: the settings reach Dask as written, from the
process's config and from the environment, and a cluster started under them renders
the same frames."""

import numpy as np

from scanline.animation import QUIET_WORKERS, Animation, worker_environment
from tests.reference import peer


def test_the_environment_says_what_the_settings_say():
    dask = peer("dask")
    collected = dask.config.collect_env(worker_environment())
    for key, value in QUIET_WORKERS.items():
        assert dask.config.get(key, config=collected) == value
    assert len(worker_environment()) == len(QUIET_WORKERS)


def test_every_setting_is_one_dask_knows():
    dask = peer("dask")
    peer("distributed")                     # its defaults are in dask.config once imported
    for key in QUIET_WORKERS:
        dask.config.get(key)                # KeyError for a setting Dask does not have


def _settings(dask_worker):
    import dask
    return (dask_worker._tick_interval,
            dask.config.get("distributed.worker.profile.enabled"),
            dask.config.get("distributed.worker.memory.monitor-interval"))


def test_a_cluster_started_under_them_has_them_and_renders_the_same_frames():
    distributed = peer("distributed")
    dask = peer("dask")
    anim = Animation(lambda i: np.full((5, 7), 30 * i, np.uint8), fps=10, frames=6)
    serial = [np.asarray(im) for im in anim.images(progress=False)]
    with dask.config.set(QUIET_WORKERS), \
            distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True,
                                     dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        (settings,) = client.run(_settings).values()
        assert settings == (1.0, False, "5s")
        assert [np.asarray(im).tolist() for im in anim.images(client=client, progress=False)] \
            == [im.tolist() for im in serial]
