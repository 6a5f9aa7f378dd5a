"""Autolev's own programs as the judge (issue 23).

Research groups published the C programs Autolev generated from their
scripts.  For each such pair found in the fetched repositories (the git
mirrors under ``$ALMIRROR``, default ``../.mirror`` beside the checkout),
this checker

* extracts the script (with the ``.al``/``.a``/``.r`` files of its folder)
  and Autolev's program into a temporary folder (nothing is kept);
* converts the script with ``python -m al2py`` and imports the module;
* writes the program's ``.in`` file in Autolev's layout (six heading lines,
  one value per line from column 60, a blank line after each group, in the
  order of the program's ``readf`` calls) from the script's Inputs, with
  seeded values for the quantities the script gives none;
* compiles the program with ``cc`` and runs it; then loads it again as a
  shared library (``main`` renamed) to call its equations at chosen states;
* compares Autolev's output files with ``run()``'s tables column by column
  (``1e-8 + 1e-5 * max|column|``: Autolev prints 7 digits), the state
  derivatives Autolev's ``eqns1`` computes with ``ode_function()`` at the
  initial state and at a perturbed one (``1e-9`` relative), and every
  ``Encode``d array Autolev's program computes with the module's value.

    python benchmarks/autolev_programs.py            # every pair, a table
    python benchmarks/autolev_programs.py --list     # the pairs found
    python benchmarks/autolev_programs.py Pendulum   # pairs whose name matches

Exit status 1 when a pair differs.
"""

from __future__ import annotations

import argparse
import contextlib
import ctypes
import importlib.util
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
import zlib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
#: Autolev prints its tables with 7 significant digits (``%- 14.6E``).
TABLE_ATOL, TABLE_RTOL = 1e-8, 1e-5
RHS_RTOL = 1e-9
INTEGRATION = ("TINITIAL", "TFINAL", "INTEGSTP", "_PRINTINT", "ABSERR", "RELERR")


def mirror_root() -> Path:
    env = os.environ.get("ALMIRROR")
    return Path(env) if env else ROOT.parent / ".mirror"


# --------------------------------------------------------------------- pairs


@dataclass(frozen=True)
class Pair:
    """An Autolev script and a program Autolev generated from it."""

    repo: str  # owner+name, the mirror folder
    script: str  # path in the repository
    program: str  # path in the repository
    kind: str  # "dynamics" | "algebraic" (raw C with main) | "cleaned" | "matlab"
    slow: bool = False

    @property
    def name(self) -> str:
        return f"{self.repo.split('+')[1]}:{Path(self.program).name}"

    def git_dir(self, root: Path | None = None) -> Path:
        return (root or mirror_root()) / self.repo / "repo"


def _git(git_dir: Path, *args: str) -> str:
    return subprocess.run(
        ["git", "-C", str(git_dir), *args],
        check=True,
        capture_output=True,
        text=True,
    ).stdout


def _show(git_dir: Path, path: str) -> str:
    return subprocess.run(
        ["git", "-C", str(git_dir), "show", f"HEAD:{path}"],
        check=True,
        capture_output=True,
    ).stdout.decode("latin-1")


_CODE = re.compile(r"^\s*code\s+(\w+)\s*\([^)]*\)\s+(\S+)", re.I | re.M)
_SLOW = ("whipple", "das3", "gait3d", "gait10dof18musc", "gait2d_osim")


def discover(root: Path | None = None) -> list[Pair]:
    """Every script whose ``CODE`` statement names a file Autolev wrote
    that is in the same repository (beside the script, or elsewhere by
    its name, case-insensitively; ``X_raw.c`` also as ``X.c`` after
    ``autolevclean``)."""
    root = root or mirror_root()
    pairs: list[Pair] = []
    if not root.is_dir():
        return pairs
    for repo_dir in sorted(root.iterdir()):
        git_dir = repo_dir / "repo"
        if not git_dir.exists():
            continue
        try:
            files = _git(git_dir, "ls-tree", "-r", "--name-only", "HEAD").splitlines()
        except subprocess.CalledProcessError:
            continue
        by_name: dict[str, list[str]] = {}
        for f in files:
            by_name.setdefault(Path(f).name.lower(), []).append(f)
        for script in files:
            if not script.lower().endswith(".al"):
                continue
            text = _show(git_dir, script)
            for kind, target in _CODE.findall(text):
                target = target.replace("\\", "/")
                base = Path(target).name.lower()
                found = _locate(script, target, files, by_name)
                cleaned = False
                if not found and base.endswith("_raw.c"):
                    found = _locate(script, target[:-6] + ".c", files, by_name)
                    cleaned = bool(found)
                if not found:
                    continue
                if base.endswith(".m"):
                    what = "matlab"
                elif cleaned:
                    what = "cleaned"
                else:
                    what = "dynamics" if kind.lower() in ("dynamics", "ode") else kind
                    what = what.lower()
                slow = any(s in script.lower() for s in _SLOW)
                pairs.append(Pair(repo_dir.name, script, found, what, slow))
    return pairs


def _locate(script, target, files, by_name) -> str | None:
    folder = str(Path(script).parent)
    beside = os.path.normpath(os.path.join(folder, target)).lower()
    for f in files:
        if f.lower() == beside:
            return f
    same = [f for f in by_name.get(Path(target).name.lower(), [])]
    return same[0] if len(same) == 1 else None


def present(pair: Pair, root: Path | None = None) -> bool:
    """Whether the program's blob is in the mirror (a snapshot may list its
    largest files without their contents)."""
    proc = subprocess.run(
        [
            "git",
            "-C",
            str(pair.git_dir(root)),
            "cat-file",
            "-e",
            f"HEAD:{pair.program}",
        ],
        capture_output=True,
    )
    return proc.returncode == 0


# ------------------------------------------------------------------- results


@dataclass
class Row:
    """One comparison: what, the largest error over the allowed one."""

    what: str
    max_error: float
    allowed: float
    detail: str = ""

    @property
    def ok(self) -> bool:
        return self.max_error <= self.allowed


@dataclass
class Report:
    pair: Pair
    rows: list[Row] = field(default_factory=list)
    skipped: str | None = None
    seconds: float = 0.0
    notes: list[str] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return self.skipped is None and all(r.ok for r in self.rows)

    def verdict(self) -> str:
        if self.skipped:
            return "not compared"
        return "match" if self.ok else "DIFFERS"


# --------------------------------------------------------------- extraction


