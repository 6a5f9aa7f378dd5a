"""Regression tests: valid inputs rejected; errors without a location."""

from __future__ import annotations

import io
import re
from contextlib import redirect_stderr, redirect_stdout

from al2py import cli


def _main(path):
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        status = cli.main([str(path)])
    return status, out.getvalue(), err.getvalue()


def test_long_flat_sum_converts(tmp_path):
    path = tmp_path / "long.al"
    path.write_text("Constants A\nE = " + "+".join(["A"] * 400) + "\n")
    status, out, err = _main(path)
    assert status == 0, err
    compile(out, "long.py", "exec")


def test_too_deep_error_has_a_location(tmp_path):
    path = tmp_path / "long.al"
    path.write_text("Constants A\nE = " + "+".join(["A"] * 5000) + "\n")
    status, _, err = _main(path)
    assert status in (0, 2)
    if status == 2:
        assert re.match(r"^.+:\d+:\d+: error: ", err), err


def test_utf8_bom_is_accepted(tmp_path):
    path = tmp_path / "bom.al"
    path.write_bytes(b"\xef\xbb\xbfConstants A\nE = A\n")
    status, out, err = _main(path)
    assert status == 0, err
