"""Shared pytest configuration for the circledist reference suite.

* registers the hypothesis profile "circledist" (deadline off, 60 examples,
  derandomized so that every run checks the same examples, no shrinking).  Select another
  profile with HYPOTHESIS_PROFILE=<name> (e.g. "circledist-long", 600 examples).

The shared cases and references are the package circledist_cases (the repository's root is on
pytest's pythonpath, pyproject.toml).
"""

import os

import pytest

try:
    from hypothesis import HealthCheck, Phase, settings

    settings.register_profile(
        "circledist",
        deadline=None,
        max_examples=60,
        derandomize=True,
        print_blob=True,
        # no shrinking by default: a failing property reports its first counter-example at
        # once instead of spending ~25 s minimising it (the long profile shrinks)
        phases=[Phase.explicit, Phase.reuse, Phase.generate, Phase.target],
        suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much, HealthCheck.data_too_large],
    )
    settings.register_profile(
        "circledist-long",
        parent=settings.get_profile("circledist"),
        max_examples=600,
        derandomize=False,
        phases=list(Phase),
    )
    settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "circledist"))
except ImportError:  # pragma: no cover - hypothesis is a test requirement
    pass


@pytest.fixture(scope="session")
def cd():
    """The module under test (tests needing it are skipped while it does not import)."""
    return pytest.importorskip("circledist", exc_type=ImportError)


@pytest.fixture
def umask_022():
    """The process's umask 0o022 for the test (files made 0o644), restored after it."""
    old = os.umask(0o022)
    yield
    os.umask(old)


def pytest_sessionfinish(session):
    """In record mode (CIRCLEDIST_REFERENCES=record: python -m tools.references record) the
    references this process computed are written to tests/references/ (each pytest-xdist worker
    adds its own)."""
    if os.environ.get("CIRCLEDIST_REFERENCES") == "record":
        from circledist_cases import reference_store

        reference_store.write_recorded()
