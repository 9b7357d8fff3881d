"""The tuner (issue 19): the fastest solver mode and settings within an error budget on a scene.

    result = physics.tune("scenes/pyramid.json", steps=600, metric="trajectory", budget=0.01)
    result.choice["key"], result.fragment        # 'sequential_impulse velocity_iterations=4', {...}

    runs      a case (scene data + Candidate) run and sampled at fixed times
    metrics   errors against the reference; the statistical fallback for chaotic scenes
    candidates  the grid, its refinement and the Pareto front
    sweep     the cases as dask.distributed tasks (LocalCluster by default), progress bar
    search    tune(): reference + convergence check, two rounds, the choice
    report    the table, the plot, the command or scene fragment
    apply     the choice written into the scene file
    command   the ``tune`` CLI command
"""
from .metrics import METRICS
from .runs import Candidate
from .search import TuneResult, tune
from .sweep import Cancelled

__all__ = ["tune", "TuneResult", "Candidate", "METRICS", "Cancelled"]
