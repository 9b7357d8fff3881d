"""One benchmark run: the parts chosen (compile, overhead, speed, scaling, accuracy, profile)
in order, into one result dict (what bench.json holds)."""
from __future__ import annotations

import contextlib
import dataclasses
import sys
import time
from dataclasses import dataclass

from .accuracy_runs import accuracy_runs
from .configs import DEFAULT_MODE, configs_for
from .engines import REF_ENGINES, usable
from .overhead import overhead
from .profile import profile_scene
from .report.files import meta
from .scaling import scaling
from .scenes import SCENES
from .speed import speed_scene
from .sweep import Sweep, open_records
from .startup import compile_times, source_hash

PARTS = ("overhead", "compile", "speed", "scaling", "accuracy", "profile")


@dataclass
class RunOptions:
    """What to run: solver ``modes``, benchmark ``scenes`` (keys of SCENES), ``parts`` (of PARTS),
    reference ``engines`` (empty: none), ``quick`` (defaults only, short runs), ``tiny`` (tests:
    shorter still), ``budget_s`` (seconds per configuration and scene before it is cut),
    ``scheduler`` (bench/sweep.py: None a local Dask cluster, an address, or "inline"),
    ``results`` (a JSON-lines file each speed and accuracy case streams into; None: none) and
    ``resume`` (skip the cases already in it)."""
    modes: list
    scenes: list
    parts: set
    engines: tuple = REF_ENGINES
    quick: bool = False
    tiny: bool = False
    budget_s: float = 20.0
    scheduler: str | None = None
    results: object = None
    resume: bool = False

    @property
    def main_mode(self) -> str:
        """The mode scaling and the cold start measure: the default mode when it is run."""
        return DEFAULT_MODE if DEFAULT_MODE in self.modes else self.modes[0]

    def plan(self, key) -> dict:
        """The run plan (steps, chunk, warm) of scene ``key`` in this run."""
        if self.tiny:
            return dict(steps=40, chunk=10, warm=10)
        return dict(SCENES[key].quick if self.quick else SCENES[key].full)

    def scale_ns(self) -> list:
        """Body counts of the scaling part."""
        if self.tiny:
            return [100, 300]
        return [100, 1000] if self.quick else [100, 300, 1000, 3000, 10000]


def _units(opts, configs) -> int:
    n = 0
    if "speed" in opts.parts:
        n += sum(len(configs[m]) if SCENES[s].sweep else 1 for s in opts.scenes for m in opts.modes)
    return n + (len(opts.scale_ns()) if "scaling" in opts.parts else 0)


def _speed(opts, configs, res, bar, sweep, records):
    res["speed"] = []
    for s in opts.scenes:
        plan = opts.plan(s)
        cf = [c for m in opts.modes for c in (configs[m] if SCENES[s].sweep else configs[m][:1])]
        rows, src = speed_scene(s, cf, plan, opts.engines, opts.budget_s, bar, sweep, records)
        res["speed"] += rows
        res["scenes"][s] = dict(source=src, title=SCENES[s].title, error=SCENES[s].error, **plan)


def _profile(opts, res, bar):
    res["profile"] = {}
    for s in opts.scenes:
        if SCENES[s].keep_world:
            continue
        bar.set_description(f"profile: {s}")
        # the rain is profiled once the pile has formed (as in its timed window)
        warm = 10 if opts.quick else (SCENES[s].full["warm"] * 4 if s.startswith("rain") else 60)
        res["profile"][s] = profile_scene(s, DEFAULT_MODE, steps=40 if opts.quick else 300, warm=warm)


def _cached_start(opts, res, bar):
    bar.set_description("compile: cached start (subprocess)")
    c = compile_times(opts.modes, ("cached",))
    if c["cached"]["source_hash"] != res["meta"]["source_hash"] or c["cached"].get("startup_s", 99) > 10:
        # physics/ changed during the run (the cache is keyed on its sources): the first
        # process compiled afresh; a second one measures the cached start
        c = compile_times(opts.modes, ("cached",))
        c["cached"]["note"] = "physics/ sources changed during the run; measured in a second process"
    res["compile"].update(c)


def run(opts) -> dict:
    """Run every part of ``opts`` with a progress bar on stderr; returns the result dict."""
    from tqdm import tqdm
    quick = opts.quick or opts.tiny
    res = {"meta": meta(quick), "modes": opts.modes, "scenes": {}}
    res["meta"]["source_hash"] = source_hash()
    t_all = time.perf_counter()
    engines, skipped = usable(opts.engines)  # e.g. no compiler for Box2D v3: say so, run the rest
    for e, why in skipped.items():
        print(f"bench: {e} skipped: {why}", file=sys.stderr)
    res["meta"]["engines"], res["meta"]["engines_skipped"] = list(engines), skipped
    opts = dataclasses.replace(opts, engines=engines)
    configs = {m: configs_for(m, quick) for m in opts.modes}
    parts = opts.parts
    bar = tqdm(total=_units(opts, configs), unit="run", dynamic_ncols=True, file=sys.stderr)
    try:  # the bar is closed however the run ends (an unreachable scheduler fails on entry)
        with _sweep(opts, parts, bar) as sweep, _records(opts) as records:
            _parts(opts, parts, configs, res, bar, sweep, records)
    finally:
        bar.close()
    res["meta"]["wall_s"] = time.perf_counter() - t_all
    res["meta"]["where"] = sweep.where if sweep is not None else "this process"
    return res


@contextlib.contextmanager
def _sweep(opts, parts, bar):
    """The Dask sweep of the speed and accuracy cases (None when neither part runs)."""
    if not {"speed", "accuracy"} & set(parts):
        yield None
        return
    bar.set_description("starting the Dask workers" if opts.scheduler is None else "connecting")
    with Sweep(opts.scheduler, progress=False) as sweep:
        yield sweep


@contextlib.contextmanager
def _records(opts):
    keep = dict(quick=opts.quick, tiny=opts.tiny, engines=list(opts.engines), budget_s=opts.budget_s)
    records = open_records(opts.results, "bench", keep, opts.resume) if opts.results is not None else None
    try:
        yield records
    finally:
        if records is not None:
            records.close()


def _parts(opts, parts, configs, res, bar, sweep, records):
    """Run the chosen parts in order into ``res``."""
    quick = opts.quick or opts.tiny
    if "compile" in parts:
        # cold: the main mode only (every other mode's first use shows as its first step below)
        bar.set_description("compile: cold start of the default mode (subprocess)")
        res["compile"] = compile_times([opts.main_mode], ("cold",))
    if "overhead" in parts:
        bar.set_description("overhead per step")
        res["overhead"] = overhead(opts.modes, reps=4000 if quick else 20000)
    if "speed" in parts:
        _speed(opts, configs, res, bar, sweep, records)
    if "scaling" in parts:
        res["scaling"] = scaling(opts.scale_ns(), opts.main_mode, opts.engines, bar)
    if "accuracy" in parts:
        res["accuracy"] = accuracy_runs(opts.modes, quick, opts.engines, bar, sweep, records)
    if "profile" in parts:
        _profile(opts, res, bar)
    if "compile" in parts:
        _cached_start(opts, res, bar)
