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


def accuracy_runs(modes, quick=False, engines=(), progress=None) -> list[dict]:
    """Rows of the whole sweep, case by case (the progress bar's total grows by the case count)."""
    cases = accuracy_cases(modes, quick, engines)
    if progress:
        progress.total += len(cases)
        progress.refresh()
    rows = []
    for case in cases:
        if progress:
            progress.set_description(f"accuracy: {case_label(case)} dt=1/{round(1 / case.dt)}"[:60])
        rows += run_accuracy_case(case)
        if progress:
            progress.update(1)
    return rows