def extract(pair: Pair, dest: Path, root: Path | None = None) -> tuple[Path, Path]:
    """The script with its folder's macro and RUN files, and the program,
    written under ``dest`` (the program keeps its path relative to the
    script's folder when it lies below it)."""
    git_dir = pair.git_dir(root)
    folder = str(Path(pair.script).parent)
    base = _run_root(git_dir, pair.script)
    under = f"{base}/" if base != "." else ""
    listing = _git(git_dir, "ls-tree", "-r", "--name-only", "HEAD", under)
    for f in listing.splitlines():
        rel = Path(f).relative_to(base) if base != "." else Path(f)
        if base == folder and len(rel.parts) > 1:
            continue  # only the script's own folder
        if f.lower().endswith((".al", ".a", ".r")):
            (dest / rel).parent.mkdir(parents=True, exist_ok=True)
            (dest / rel).write_text(_show(git_dir, f), encoding="latin-1")
    prog = dest / "autolev" / Path(pair.program).name
    prog.parent.mkdir(parents=True, exist_ok=True)
    prog.write_text(_show(git_dir, pair.program), encoding="latin-1")
    if pair.kind == "cleaned":  # the header the cleaned file includes
        pfolder = str(Path(pair.program).parent)
        for f in _git(
            git_dir, "ls-tree", "--name-only", "HEAD", f"{pfolder}/"
        ).splitlines():
            if f.endswith(".h"):
                (prog.parent / Path(f).name).write_text(_show(git_dir, f), "latin-1")
    script = Path(pair.script)
    return dest / (script.relative_to(base) if base != "." else script), prog


def _run_root(git_dir: Path, script: str) -> str:
    """The folder Autolev ran the script in: its own, or its parent where
    a ``RUN sub/x.al`` names a file from there (BioMAC's NoDer scripts RUN
    ``gait2d_osim/gait2d_osim_FK.al`` from c_files/)."""
    folder = Path(script).parent
    files = set(_git(git_dir, "ls-tree", "-r", "--name-only", "HEAD").splitlines())
    for target in re.findall(r"^\s*run\s+(\S+)", _show(git_dir, script), re.I | re.M):
        target = target.replace("\\", "/")
        if str(folder / target) not in files and str(folder.parent / target) in files:
            return str(folder.parent)
    return str(folder)


def convert_and_import(script: Path, run_dir: Path | None = None):
    """``python -m al2py SCRIPT -o model.py`` beside the script, imported;
    ``run_dir`` (the folder Autolev ran it in, see _run_root) is put on
    AUTOLEVPATH."""
    out = script.parent / f"_al2py_{abs(hash(script.name)) % 10**8}.py"
    env = dict(os.environ)
    if run_dir is not None:
        env["AUTOLEVPATH"] = str(run_dir)
    proc = subprocess.run(
        [sys.executable, "-m", "al2py", script.name, "-o", out.name],
        cwd=script.parent,
        capture_output=True,
        text=True,
        env=env,
    )
    if proc.returncode:
        raise RuntimeError(f"al2py failed:\n{proc.stdout}{proc.stderr}")
    spec = importlib.util.spec_from_file_location(out.stem, out)
    module = importlib.util.module_from_spec(spec)
    with contextlib.chdir(script.parent):
        spec.loader.exec_module(module)
    return module


# ------------------------------------------------------------ Autolev's C


@dataclass
class CProgram:
    """What the checker needs to know about an Autolev C program."""

    source: str
    groups: list[list[str]]  # readf groups, C names in order
    infile: str  # relative path main opens for reading
    outfiles: str | None  # printf pattern of output files (``X.%d``)
    state: list[str]  # VAR[i] = name, in order
    arrays: dict[str, tuple[int, ...]]  # global double arrays and shapes

    @classmethod
    def parse(cls, source: str) -> CProgram:
        body = re.sub(r"\s+", " ", source)
        groups = [
            [a.strip().lstrip("&").strip() for a in m.group(1).split(",")]
            for m in re.finditer(r"readf\(Fptr\[0\],(.*?),\s*NULL\);", body)
        ]
        m_in = re.search(r'strcpy\(fileName, "([^"]+)"\)', source)
        infile = m_in.group(1) if m_in else ""
        out = re.search(r'sprintf\(fileName, "([^"]+)", iloop\)', source)
        nout = re.search(r"iloop<=(\d+);", source)
        outfiles = out.group(1) if out and nout and int(nout.group(1)) > 0 else None
        state = [
            name
            for _i, name in sorted(
                (int(i), n) for i, n in re.findall(r"VAR\[(\d+)\] = (\w+);", source)
            )
        ]
        arrays: dict[str, tuple[int, ...]] = {}
        for decl in re.findall(r"^double\s+(.*?);", source, re.M | re.S):
            for m in re.finditer(r"(\w+)((?:\[\s*\d+\s*\])+)", decl):
                dims = tuple(int(d) for d in re.findall(r"\d+", m.group(2)))
                arrays[m.group(1)] = dims
        # the unnamed static ``z`` is Autolev's intermediates, not a result
        arrays.pop("z", None)
        return cls(source, groups, infile, outfiles, state, arrays)

    def _functions(self) -> list[tuple[int, int]]:
        """Spans of the function definitions (a header at column 0)."""
        heads = [
            m.start()
            for m in re.finditer(r"^(?:void|int)\s+\w+\s*\(", self.source, re.M)
        ]
        return list(zip(heads, heads[1:] + [len(self.source)], strict=True))

    def _hiding(self) -> list[tuple[int, int, str]]:
        """(function span, name) where a function declares a local ``int``
        named like a script quantity and never assigns it: its uses mean
        the script's quantity (Autolev's ``output()`` declares ``int i1;``,
        so a constant ``I1`` reads as that uninitialized local there)."""
        globals_ = set()
        for decl in re.findall(r"^double\s+(.*?);", self.source, re.M | re.S):
            globals_.update(re.findall(r"(\w+)(?:\[[^]]*\])*\s*(?:,|$)", decl))
        found = []
        for a, b in self._functions():
            body = self.source[a:b]
            for decl in re.findall(r"^int\s+([\w, ]+);", body, re.M):
                for name in (n.strip() for n in decl.split(",")):
                    assigned = re.search(rf"\b{name}\s*(?:=[^=]|\+\+|--|\+=|-=)", body)
                    if name in globals_ and not assigned:
                        found.append((a, b, name))
        return found

    def shadowed(self) -> list[str]:
        return sorted({name for _a, _b, name in self._hiding()})

    def unshadowed(self) -> str:
        """The source with each hiding local declaration renamed."""
        src = self.source
        for a, b, name in sorted(self._hiding(), reverse=True):
            body = re.sub(
                rf"^(int\s+(?:[\w, ]+,\s*)?){name}\b",
                rf"\g<1>{name}_local_",
                src[a:b],
                flags=re.M,
            )
            src = src[:a] + body + src[b:]
        return src


