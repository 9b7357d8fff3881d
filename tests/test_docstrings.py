"""Every public name of ``physics`` has a docstring, and the examples in them run (issue 21).

The walk is the API reference's own (tools/docs/coverage.py, griffe, static): every name in
``physics.__all__`` and each public member of the classes it exports, inherited ones included."""
import doctest
import importlib
import pkgutil

import physics
from tools.docs.coverage import measure


def test_every_public_name_has_a_docstring():
    cov = measure("physics")
    assert len(cov.documented) > 100  # the walk saw the API (World, Body, shapes, ...), not nothing
    assert cov.missing == [], "public names without a docstring:\n  " + "\n  ".join(cov.missing)


def _modules():
    for m in pkgutil.walk_packages(physics.__path__, "physics."):
        if not m.name.endswith("__main__"):
            yield importlib.import_module(m.name)


def test_the_docstring_examples_run():
    finder, runner = doctest.DocTestFinder(), doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    with_examples = set()
    for mod in [physics, *_modules()]:
        for test in finder.find(mod, mod.__name__):
            if test.examples:
                runner.run(test)
                with_examples.add(test.name.rsplit(".", 1)[-1])
    res = runner.summarize(verbose=False)
    # the main entry points carry examples (the walk found them: it did not test nothing)
    assert {"World", "solvers_available"} <= with_examples
    assert res.failed == 0
