"""pytest plugin: Autolev scripts as tests (``pytest --al2py models/``).

With the plugin enabled, every ``*.al`` file pytest meets becomes one test
item that does what ``al2py check`` does for it: convert, import the
generated module in a fresh process (with a timeout), and compare each
response with the transcript ``NAME.all`` beside the script, if there is one.
A failing item shows the same report as ``al2py check``.

The plugin is installed with al2py (entry point ``pytest11``) but stays OFF
unless enabled, by ``--al2py`` on the command line or in an ini file::

    [pytest]            # or [tool.pytest.ini_options] in pyproject.toml
    al2py = true
    al2py_timeout = 120 # seconds per script (default 300)

Skip include-only fragments the usual way (``--ignore-glob='*/include/*'``,
``collect_ignore_glob`` in a ``conftest.py``).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from . import batch

__all__ = ["AutolevFile", "AutolevItem", "AutolevCheckFailed"]


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("al2py", "Autolev scripts as tests (al2py)")
    group.addoption(
        "--al2py",
        action="store_true",
        default=False,
        help="collect *.al scripts as tests: convert, import and compare with "
        "the NAME.all transcript beside each (also: ini 'al2py = true')",
    )
    group.addoption(
        "--al2py-timeout",
        type=float,
        default=None,
        metavar="SECONDS",
        help="give up on a script after SECONDS (default: ini al2py_timeout, 300)",
    )
    parser.addini(
        "al2py",
        type="bool",
        default=False,
        help="collect *.al scripts as tests (like --al2py)",
    )
    parser.addini(
        "al2py_timeout",
        default=str(batch.DEFAULT_TIMEOUT),
        help="seconds per Autolev script before it counts as an error (default 300)",
    )


def _enabled(config: pytest.Config) -> bool:
    return bool(config.getoption("al2py") or config.getini("al2py"))


def _timeout(config: pytest.Config) -> float:
    given = config.getoption("al2py_timeout")
    if given is not None:
        return float(given)
    try:
        return float(config.getini("al2py_timeout"))
    except ValueError:
        raise pytest.UsageError("ini al2py_timeout: not a number of seconds") from None


def pytest_collect_file(
    file_path: Path, parent: pytest.Collector
) -> pytest.Collector | None:
    if file_path.suffix.lower() == ".al" and _enabled(parent.config):
        return AutolevFile.from_parent(parent, path=file_path)
    return None


class AutolevCheckFailed(Exception):
    """Raised by an item whose script failed or errored; carries the result."""

    def __init__(self, result: batch.FileResult) -> None:
        super().__init__(result.status)
        self.result = result


class AutolevFile(pytest.File):
    """An ``.al`` script: one item, named after the script."""

    def collect(self):
        yield AutolevItem.from_parent(self, name=self.path.stem)


class AutolevItem(pytest.Item):
    """Convert, import and check one script, as ``al2py check`` does."""

    def runtest(self) -> None:
        script = batch.Script(self.path, Path(self.path.name))
        result = batch.check_file(script, timeout=_timeout(self.config))
        self.user_properties.append(("al2py_status", result.status))
        if result.transcript:
            self.user_properties.append(("al2py_responses", result.responses))
        for note in result.notes:  # what a passing check did not cover
            self.user_properties.append(("al2py_note", note))
            self.warn(pytest.PytestWarning(f"{self.path.name}: {note}"))
        if result.status != batch.PASSED:
            raise AutolevCheckFailed(result)

    def repr_failure(self, excinfo, style=None):  # type: ignore[override]
        if isinstance(excinfo.value, AutolevCheckFailed):
            return batch.format_file_report(excinfo.value.result)
        return super().repr_failure(excinfo, style=style)

    def reportinfo(self):
        return self.path, None, f"al2py check {self.path.name}"