def write_in(prog: CProgram, values: dict[str, float], path: Path) -> None:
    """The ``.in`` file in Autolev's layout: the program skips six lines,
    reads each value from column 60 of its line (``strtod``), and skips
    one line after each group."""
    lines = [
        f"File: {path.name}",
        "-" * 77,
        "Note: written by al2py's checker.",
        "-" * 58 + "+" + "-" * 18,
        "Description  Quantity  Units".ljust(58) + "| Value",
        "-" * 58 + "|" + "-" * 18,
    ]
    for group in prog.groups:
        for name in group:
            label = f"Value                {name}"[:57].ljust(58)
            lines.append(f"{label}| {values[name.upper()]!r}")
        lines.append("")
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n" * 4)


def compile_program(src: Path, *, shared: bool) -> Path:
    out = src.with_suffix(".so" if shared else ".exe")
    cmd = ["cc", "-O0", "-w", "-o", str(out), str(src), "-lm"]
    if shared:
        cmd[1:1] = ["-shared", "-fPIC", "-Dmain=autolev_main"]
    subprocess.run(cmd, check=True, capture_output=True, text=True)
    return out


def read_table(path: Path) -> np.ndarray:
    rows = []
    for line in path.read_text().splitlines():
        if line.strip() and not line.startswith("%"):
            rows.append([float(x) for x in line.split()])
    return np.array(rows)


@contextlib.contextmanager
def _quiet_stdout():
    """Send the C library's stdout to /dev/null (Autolev's main prints
    every row)."""
    libc = ctypes.CDLL(None)
    sys.stdout.flush()
    saved = os.dup(1)
    with open(os.devnull, "w") as null:
        os.dup2(null.fileno(), 1)
    try:
        yield
    finally:
        libc.fflush(None)
        os.dup2(saved, 1)
        os.close(saved)


class Loaded:
    """An Autolev program as a shared library: its globals by name."""

    def __init__(self, so: Path, prog: CProgram):
        self.lib = ctypes.CDLL(str(so))
        self.prog = prog

    def main(self, cwd: Path) -> None:
        with contextlib.chdir(cwd), _quiet_stdout():
            self.lib.autolev_main()

    def array(self, name: str) -> np.ndarray:
        dims = self.prog.arrays[name]
        n = math.prod(dims)
        return np.array((ctypes.c_double * n).in_dll(self.lib, name)).reshape(dims)

    def eqns1(self, t: float, y: list[float]) -> np.ndarray:
        n = len(y)
        var = (ctypes.c_double * n)(*y)
        varp = (ctypes.c_double * n)()
        fn = self.lib.eqns1
        fn.argtypes = [ctypes.c_double, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_char]
        fn(t, var, varp, b"\0")
        return np.array(varp)


# ----------------------------------------------------------- value choice


def _seeded(name: str, lo: float, hi: float) -> float:
    """A value for a quantity the script gives none: fixed per name."""
    seed = zlib.crc32(name.upper().encode())
    return float(np.random.default_rng(seed).uniform(lo, hi))


def _al_name(cname: str, variables: dict[str, int]) -> str:
    """Autolev's C spells ``Q1'`` as ``q1p`` and ``Q1''`` as ``q1pp``."""
    up = cname.upper()
    for k in (2, 1):
        base = up[:-k]
        if up.endswith("P" * k) and variables.get(base, -1) >= k:
            return base + "'" * k
    return up


def job_for(module, program: str):
    for job in module.al.numerics.jobs:
        if job.filename and Path(job.filename.replace("\\", "/")).name.lower() == (
            Path(program).name.lower()
        ):
            return job
    raise LookupError(f"no CODE statement writes {program}")


def _values(prog: CProgram, job, integration: dict[str, float]) -> dict[str, float]:
    """Values for every name the program reads: the script's Input (in its
    own unit, as the program reads it), else a seeded one."""
    variables = {name.upper(): order for name, _obj, order in job.variables}
    inputs = {k.upper(): v.value for k, v in job.inputs.items()}
    values = {}
    for group in prog.groups:
        for cname in group:
            up = cname.upper()
            if up in INTEGRATION:
                values[up] = integration[up]
            elif _al_name(cname, variables) in inputs:
                values[up] = float(inputs[_al_name(cname, variables)])
            elif _al_name(cname, variables).rstrip("'") in variables:
                values[up] = _seeded(up, -0.6, 0.6)
            else:
                values[up] = _seeded(up, 0.5, 1.5)
    return values


def _overrides(prog: CProgram, job, values: dict[str, float]) -> dict[str, float]:
    variables = {name.upper(): order for name, _obj, order in job.variables}
    out = {}
    for group in prog.groups:
        for cname in group:
            if cname.upper() in INTEGRATION:
                continue
            out[_al_name(cname, variables)] = values[cname.upper()]
    for key in ("TINITIAL", "TFINAL", "INTEGSTP", "ABSERR", "RELERR"):
        if key in values:
            out[key] = values[key]
    if "_PRINTINT" in values:
        out["PRINTINT"] = int(values["_PRINTINT"])
    return out


def _rel(a: np.ndarray, b: np.ndarray) -> float:
    a, b = np.asarray(a, float), np.asarray(b, float)
    scale = max(np.max(np.abs(b), initial=0.0), 1e-300)
    return float(np.max(np.abs(a - b), initial=0.0) / max(scale, 1.0))


# --------------------------------------------------------------- checking


def check(
    pair: Pair,
    root: Path | None = None,
    keep: Path | None = None,
    same_language: bool = False,
) -> Report:
    """Compare Autolev's program with al2py's module; with ``same_language``
    also with the program ``al2py code`` writes for the same ``CODE``
    statement (rows named ``al2py C``/``al2py MATLAB``)."""
    report = Report(pair)
    start = time.perf_counter()
    if pair.kind == "matlab" and shutil.which("octave") is None:
        report.skipped = "MATLAB program: needs GNU Octave (octave not on PATH)"
        return report
    if pair.kind != "matlab" and shutil.which("cc") is None:
        report.skipped = "no C compiler (cc)"
        return report
    if not present(pair, root):
        report.skipped = (
            f"{pair.program} is listed in the repository's tree but its blob"
            " is absent from the mirror (git cat-file -e fails)"
        )
        return report
    with tempfile.TemporaryDirectory(prefix="al2py-judge-") as tmp:
        work = keep or Path(tmp)
        script, program = extract(pair, work, root)
        module = convert_and_import(script, work if script.parent != work else None)
        written = pair.program
        if pair.kind == "cleaned":  # the CODE statement wrote X_raw.c
            written = str(Path(pair.program).with_suffix("")) + "_raw.c"
        job = job_for(module, written)
        ours = None
        if same_language:
            run_dir = work if script.parent != work else None
            ours = OurProgram.write(report, script, written, run_dir)
        if pair.kind == "cleaned":
            _check_cleaned(report, module, job, program, ours)
        elif pair.kind == "matlab":
            _check_matlab(report, module, job, program, ours)
        elif job.kind in ("DYNAMICS", "ODE"):
            _check_dynamics(report, module, job, program, ours)
        else:
            _check_algebraic(report, module, job, program, ours)
    report.seconds = time.perf_counter() - start
    return report


