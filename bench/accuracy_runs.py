"""The accuracy sweep: every accuracy scenario (bench/accuracy.py) in every engine, mode and
setting at dt 1/60, plus the time-step and integrator sweeps of each mode's defaults."""
from __future__ import annotations

from . import accuracy
from .cases import AccuracyCase
from .configs import configs_for, uses_integrator
from .engines import build
from .engines.ours import OursSim

DT = 1 / 60


def accuracy_cases(modes, quick=False, engines=()) -> list[AccuracyCase]:
    """References at every dt first, then per mode each configuration at 1/60 and (full run) the
    defaults at the other dts and with the other integrators the mode honours."""
    dts = (DT,) if quick else (1 / 30, DT, 1 / 120)
    jobs = [(e, None, dt, None) for e in engines for dt in dts]
    for mode in modes:
        uses_int = uses_integrator(mode)
        for cfg in configs_for(mode, quick):
            jobs.append(("stelkropp", cfg, DT, None))
            if cfg.default and not quick:
                jobs += [("stelkropp", cfg, dt, None) for dt in dts if dt != DT]
                if uses_int:
                    jobs += [("stelkropp", cfg, DT, integ) for integ in ("euler", "rk4")]
    out = []
    for engine, cfg, dt, integ in jobs:
        names = tuple(accuracy.SCENARIOS) if dt == DT and integ is None else tuple(accuracy.DT_SCENARIOS)
        out.append(AccuracyCase(engine, cfg, dt, integ, names))
    return out


def case_label(case) -> str:
    """The configuration's label in tables (the engine's name for a reference)."""
    if case.config is None:
        return case.engine
    return case.config.label + (f" integrator={case.integrator}" if case.integrator else "")


def run_accuracy_case(case) -> list[dict]:
    """One row per metric of every scenario of ``case``."""
    rows = []
    if case.config is not None:
        cfg, integ = case.config, case.integrator

        def make(d):
            return OursSim(d, solver=cfg.mode, settings=cfg.settings, integrator=integ)
        head = dict(engine="stelkropp", mode=cfg.mode, label=case_label(case), settings=cfg.settings, dt=case.dt,
                    integrator=integ or "symplectic_euler")
        is_default = cfg.default and integ is None
    else:
        def make(d):
            return build(case.engine, d)
        head = dict(engine=case.engine, mode=case.engine, label=case.engine, settings={}, dt=case.dt,
                    integrator=None)
        is_default = True
    for name in case.names:
        for m in accuracy.run_scenario(name, make, case.dt):
            rows.append(dict(head, scenario=name, default=is_default, **m))
    return rows


def accuracy_runs(modes, quick=False, engines=(), progress=None, sweep=None, records=None) -> list[dict]:
    """Rows of the whole sweep (the progress bar's total grows by the case count).  The cases
    (figures, no timings) run side by side on ``sweep`` (bench/sweep.py; None: here, in turn),
    each into ``records`` as it finishes."""
    from .sweep import run_cases
    cases = accuracy_cases(modes, quick, engines)
    if progress:
        progress.total += len(cases)
        progress.refresh()
    outs = run_cases(sweep, run_accuracy_case, cases, accuracy_key, progress, records,
                     label=lambda c: f"accuracy: {case_label(c)} dt=1/{round(1 / c.dt)}")
    return [row for rows in outs for row in rows]


def accuracy_key(case) -> str:
    """An accuracy case's name in a results file."""
    return f"accuracy {case.engine} {case_label(case)} dt={case.dt!r} {','.join(case.names)}"