def _integration_for(job, tight: bool = True) -> dict[str, float]:
    inputs = {k.upper(): v.value for k, v in job.inputs.items()}
    t0 = float(inputs.get("TINITIAL", 0.0))
    t1 = float(inputs.get("TFINAL", t0 + 2.0))
    step = float(inputs.get("INTEGSTP", (t1 - t0) / 100))
    return {
        "TINITIAL": t0,
        "TFINAL": t1,
        "INTEGSTP": step,
        "_PRINTINT": float(int(inputs.get("PRINTINT", 1))),
        # both integrators run tight, so the tables judge the equations
        "ABSERR": 1e-11,
        "RELERR": 1e-11,
    }


def _check_dynamics(
    report: Report, module, job, program: Path, ours: OurProgram | None = None
) -> None:
    from al2py_runtime.jobs import run as rjobs

    prog = _unshadow(report, program)
    cwd = program.parent
    exe = compile_program(program, shared=False)
    for label, perturb in (("script Inputs", False), ("perturbed state", True)):
        integ = _integration_for(job)
        values = _values(prog, job, integ)
        if perturb:
            for name in prog.state:
                values[name.upper()] = _seeded(name + "~", -0.5, 0.5)
        values = _run_program(report, label, prog, exe, values)
        if ours is not None and prog.outfiles:
            # the very .in file Autolev's program read
            shutil.copy(cwd / prog.infile, ours.folder / prog.infile)
            ours.run()
            _compare_files(report, f"{label}: {ours.label}", cwd, ours.folder)
        overrides = _overrides(prog, job, values)
        result = rjobs.run_job(job, overrides)
        tables = (
            [t for t in result.tables if not t.encoded]
            if hasattr(result.tables[0], "encoded")
            else result.tables
        )
        if prog.outfiles:
            _compare_tables(report, label, tables, cwd, prog.outfiles)
        # The right-hand side and encoded arrays at the initial state: the
        # program's main with TFINAL = TINITIAL computes its constants and
        # calls output() once.
        values0 = dict(values, TFINAL=values["TINITIAL"])
        write_in(prog, values0, cwd / prog.infile)
        so = compile_program(program, shared=True)
        lib = Loaded(so, prog)
        lib.main(cwd)
        f, y0, names = rjobs.ode_function(job, overrides)
        variables = {n.upper(): o for n, _obj, o in job.variables}
        y_al = dict(zip(names, y0, strict=True))
        ours_d = dict(
            zip(names, f(values["TINITIAL"], np.array(y0, float)), strict=True)
        )
        var = [y_al[_al_name(n, variables)] for n in prog.state]
        theirs_d = lib.eqns1(values["TINITIAL"], var)
        ours_v = np.array([ours_d[_al_name(n, variables)] for n in prog.state])
        report.rows.append(
            Row(
                f"{label}: state derivatives at t0 ({len(var)})",
                _rel(ours_v, theirs_d),
                RHS_RTOL,
            )
        )
        _compare_encoded(report, label, job, lib, result, row=0)
        del lib


def _run_program(report, label, prog: CProgram, exe: Path, values: dict) -> dict:
    """Run Autolev's program on ``values``; where its integrator gives up
    (a perturbed bicycle falls over), halve the interval, up to four times,
    so that both programs are compared where Autolev's integrates."""
    cwd = exe.parent
    for _ in range(5):
        write_in(prog, values, cwd / prog.infile)
        proc = subprocess.run(
            [str(exe)], cwd=cwd, capture_output=True, text=True, timeout=600
        )
        if proc.returncode:
            raise RuntimeError(f"Autolev's program failed:\n{proc.stdout[-2000:]}")
        if "integration failed" not in proc.stdout:
            return values
        t0, t1 = values["TINITIAL"], values["TFINAL"]
        report.notes.append(
            f"{label}: Autolev's program stops (its integration fails to converge)"
            f" before TFINAL = {t1:g}; compared up to {t0 + (t1 - t0) / 2:g}"
        )
        values = dict(values, TFINAL=t0 + (t1 - t0) / 2)
    raise RuntimeError(f"Autolev's program does not integrate:\n{proc.stdout[-500:]}")


def _compare_tables(report, label, tables, cwd: Path, pattern: str) -> None:
    """Autolev's output files ``pattern % i`` against ``run()``'s tables,
    column by column."""
    for i, table in enumerate(tables, start=1):
        theirs = read_table(cwd / (pattern % i))
        ours = np.asarray(table.data, float)
        if theirs.shape != ours.shape:
            report.rows.append(
                Row(
                    f"{label}: table {i} shape",
                    math.inf,
                    0.0,
                    f"Autolev {theirs.shape}, al2py {ours.shape}",
                )
            )
            continue
        worst, allowed, where = 0.0, 0.0, ""
        for j, col in enumerate(table.columns):
            tol = TABLE_ATOL + TABLE_RTOL * np.max(np.abs(theirs[:, j]))
            err = float(np.max(np.abs(theirs[:, j] - ours[:, j])))
            if err / tol > (worst / allowed if allowed else -1):
                worst, allowed, where = err, tol, col.label
        report.rows.append(
            Row(
                f"{label}: {pattern % i} ({ours.shape[0]}x{ours.shape[1]})",
                worst,
                allowed,
                f"worst column {where}",
            )
        )


def _compare_files(report, label, theirs_dir: Path, ours_dir: Path) -> None:
    """Each output file Autolev's program wrote (``STEM.1``, ...) against
    the one al2py's program wrote, column by column (the tables' rule)."""
    files = sorted(
        f
        for f in theirs_dir.iterdir()
        if re.fullmatch(r"\d+", f.suffix[1:] or "x") and f.is_file()
    )
    if not files:
        report.rows.append(Row(f"{label}: output files", math.inf, 0.0, "none"))
    for theirs_file in files:
        ours_file = ours_dir / theirs_file.name
        what = f"{label}: {theirs_file.name}"
        if not ours_file.exists():
            report.rows.append(Row(what, math.inf, 0.0, "al2py wrote no such file"))
            continue
        theirs, ours = read_table(theirs_file), read_table(ours_file)
        if theirs.shape != ours.shape:
            detail = f"Autolev {theirs.shape}, al2py {ours.shape}"
            report.rows.append(Row(f"{what} shape", math.inf, 0.0, detail))
            continue
        worst, allowed, where = 0.0, 0.0, 0
        for j in range(theirs.shape[1]):
            tol = TABLE_ATOL + TABLE_RTOL * np.max(np.abs(theirs[:, j]))
            err = float(np.max(np.abs(theirs[:, j] - ours[:, j])))
            if err / tol > (worst / allowed if allowed else -1):
                worst, allowed, where = err, tol, j + 1
        shape = f"{ours.shape[0]}x{ours.shape[1]}"
        report.rows.append(
            Row(f"{what} ({shape})", worst, allowed, f"worst column {where}")
        )


@dataclass
class OurProgram:
    """The program ``al2py code`` writes for the same ``CODE`` statement,
    in the language of Autolev's (C compiled with ``cc -std=c99``, MATLAB
    run in Octave), in its own folder."""

    path: Path
    exe: Path | None

    @property
    def folder(self) -> Path:
        return self.path.parent

    @property
    def label(self) -> str:
        return "al2py C" if self.path.suffix == ".c" else "al2py MATLAB"

    @classmethod
    def write(
        cls, report: Report, script: Path, written: str, run_dir: Path | None
    ) -> OurProgram | None:
        folder = script.parent / "al2py_code"
        env = dict(os.environ)
        if run_dir is not None:
            env["AUTOLEVPATH"] = str(run_dir)
        proc = subprocess.run(
            [sys.executable, "-m", "al2py", "code", script.name, "-o", str(folder)],
            cwd=script.parent,
            capture_output=True,
            text=True,
            env=env,
        )
        path = folder / Path(written.replace("\\", "/")).name
        if not path.exists():
            why = (proc.stderr or proc.stdout).strip().splitlines()
            report.notes.append(
                f"al2py code wrote no {path.name}: {why[-1] if why else proc.returncode}"
            )
            return None
        exe = None
        if path.suffix == ".c":
            exe = path.with_suffix(".exe")
            subprocess.run(
                ["cc", "-O0", "-std=c99", "-o", str(exe), str(path), "-lm"],
                check=True,
                capture_output=True,
                text=True,
            )
        return cls(path, exe)

    def run(self) -> None:
        for old in self.folder.glob(f"{self.path.stem}.[0-9]*"):
            old.unlink()
        if self.exe is not None:
            cmd = [str(self.exe)]
        else:
            cmd = [*_OCTAVE, "--eval", self.path.stem]
        proc = subprocess.run(
            cmd, cwd=self.folder, capture_output=True, text=True, timeout=1800
        )
        if proc.returncode or "error" in proc.stderr.lower():
            raise RuntimeError(f"al2py's program failed:\n{proc.stderr[-2000:]}")

    def in_names(self) -> list[str]:
        """The names our ``STEM.in`` reads, in order (upper case)."""
        path = self.folder / f"{self.path.stem}.in"
        return [
            line[21:42].strip().upper()
            for line in path.read_text().splitlines()[6:]
            if len(line) >= 59 and line[58] == "|"
        ]

    def write_in(self, values: dict[str, float]) -> None:
        """Our ``STEM.in`` with ``values`` (by the script's name, upper case)
        put from column 60: the values Autolev's MATLAB program holds."""
        path = self.folder / f"{self.path.stem}.in"
        lines = path.read_text().splitlines()
        for k, line in enumerate(lines[6:], start=6):
            if len(line) < 59 or line[58] != "|":
                continue
            name = line[21:42].strip().upper()
            if name not in values:
                raise LookupError(f"al2py's {path.name} reads {name}, Autolev's not")
            lines[k] = f"{line[:58]}| {values[name]!r}"
        path.write_text("\n".join(lines) + "\n")

    def call_outputs(self) -> dict[str, np.ndarray]:
        """The quantities al2py's C program computes from its ``STEM.in``,
        at full precision: a harness includes the program (its ``main``
        renamed), reads the ``.in`` with the program's own ``al_start``,
        calls its ``outputs`` and prints every value (an ``Encode``d array
        has no output file).  Keyed by the column labels of the program's
        headers: ``FK[1]``, ``DFK_DQ[1,2]`` ... grouped as ``FK``, ``DFK_DQ``
        (row by row)."""
        source = self.path.read_text()
        labels = _header_labels(source)
        stem = self.path.stem
        harness = self.folder / "al2py_own_harness.c"
        exe = harness.with_suffix(".exe")
        if not exe.exists():
            harness.write_text(_OWN_HARNESS.format(program=self.path.name))
            subprocess.run(
                ["cc", "-O0", "-std=c99", "-w", "-I", str(self.folder)]
                + ["-o", str(exe), str(harness), "-lm"],
                check=True,
                capture_output=True,
                text=True,
            )
        proc = subprocess.run(
            [str(exe)], cwd=self.folder, capture_output=True, text=True, timeout=600
        )
        if proc.returncode or proc.stderr:
            raise RuntimeError(f"al2py's {stem} failed:\n{proc.stderr[-2000:]}")
        values = [float(x) for x in proc.stdout.split()]
        if len(values) != len(labels):
            raise RuntimeError(
                f"al2py's {stem}: {len(values)} outputs, {len(labels)} column labels"
            )
        found: dict[str, list[float]] = {}
        for label, value in zip(labels, values, strict=True):
            found.setdefault(label.split("[")[0].upper(), []).append(value)
        return {k: np.array(v) for k, v in found.items()}


#: main() of the harness around al2py's Algebraic C program (no range: the
#: constants p are the inputs v, as the program's own main copies them).
_OWN_HARNESS = """\
#define main al2py_program_main
#include "{program}"
#undef main
#if AL_NIN != AL_NP
#error "the harness calls an Algebraic program without a range"
#endif
int main(void)
{{
    char name[] = "al2py_own_harness";
    char *argv[] = {{name, 0}};
    double v[AL_NIN > 0 ? AL_NIN : 1], p[AL_NP > 0 ? AL_NP : 1], y[1] = {{0.0}};
    static double out[AL_NOUT > 0 ? AL_NOUT : 1];
    if (al_start(1, argv, v)) return 2;
    for (int i = 0; i < AL_NP; i++) p[i] = v[i];
    int code = outputs(AL_T0, y, p, out);
    for (int i = 0; i < AL_NOUT; i++) printf("%.17g\\n", out[i] * al_factor[i]);
    return code;
}}
"""


def _header_labels(source: str) -> list[str]:
    """The column labels of al2py's C program, every table in order: the
    third line of each ``al_header`` string (``%      FK[1]    FK[2] ...``)."""
    block = re.search(r"al_header\[\d+\] = \{(.*?)\n\};", source, re.S)
    if block is None:
        raise ValueError("al2py's program has no al_header")
    labels = []
    for text in re.findall(r'"((?:[^"\\]|\\.)*)"', block.group(1)):
        lines = text.split("\\n")
        labels += lines[2].lstrip("%").split()
    return labels


def _unshadow(report: Report, program: Path) -> CProgram:
    """Parse the program; where a local hides a script name, note it and
    compile the program with the local renamed (Autolev's defect, not the
    script's meaning)."""
    prog = CProgram.parse(program.read_text(encoding="latin-1"))
    hidden = prog.shadowed()
    if hidden:
        report.notes.append(
            "Autolev's program declares local int "
            + ", ".join(hidden)
            + " hiding the script's constant(s) of that name; compared with"
            " the local renamed"
        )
        program.write_text(prog.unshadowed(), encoding="latin-1")
        prog = CProgram.parse(prog.unshadowed())
    return prog


def _compare_encoded(report, label, job, lib, result, row) -> None:
    for name, (m, n) in job.encoded.items():
        cname = next((c for c in lib.prog.arrays if c.upper() == name.upper()), None)
        if cname is None:
            continue
        theirs = lib.array(cname).reshape(m, n)
        # result[NAME] is an array of shape (rows, m, n)
        ours = np.asarray(result[name], float)[row].reshape(m, n)
        report.rows.append(
            Row(f"{label}: Encode {name} ({m}x{n})", _rel(ours, theirs), RHS_RTOL)
        )


def _check_algebraic(
    report: Report, module, job, program: Path, own: OurProgram | None = None
) -> None:
    """Run Autolev's program on seeded values and compare its Encoded
    arrays with the module's; with ``own``, also with those al2py's C
    program computes from the very ``.in`` Autolev's program read."""
    prog = _unshadow(report, program)
    cwd = program.parent
    values = _values(prog, job, {})
    write_in(prog, values, cwd / prog.infile)
    exe = compile_program(program, shared=False)
    proc = subprocess.run(
        [str(exe)], cwd=cwd, capture_output=True, text=True, timeout=600
    )
    if proc.returncode or "error" in proc.stdout.lower():
        raise RuntimeError(f"Autolev's program failed:\n{proc.stdout[-2000:]}")
    from al2py_runtime.jobs.run import run_job

    result = run_job(job, _overrides(prog, job, values))
    lib = Loaded(compile_program(program, shared=True), prog)
    lib.main(cwd)
    _compare_encoded(report, "seeded values", job, lib, result, row=0)
    if own is not None and own.path.suffix == ".c":
        shutil.copy(cwd / prog.infile, own.folder / f"{own.path.stem}.in")
        encoded = {k.upper() for k in job.encoded}
        theirs = {a: lib.array(a) for a in prog.arrays if a.upper() in encoded}
        _compare_own_outputs(report, "seeded values", own, theirs, None)
    if not report.rows:
        report.skipped = "the program computes no Encoded array to compare"


# ------------------------------------------------- cleaned C functions


@dataclass
class CleanedFunction:
    """A function the authors' ``autolevclean`` made of Autolev's code:
    ``void NAME(STRUCT* par, double q[NDOF], ..., double out[N][M])``.
    The script's constant ``par__X`` is the field ``par->X``; an input
    array's elements are named by ``double q1 = q[0];`` lines; every other
    array is an output."""

    name: str
    struct: tuple[str, str] | None  # (type, parameter name)
    arrays: list[tuple[str, str]]  # (name, "[NDOF][NMOM]") in order
    elements: dict[str, tuple[str, int]]  # q1p -> ("qd", 0)
    fields: list[str]  # par->X used

    @classmethod
    def parse(cls, source: str) -> CleanedFunction:
        head = re.search(r"^void\s+(\w+)\s*\((.*?)\)\s*\{", source, re.M | re.S)
        if head is None:
            raise ValueError("no function definition in the cleaned program")
        struct, arrays = None, []
        for param in head.group(2).split(","):
            param = " ".join(param.split())
            if m := re.fullmatch(r"(\w+)\s*\*\s*(\w+)", param):
                struct = (m.group(1), m.group(2))
            elif m := re.fullmatch(r"double (\w+)\s*((?:\[\s*\w+\s*\])+)", param):
                arrays.append((m.group(1), m.group(2).replace(" ", "")))
            else:
                raise ValueError(f"unexpected parameter {param!r}")
        elements = {
            m.group(1): (m.group(2), int(m.group(3)))
            for m in re.finditer(r"double\s+(\w+)\s*=\s*(\w+)\[(\d+)\];", source)
        }
        fields = []
        if struct:
            for f in re.findall(rf"\b{struct[1]}->(\w+)", source):
                if f not in fields:
                    fields.append(f)
        return cls(head.group(1), struct, arrays, elements, fields)

    @property
    def inputs(self) -> set[str]:
        return {arr for arr, _i in self.elements.values()}

    def harness(self, values: dict[str, float], header: str) -> str:
        """C source of a main() that fills the struct and the input arrays
        with ``values`` (keyed by the C names: field or element), calls the
        function and prints every output array, one ``name index value``
        line per element (row by row)."""
        lines = ["#include <stdio.h>", "#include <string.h>"]
        lines += [f'#include "{header}"', "int main(void)", "{"]
        call = []
        if self.struct:
            stype, sname = self.struct
            lines.append(f"  static {stype} {sname}_;")
            lines.append(f"  memset(&{sname}_, 0, sizeof {sname}_);")
            for f in self.fields:
                lines.append(f"  {sname}_.{f} = {values[f]!r};")
            call.append(f"&{sname}_")
        for name, dims in self.arrays:
            lines.append(f"  static double {name}{dims};")
            call.append(name)
        for cname, (arr, i) in self.elements.items():
            lines.append(f"  {arr}[{i}] = {values[cname]!r};")
        lines.append(f"  {self.name}({', '.join(call)});")
        for name, _dims in self.arrays:
            if name in self.inputs:
                continue
            lines += [
                "  {",
                f"    const double *p = (const double *) {name};",
                f"    size_t i, n = sizeof {name} / sizeof(double);",
                f'    for (i = 0; i < n; i++) printf("{name} %zu %.17g\\n", i, p[i]);',
                "  }",
            ]
        lines += ["  return 0;", "}", ""]
        return "\n".join(lines)


class _Printed:
    """The arrays a harness printed, looked up as :class:`Loaded` is."""

    def __init__(self, stdout: str):
        found: dict[str, list[float]] = {}
        for line in stdout.splitlines():
            name, _i, value = line.split()
            found.setdefault(name, []).append(float(value))
        self.values = {k: np.array(v) for k, v in found.items()}
        self.prog = self
        self.arrays = {k: v.shape for k, v in self.values.items()}

    def array(self, name: str) -> np.ndarray:
        return self.values[name]


def _check_cleaned(
    report: Report, module, job, program: Path, own: OurProgram | None = None
) -> None:
    """Call the cleaned function at the script's Inputs and at two seeded
    states through a C harness written here, and compare every Encoded
    array it returns with the module's; with ``own`` (al2py's C program for
    the same CODE statement) also with the arrays that program computes
    from a ``.in`` holding the same values (see OurProgram.call_outputs)."""
    from al2py_runtime.jobs import run as rjobs

    source = program.read_text(encoding="latin-1")
    fn = CleanedFunction.parse(source)
    header = re.search(r'#include\s+"([^"]+)"', source)
    if header is None:
        raise ValueError("the cleaned program includes no header")
    variables = {name.upper(): order for name, _obj, order in job.variables}
    inputs = {k.upper(): float(v.value) for k, v in job.inputs.items()}
    prefix = f"{fn.struct[1]}__" if fn.struct else ""
    cwd = program.parent
    obj = program.with_suffix(".o")
    subprocess.run(
        ["cc", "-O0", "-w", "-c", "-o", str(obj), str(program)],
        check=True,
        capture_output=True,
        text=True,
    )
    for k, label in enumerate(("script Inputs", "seeded state 1", "seeded state 2")):
        values, overrides = {}, {}
        for f in fn.fields:
            al = (prefix + f).upper()
            values[f] = inputs.get(al, _seeded(al, 0.5, 1.5))
            overrides[al] = values[f]
        for cname in fn.elements:
            al = _al_name(cname, variables)
            tag = al + "~" * k
            values[cname] = (
                inputs[al] if k == 0 and al in inputs else _seeded(tag, -0.6, 0.6)
            )
            overrides[al] = values[cname]
        src = cwd / f"al2py_harness_{k}.c"
        src.write_text(fn.harness(values, header.group(1)))
        exe = src.with_suffix(".exe")
        subprocess.run(
            ["cc", "-O0", "-w", "-I", str(cwd), "-o", str(exe), str(src), str(obj)]
            + ["-lm"],
            check=True,
            capture_output=True,
            text=True,
        )
        proc = subprocess.run(
            [str(exe)], capture_output=True, text=True, check=True, timeout=600
        )
        result = rjobs.run_job(job, overrides)
        theirs = _Printed(proc.stdout)
        _compare_encoded(report, label, job, theirs, result, row=0)
        if own is not None:
            _compare_own_outputs(report, label, own, theirs.values, overrides)
    if not report.rows:
        report.skipped = "the cleaned function returns no Encoded array"


def _compare_own_outputs(
    report: Report,
    label: str,
    own: OurProgram,
    theirs: dict[str, np.ndarray],
    values: dict | None,
) -> None:
    """Every array Autolev's program computed (``theirs``, by its C name)
    against the one al2py's program computes from a ``.in`` holding
    ``values`` (names Autolev's function does not read are seeded, and
    noted); ``values`` None: from the ``.in`` already in its folder."""
    if values is not None:
        names = own.in_names()
        unread = [n for n in names if n not in values]
        if unread and not any(n.startswith("al2py's .in also") for n in report.notes):
            report.notes.append(
                "al2py's .in also reads " + ", ".join(unread) + " (seeded values),"
                " which Autolev's function does not"
            )
        own.write_in({n: values.get(n, _seeded(n, 0.5, 1.5)) for n in names})
    ours = own.call_outputs()
    for name, arr in theirs.items():
        arr = np.ravel(arr)
        what = f"{label}: {own.label} {name} ({arr.size})"
        mine = ours.get(name.upper())
        if mine is None or mine.shape != arr.shape:
            got = "none" if mine is None else f"{mine.size} values"
            report.rows.append(Row(what, math.inf, 0.0, f"al2py's program: {got}"))
            continue
        report.rows.append(Row(what, _rel(mine, arr), RHS_RTOL))


# ------------------------------------------------------ MATLAB programs


_OCTAVE = ["octave", "--no-gui", "--no-history", "--norc", "--quiet"]
_M_VALUE = re.compile(r"^(\w+)(\s+=\s*)(-?[0-9.]+(?:[Ee][-+]?\d+)?)(\s*;)", re.M)


class MProgram:
    """An Autolev MATLAB program: ``ReadUserInput`` holds one value per
    line (``q1 = 0.0;  % m  Initial Value``) up to ``% Unit conversions``;
    a Dynamics program integrates ``mdlDerivatives`` with ode45, an
    Algebraic one computes its Encoded arrays as globals."""

    def __init__(self, source: str, stem: str):
        self.source, self.stem = source, stem
        start = re.search(r"^function\s+(?:\w+\s*=\s*)?ReadUserInput", source, re.M)
        end = source.index("% Unit conversions", start.end())
        self.span = (start.end(), end)
        self.names = [m.group(1) for m in _M_VALUE.finditer(source, *self.span)]
        self.state = [
            n
            for _i, n in sorted(
                (int(i), n)
                for i, n in re.findall(r"^VAR\((\d+)\) = (\w+);", source, re.M)
            )
        ]
        out = re.search(r"fopen\('([^']+)\.1'", source)
        self.outfiles = f"{out.group(1)}.%d" if out else None
        self.arrays = sorted(set(re.findall(r"^(\w+)\(1,1\) = ", source, re.M)))

    def with_values(self, values: dict[str, float]) -> str:
        a, b = self.span

        def put(m):
            value = values.get(m.group(1).upper())
            if value is None:
                return m.group(0)
            return f"{m.group(1)}{m.group(2)}{value!r}{m.group(4)}"

        return self.source[:a] + _M_VALUE.sub(put, self.source[a:b]) + self.source[b:]

    def rhs_variant(self, values: dict[str, float]) -> str:
        """The program with its main replaced by: read the inputs, print
        ``mdlDerivatives`` at TINITIAL."""
        text = self.with_values(values)
        second = re.search(r"^function\s", text[1:], re.M).start() + 1
        main = (
            "function al2py_rhs\n"
            "VAR = ReadUserInput;\n"
            "global TINITIAL\n"
            "d = mdlDerivatives(TINITIAL, VAR, 0);\n"
            "printf('%.17g\\n', d);\n\n"
        )
        return main + text[second:]


def _octave(cwd: Path, command: str) -> str:
    proc = subprocess.run(
        [*_OCTAVE, "--eval", command],
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=600,
    )
    if proc.returncode or "error:" in proc.stderr:
        raise RuntimeError(f"Octave failed:\n{proc.stderr[-2000:]}")
    return proc.stdout


def _check_matlab(
    report: Report, module, job, program: Path, own: OurProgram | None = None
) -> None:
    """Run the MATLAB program in GNU Octave on the script's Inputs (values
    edited into ``ReadUserInput``) and on a perturbed state; compare its
    output files with ``run()``'s tables, ``mdlDerivatives`` at the
    initial state with ``ode_function()``, and the Encoded globals of an
    Algebraic program with the module's."""
    from al2py_runtime.jobs import run as rjobs

    mprog = MProgram(program.read_text(encoding="latin-1"), program.stem)
    cprog = CProgram("", [mprog.names], "", None, mprog.state, {})
    cwd = program.parent
    variables = {n.upper(): o for n, _obj, o in job.variables}
    dynamic = job.kind in ("DYNAMICS", "ODE")
    phases = (("script Inputs", False), ("perturbed state", True))
    for label, perturb in phases:
        integ = _integration_for(job)
        integ.update(ABSERR=1e-10, RELERR=1e-10)  # Octave's ode45 too
        values = _values(cprog, job, integ)
        if "PRINTINT" in values:  # the C programs' _printint
            values["PRINTINT"] = values["_PRINTINT"] = integ["_PRINTINT"]
        if perturb:
            for name in mprog.names:
                if _al_name(name, variables).rstrip("'") in variables:
                    values[name.upper()] = _seeded(name + "~", -0.5, 0.5)
        if dynamic:
            # Octave's ode45 interprets mdlDerivatives at every stage (a
            # minute per few output steps for bicycle14.m): ten print steps
            t0, t1, h = values["TINITIAL"], values["TFINAL"], values["INTEGSTP"]
            values["TFINAL"] = min(t1, t0 + 10 * h) if t1 > t0 else t1
        program.write_text(mprog.with_values(values), encoding="latin-1")
        overrides = _overrides(cprog, job, values)
        result = rjobs.run_job(job, overrides)
        tables = [t for t in result.tables if not getattr(t, "encoded", False)]
        encoded = [
            a for a in mprog.arrays if a.upper() in {k.upper() for k in job.encoded}
        ]
        printing = "".join(
            f"printf('@ {a}\\n'); printf('%.17g\\n', {a}.');" for a in encoded
        )
        glob = f"global {' '.join(encoded)}; " if encoded else ""
        out = _octave(cwd, f"{glob}{program.stem}; {printing}")
        if mprog.outfiles:
            _compare_tables(report, label, tables, cwd, mprog.outfiles)
            if own is not None:
                by_name = {_al_name(k, variables): v for k, v in values.items()}
                own.write_in(by_name)
                own.run()
                _compare_files(report, f"{label}: {own.label}", cwd, own.folder)
        if encoded:
            _compare_encoded(report, label, job, _OctavePrinted(out), result, 0)
        if dynamic:
            (cwd / "al2py_rhs.m").write_text(
                mprog.rhs_variant(values), encoding="latin-1"
            )
            theirs = np.array(
                [float(x) for x in _octave(cwd, "al2py_rhs").split()], float
            )
            f, y0, names = rjobs.ode_function(job, overrides)
            ours_d = dict(
                zip(names, f(values["TINITIAL"], np.array(y0, float)), strict=True)
            )
            ours = np.array([ours_d[_al_name(n, variables)] for n in mprog.state])
            report.rows.append(
                Row(
                    f"{label}: state derivatives at t0 ({len(ours)})",
                    _rel(ours, theirs),
                    RHS_RTOL,
                )
            )


class _OctavePrinted(_Printed):
    """Arrays Octave printed as ``@ NAME`` then one value a line."""

    def __init__(self, stdout: str):
        lines, name = [], None
        found: dict[str, list[float]] = {}
        for line in stdout.splitlines():
            if line.startswith("@ "):
                name = line[2:].strip()
                found[name] = []
            elif name is not None and line.strip():
                try:
                    found[name].append(float(line))
                except ValueError:
                    name = None
        super().__init__("\n".join(lines))
        self.values = {k: np.array(v) for k, v in found.items()}
        self.arrays = {k: v.shape for k, v in self.values.items()}


# -------------------------------------------------------------------- CLI


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument(
        "names", nargs="*", help="only pairs whose name contains one of these"
    )
    ap.add_argument("--list", action="store_true", help="list the pairs found")
    ap.add_argument("--root", type=Path, default=None, help="mirror root ($ALMIRROR)")
    ap.add_argument("--keep", type=Path, default=None, help="work in this folder")
    ap.add_argument(
        "--same-language",
        action="store_true",
        help="also run the program al2py code writes (same language, same .in)",
    )
    args = ap.parse_args(argv)
    pairs = [
        p
        for p in discover(args.root)
        if not args.names or any(n.lower() in p.name.lower() for n in args.names)
    ]
    if not pairs:
        print(f"no pairs found under {args.root or mirror_root()}")
        return 0
    if args.list:
        for p in pairs:
            print(f"{p.name:45} {p.kind:10} {p.repo}:{p.script}")
        return 0
    failed = False
    print(f"{'pair':40} {'compared':55} {'max error':>10} {'allowed':>10}  verdict")
    for p in pairs:
        if args.keep:
            args.keep.mkdir(parents=True, exist_ok=True)
        try:
            rep = check(p, args.root, args.keep, args.same_language)
        except Exception as exc:  # noqa: BLE001 - a report line per pair
            print(f"{p.name:40} error: {str(exc).strip()[:300]}")
            failed = True
            continue
        if rep.skipped:
            print(f"{p.name:40} {rep.skipped}")
        for note in rep.notes:
            print(f"{p.name:40} note: {note}")
        for r in rep.rows:
            mark = "match" if r.ok else "DIFFERS"
            print(
                f"{p.name:40} {r.what:55} {r.max_error:10.2e} {r.allowed:10.2e}  {mark} {r.detail}"
            )
        failed |= not rep.ok and not rep.skipped
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
