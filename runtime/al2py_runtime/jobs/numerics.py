"""Numerical CODE jobs: Input/Output with units, Dynamics/ODE/Nonlinear/Algebraic.

:class:`Numerics` records ``UnitSystem``, ``Input``, ``Output`` and ``CODE``
for a :class:`Workspace` (its ``numerics`` part).  A generated module calls
it directly: each statement (``al.numerics.input(...)``), ``Input(X)`` and
``Units(a, b)`` in expressions, and the module's ``run()``, ``ode_function()``
and ``evaluate()``; so an Input value or a ``backend`` goes from the module to
:func:`~.run.run_job` through :meth:`Numerics.run` alone.

Recording (``unit_system``, ``input``, ``output``, ``code``) only stores what
the statements say, so importing a generated module does no numerical work.
``CODE`` takes a snapshot of the right-hand sides in force; later statements
do not change the job.  ``run()`` performs the job (see :mod:`.jobs`).

>>> from al2py_runtime import Workspace, t
>>> al = Workspace("odexy.al")
>>> a, b = al.constants("A", "B")
>>> x, y = al.variables("X'", "Y'")
>>> _ = al.assign("X'", -a * x - b * y)
>>> _ = al.assign("Y'", -y - t * x**2)
>>> al.numerics.input({"A": 1, "B": 2, "X": 2, "Y": 3, "TFINAL": 5, "INTEGSTP": 0.1})
>>> al.numerics.output([("T", t, None), ("X", x, None), ("Y", y, None)])
>>> job = al.numerics.code("ODE", file="odexy.c")
>>> result = al.numerics.run()
>>> round(float(result["X"][-1]), 6), len(result.tables[0])
(0.497489, 51)
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import PurePath
from typing import TYPE_CHECKING, Any, Protocol

import sympy as sp
from sympy.physics.vector import Vector

from ..names.printing import element_labels
from ..safety import Statements, statement
from .records import (
    KINDS,
    AnimateSpec,
    InputValue,
    Job,
    NumericsError,
    OutputItem,
    OutputSpec,
    job_stem,
    normalize_name,
    output_stems,
)
from .units import UnitSystem, units_factor

if TYPE_CHECKING:
    from ..model.model import Model
    from ..names.settings import Settings
    from ..names.table import NameTable
    from .tables import Result

# The job runner (numpy, the compiled backends) loads when a job first
# needs it (``from .run import ...`` in the methods), not with the model.
__all__ = ["Numerics", "NumericsError"]


@dataclass
class _NumericsState:
    unit_system: UnitSystem = field(default_factory=UnitSystem)
    inputs: dict[str, InputValue] = field(default_factory=dict)
    outputs: list[OutputSpec] = field(default_factory=list)
    jobs: list[Job] = field(default_factory=list)
    encoded: list[str] = field(default_factory=list)  # names, in order
    #: matrices (and vectors) an Output lists: name -> shape of its elements
    shapes: dict[str, tuple[int, int]] = field(default_factory=dict)
    #: ``Units T=S, X=m``: the unit of a name in later Inputs and Outputs
    #: that give none.
    units_of: dict[str, str] = field(default_factory=dict)
    #: the latest ``Animate(N, O, A, B)``
    animate: AnimateSpec | None = None


class ScriptValues(Protocol):
    """The script's operations on Autolev names that :class:`Numerics`
    calls (the workspace, :class:`al2py_runtime.workspace.Workspace`, is
    the one implementation)."""

    def value(self, name: str) -> Any:
        """The current value of an Autolev name (``"X"``, ``"ZERO[2]"``)."""
        ...

    def val(self, x: Any) -> Any:
        """The value of an Autolev name or expression."""
        ...

    def symbol(self, name: str) -> Any:
        """The sympy object of a declared name."""
        ...

    def resolve(self, expr: Any, keep: Iterable[Any] = ()) -> Any:
        """``expr`` with every right-hand side substituted but ``keep``."""
        ...


class Numerics:
    """Inputs, outputs, units and the numerical jobs of a script.

    It is given the small objects of the script it reads when ``CODE``
    takes its snapshot: ``script`` (:class:`ScriptValues`), the file name,
    the name table, the settings, the statements, and the model (for the
    geometry an animation draws); nothing else refers back."""

    def __init__(
        self,
        script: ScriptValues,
        *,
        filename: str,
        table: NameTable,
        settings: Settings,
        statements: Statements,
        model: Model,
    ) -> None:
        self._script = script
        self._filename = filename
        self._table = table
        self._settings = settings
        #: where the script's statement calls stand (a failing Input,
        #: Output, UnitSystem or CODE statement names its ``.al`` line)
        self.statements = statements
        self._model = model
        self._numerics = _NumericsState()
        #: compiled quantities (:meth:`compiled_quantity`)
        self._compiled: dict[tuple, tuple[Any, Any]] = {}

    # ------------------------------------------------------------ recording

    @statement
    def unit_system(
        self, mass: str = "kg", length: str = "m", time: str = "sec", *, line=None
    ) -> None:
        """``UnitSystem kg, meter, sec``: the units values have inside a run."""
        self._numerics.unit_system = UnitSystem(mass, length, time)

    @statement
    def units_of(self, units: Mapping[str, str], *, line: int | None = None) -> None:
        """``Units T=S, X=m``: the unit of each name where an Input or Output
        of it gives none."""
        for name, unit in units.items():
            self._numerics.units_of[normalize_name(name)] = unit

    @statement
    def input(self, values: Mapping[str, Any], *, line: int | None = None) -> None:
        """``Input A=1, QA=30 deg``: values are numbers or ``(number, unit)``."""
        store = self._numerics.inputs
        for name, spec in values.items():
            value, unit = spec if isinstance(spec, tuple) else (spec, None)
            unit = unit or self._numerics.units_of.get(normalize_name(name))
            try:
                expr = sp.sympify(value)
            except (TypeError, ValueError, sp.SympifyError):
                raise ValueError(
                    f"Input {name} (line {line}): {value!r} is not a number"
                ) from None
            # ``Input E4 = COS(QQ1/2)``: computed from the other Inputs at run
            # time (in internal units), see jobs.input_values.
            number = float(expr) if expr.is_number else expr
            store[normalize_name(name)] = InputValue(
                number, unit if unit else None, line
            )

    @statement
    def output(
        self,
        items: Iterable[tuple[str, Any, str | None]],
        *,
        line: int | None = None,
    ) -> None:
        """``Output T, X m, QA deg``: one output table (file ``STEM.n``)."""
        default = self._numerics.units_of
        columns: list[OutputItem] = []
        for lab, expr, unit in items:
            unit = unit or default.get(normalize_name(lab)) or None
            columns.extend(self._output_items(str(lab), expr, unit))
        self._numerics.outputs.append(OutputSpec(tuple(columns), line))

    def _output_items(self, label: str, value: Any, unit: str | None) -> list:
        """One column per element of a matrix, row by row, named as the
        transcript names them (``A[1,2]``, ``B[2]``); a vector gives its
        measure numbers in the Newtonian frame (``G>[1]``...)."""
        if isinstance(value, Vector):
            frame = self._newtonian()
            if frame is None:
                raise ValueError(
                    f"Output {label}: a vector's measure numbers need a "
                    "Newtonian frame"
                )
            value = value.to_matrix(frame) if value != 0 else sp.zeros(3, 1)
        if not isinstance(value, sp.MatrixBase):
            return [OutputItem(label, value, unit)]
        self._numerics.shapes[normalize_name(label)] = value.shape
        names = element_labels(label, value.rows, value.cols)
        return [OutputItem(n, e, unit) for n, e in zip(names, value, strict=True)]

    def _newtonian(self) -> Any:
        for entry in self._table.entries.values():
            if entry.kind == "newtonian":
                return entry.obj
        return None

    @statement
    def encode(self, *names: str, line: int | None = None) -> None:
        """``Encode A, B'``: the CODE job that follows computes these
        quantities at every output row, as Autolev's generated programs did
        (``result["A"]``; see docs/semantics.md)."""
        for name in names:
            key = normalize_name(name)
            if key not in self._numerics.encoded:
                self._numerics.encoded.append(key)

    @statement
    def animate(
        self, newtonian: Any, point: Any, *frames: Any, line: int | None = None
    ) -> None:
        """``Animate(N, O, A, B)``: the CODE jobs that follow animate frames
        and bodies ``A``, ``B`` in the Newtonian frame ``N``, positions
        measured from the point ``O`` (``result.animate()``; see
        :mod:`al2py_runtime.jobs.scene`)."""
        self._numerics.animate = AnimateSpec(newtonian, point, tuple(frames), line)

    def _encoded_spec(self, line: int | None) -> tuple[OutputSpec | None, dict]:
        """The encoded quantities as one (unwritten) output table."""
        items: list[OutputItem] = []
        shapes: dict[str, tuple[int, int]] = {}
        for key in self._numerics.encoded:
            value = self._script.value(key)
            if isinstance(value, sp.MatrixBase):
                shapes[key] = value.shape
                names = element_labels(key, value.rows, value.cols)
                items.extend(
                    OutputItem(n, e) for n, e in zip(names, value, strict=True)
                )
            else:
                items.append(OutputItem(key, value))
        if not items:
            return None, {}
        return OutputSpec(tuple(items), line, encoded=True), shapes

    @statement
    def code(
        self,
        kind: str,
        eqs: Any = None,
        unknowns: Iterable[Any] | None = None,
        *,
        sweep: tuple | None = None,
        file: str | None = None,
        line: int | None = None,
        options: Iterable[str] = (),
    ) -> Job:
        """``CODE Dynamics() file.c`` (also ``ODE``, ``Nonlinear(eqs, x, y)``,
        ``Algebraic(eqs, x, y)`` and ``Algebraic() [PHI deg=0,360,1]``).

        Records the job; ``run()`` performs it.  ``file``'s stem names the
        job and its output files (``STEM_2``, ``STEM_3``... when an earlier
        job has that stem: :func:`~.records.output_stems`); its extension
        (.c, .m, .for, .f) chooses the language of ``al2py code``."""
        job = self._make_job(kind, eqs, unknowns, sweep=sweep, file=file, line=line)
        job.options = tuple(str(w).upper() for w in options)
        # a stem an earlier job has is named apart (STEM_2): no job writes
        # another's output files
        job.stem = output_stems([j.stem for j in self._numerics.jobs] + [job.stem])[-1]
        self._numerics.jobs.append(job)
        return job

    def _make_job(
        self,
        kind: str,
        eqs: Any = None,
        unknowns: Iterable[Any] | None = None,
        *,
        sweep: tuple | None = None,
        file: str | None = None,
        line: int | None = None,
    ) -> Job:
        """A snapshot of the script's state as a job (not recorded)."""
        kind = kind.upper()
        if kind not in KINDS:
            raise ValueError(f"CODE option must be one of {', '.join(KINDS)}")
        state = self._numerics
        eq_matrix, eqs_name = None, None
        if eqs is not None:
            eqs_name = self._matrix_name(eqs)
            if isinstance(eqs, sp.MatrixBase):
                eq_matrix = sp.Matrix(list(eqs))
            elif isinstance(eqs, list | tuple):
                eq_matrix = sp.Matrix(list(eqs))
            else:
                eq_matrix = sp.Matrix([self._script.val(eqs)])
        objs = [
            self._script.symbol(u) if isinstance(u, str) else u for u in unknowns or ()
        ]
        if sweep is not None:
            obj, unit, start, stop, step = sweep
            if isinstance(obj, str):
                obj = self._script.symbol(obj)
            sweep = (obj, unit or None, float(start), float(stop), float(step))
            if float(step) == 0:
                raise ValueError("CODE sweep step must not be 0")
        zero = None
        if kind in ("DYNAMICS", "ODE"):
            value = self._table.stored.get("ZERO")
            if isinstance(value, sp.MatrixBase):
                zero = sp.Matrix(value)
        encoded, shapes = self._encoded_spec(line)
        from .scene import Geometry

        outputs = list(state.outputs) + ([encoded] if encoded is not None else [])
        job = Job(
            kind=kind,
            stem=job_stem(file, self._filename),
            filename=file,
            line=line,
            source=self._filename,
            eqs=eq_matrix,
            eqs_name=eqs_name,
            unknowns=objs,
            sweep=sweep,
            rhs=dict(self._table.rhs),
            zero=zero,
            outputs=outputs,
            encoded={**state.shapes, **shapes},
            inputs=dict(state.inputs),
            unit_system=state.unit_system,
            digits=self._settings.digits,
            variables=[
                (name, e.obj, e.order)
                for name, e in self._table.entries.items()
                if e.kind in ("variable", "specified") and name != "T"
            ],
            names=dict(self._table.by_obj),
            entries={name: (e.kind, e.obj) for name, e in self._table.entries.items()},
            declared={
                name: e.line
                for name, e in self._table.entries.items()
                if e.line is not None
            },
            animate=state.animate,
            geometry=Geometry.of(self._model),
            initials={
                name: float(getattr(e, "extra", {}).get("initial", 0.0))
                for name, e in self._table.entries.items()
                if "initial" in getattr(e, "extra", {})
                or name.startswith("NICHECK_WORK")
            },
        )
        return job

    def _matrix_name(self, value: Any) -> str | None:
        for name, stored in self._table.stored.items():
            if stored is value:
                return name
        if isinstance(value, sp.MatrixBase):
            for name, stored in self._table.stored.items():
                if isinstance(stored, sp.MatrixBase) and stored == value:
                    return name
        return None

    # ------------------------------------------------------------ functions

    @statement
    def input_value(self, name: str, unit_system: bool = False) -> Any:
        """Autolev ``Input(X)``; ``Input(X, UnitSystem)`` with ``unit_system``
        converts it to the units of the ``UnitSystem``."""
        key = normalize_name(name)
        item = self._numerics.inputs.get(key)
        if item is None:
            value = self._assigned_value(key)
            if value is None:
                raise KeyError(f"{name} has no Input value")
            return value
        factor = self._numerics.unit_system.to_internal(item.unit)
        value = item.value
        if isinstance(value, sp.Basic) and not value.is_number:
            # ``Input E1 = COS(Q1/2)``: computed from the other Inputs (and
            # the script's values) as a job computes it, in internal units
            from .run import input_values

            values, _ = input_values(self._make_job("ALGEBRAIC"), {})
            value = values.values[key] / factor
        if unit_system:
            return sp.Float(float(value) * factor)
        return _as_number(value)

    def _assigned_value(self, key: str) -> Any:
        """``Input(A)`` of a name with no Input but a value of its own
        (``A = PI/2``, ``U1 = Dot(W_A_N>, A1>)``): that value, computed from
        the Inputs (the initial values, for variables) as a job computes
        it; None if ``A`` has no such value, or it is not a number then.
        Autolev's programs fold such a constant into the code rather than
        reading it (docs/semantics.md, "Input")."""
        entry = self._table.entries.get(key)
        if entry is None or entry.kind not in ("constant", "variable", "specified"):
            return None
        rhs = self._table.rhs.get(entry.obj)
        if not isinstance(rhs, sp.Basic):
            return None
        from .run import input_values

        values, _ = input_values(self._make_job("ALGEBRAIC"), {}, zero_missing=False)
        known = {
            e.obj: values.values[name]
            for name, e in self._table.entries.items()
            if name in values.values
        }
        value = self._script.resolve(rhs).xreplace(known)
        return _as_number(value) if value.is_number else None

    @statement
    def units(self, a: str, b: str) -> Any:
        """Autolev ``Units(a, b)``: the factor converting a value in ``a`` to
        ``b`` (``Units("n*m", "lbf*ft")`` is 0.7375621...)."""
        return sp.Float(units_factor(a, b))

    # -------------------------------------------------------------- running

    @property
    def jobs(self) -> list[Job]:
        """The recorded ``CODE`` jobs, in script order."""
        return list(self._numerics.jobs)

    @property
    def inputs(self) -> dict[str, InputValue]:
        """The ``Input`` values recorded so far (upper-case names)."""
        return dict(self._numerics.inputs)

    def run(
        self,
        values: Mapping[str, Any] | None = None,
        /,
        *,
        backend: str | None = None,
        zero_missing: bool | None = None,
        job: str | int | None = None,
        **overrides: Any,
    ) -> Result:
        """Perform one of the script's ``CODE`` jobs (see :meth:`job` for
        which one without ``job``: the only job, else the only Dynamics/ODE
        job, else an error listing the jobs; ``job="WhippleDynamics.c"``
        names one by its file or file stem, ``job=2`` by its place).

        Keyword names are Autolev names in any case, in the Input's own
        units: ``run(QA=30, tfinal=5)``; names with primes go in a mapping:
        ``run({"X'": 1})``.  ``backend`` (``"auto"``, ``"c"``, ``"llvm"``,
        ``"lambdify"``) chooses how Dynamics/ODE equations are evaluated;
        see :mod:`al2py_runtime.jobs.backends`.  Missing values follow
        :func:`~.run.missing_value_rule`: a Specified quantity no equation
        and no Input gives is 0, noted in ``result.notes`` and warned
        (:class:`~al2py_runtime.MissingValueWarning`); a constant the job
        needs that no Input gives stops it with its name and line, unless
        ``zero_missing=True`` (then it is 0 and noted too)."""
        merged = dict(values or {})
        merged.update(overrides)
        from .run import run_job, warn_notes

        result = run_job(
            self.job(job), merged, backend=backend, zero_missing=zero_missing
        )
        warn_notes(result.missing)
        return result

    def job(self, name: str | int | None = None, *, dynamics: bool = False) -> Job:
        """The ``CODE`` job called ``name``: its stem (the file's stem, named
        apart as ``STEM_2`` when an earlier job has it), its file name (any
        case; it must name one job), or its place among the CODE statements
        (``1`` is the first).

        Without ``name``, never a job the user probably did not mean: the
        only job when there is one; else the only Dynamics/ODE job; else an
        error that lists the jobs with their files and lines.  With
        ``dynamics`` (:meth:`ode_function`) only Dynamics/ODE jobs count."""
        jobs = self._numerics.jobs
        if not jobs:
            raise NumericsError(f"{self._filename} has no CODE statement")
        moving = [j for j in jobs if j.kind in ("DYNAMICS", "ODE")]
        if name is None:
            if len(moving) == 1:
                return moving[0]
            if len(jobs) == 1 and not dynamics:
                return jobs[0]
            if dynamics and not moving:
                raise NumericsError(
                    f"{self._filename} has no CODE Dynamics or ODE job;"
                    f" jobs: {_listing(jobs)}"
                )
            which = f", {len(moving)} of them Dynamics/ODE" if moving else ""
            raise NumericsError(
                f"{self._filename} has {len(jobs)} CODE jobs{which}; choose"
                f" one with job= (--job): {_listing(jobs)}"
            )
        if isinstance(name, int) and not isinstance(name, bool):
            if 1 <= name <= len(jobs):
                return jobs[name - 1]
            found = []
        else:
            key = str(name).upper()
            found = [
                j
                for j in jobs
                if key
                in (
                    j.stem.upper(),
                    (j.filename or "").upper(),
                    PurePath((j.filename or "").replace("\\", "/")).name.upper(),
                )
            ]
            if not found and key.isdigit() and 1 <= int(key) <= len(jobs):
                found = [jobs[int(key) - 1]]
        if len(found) == 1:
            return found[0]
        if found:
            raise NumericsError(
                f"{self._filename}: {name!r} names {len(found)} CODE jobs; "
                f"choose one with job=: {_listing(jobs)}"
            )
        raise NumericsError(
            f"{self._filename} has no CODE job {name!r}; jobs: {_listing(jobs)}"
        )

    def document_run(self, run: Any) -> Any:
        """Give a module's ``run`` function its Inputs as keyword parameters
        (with their values, in their units) for ``help()`` and tab completion."""
        from .results import document_run

        return document_run(self, run)

    def ode_function(
        self,
        values: Mapping[str, Any] | None = None,
        /,
        *,
        backend: str | None = None,
        zero_missing: bool | None = None,
        job: str | int | None = None,
        **overrides: Any,
    ) -> tuple[Any, list[float], list[str]]:
        """``(f, y0, names)``: a CODE Dynamics/ODE job's equations of motion
        for ``scipy.integrate.solve_ivp(f, (t0, t1), y0)``, in internal units
        (the UnitSystem's, SI by default; angles in radians).  Without
        ``job``, the script's only Dynamics/ODE job (else an error listing
        the jobs; see :meth:`job`).  Overrides are given as for :meth:`run`,
        in the Inputs' own units, and missing values follow the same rule.
        ``run()`` integrates the same function; ``backend`` as for
        :meth:`run`."""
        merged = dict(values or {})
        merged.update(overrides)
        from .run import ode_function, warn_notes

        f, y0, names, notes = ode_function(
            self.job(job, dynamics=True),
            merged,
            backend=backend,
            zero_missing=zero_missing,
            notes=True,
        )
        warn_notes(notes)
        return f, y0, names

    def evaluate_name(
        self,
        name: str,
        values: Mapping[str, Any] | None = None,
        /,
        *,
        zero_missing: bool | None = None,
        backend: str | None = None,
        **more: Any,
    ) -> Any:
        """The named quantity as a float (or numpy array for a matrix).

        Every Input value (given in the Input's units), the ``values`` given
        here (also in the Input's units; names without an Input are in the
        unit system's units, radians for angles) and every named intermediate
        are substituted.  Time is TINITIAL unless ``T`` is given.

        The quantity is compiled on the first call (:mod:`.quantities`), so
        later calls cost microseconds.  Any value may be a numpy array: the
        values broadcast together and the result has their shape in front
        (``evaluate_name("AMAT", U6=speeds)``: one matrix per speed).  A
        Specified quantity nobody gives is 0 (noted once on stderr), as in
        a run; a constant or variable without a value stops with its name
        unless ``zero_missing``.  ``backend``: see
        :func:`.quantities.build_kernel`."""
        from .quantities import evaluate_compiled

        merged = dict(values or {})
        merged.update(more)
        job = self._make_job("ALGEBRAIC", line=None)
        value = self._script.value(name)
        if not isinstance(value, sp.Basic | sp.MatrixBase | int | float):
            from .run import evaluate_with_inputs

            return evaluate_with_inputs(job, value, name, merged)
        plan = self.compiled_quantity(name, merged, backend, job)

        def exact(point: Mapping[str, Any]) -> Any:
            from .run import evaluate_with_inputs

            return evaluate_with_inputs(job, value, name, point)

        return evaluate_compiled(job, plan, merged, exact, zero_missing)

    def sweep(
        self,
        name: str | None = None,
        values: Mapping[str, Any] | None = None,
        /,
        *,
        executor: Any = None,
        job: str | None = None,
        backend: str | None = None,
        zero_missing: bool | None = None,
        chunksize: int | None = None,
        origin: tuple[str, str | None] | None = None,
        **given: Any,
    ) -> Any:
        """A :class:`.sweep.Sweep` of the quantity ``name`` (compiled once,
        or for a large quantity over a few points its numpy tape:
        :func:`.quantities.takes_tape`),
        or without a name of the ``CODE`` job (``job`` chooses it as for
        :meth:`run`), over the grid that the 1-D arrays among the values
        span (several: their product); scalars are fixed.  Values are given
        as for :meth:`evaluate_name` (a quantity) or :meth:`run` (a job).

        ``executor``: ``None`` (in this process), any
        ``concurrent.futures.Executor``, or ``"dask"`` (the Dask client of
        this process); the work goes out in chunks of ``chunksize`` points.
        ``origin`` is the module's ``(__name__, __file__)``, which a job
        sweep's workers import (a module's ``sweep()`` passes it)."""
        from .sweep import grid, sweep_job, sweep_quantity

        merged = dict(values or {})
        merged.update(given)
        if name is None:
            chosen = self.job(job)
            index = next(i for i, j in enumerate(self._numerics.jobs) if j is chosen)
            return sweep_job(
                chosen,
                index,
                merged,
                origin=origin,
                executor=executor,
                backend=backend,
                zero_missing=zero_missing,
                chunksize=chunksize,
            )
        if job is not None:
            raise NumericsError("sweep() takes a quantity's name or job=..., not both")
        snapshot = self._make_job("ALGEBRAIC", line=None)
        value = self._script.value(name)
        if not isinstance(value, sp.Basic | sp.MatrixBase | int | float):
            raise NumericsError(
                f"{name} is not a scalar or matrix; it cannot be evaluated"
            )
        # the grid's size: a sweep of a few points may run a numpy tape
        # (quantities.takes_tape)
        points = math.prod(len(a) for a in grid(merged)[0].values())
        plan = self.compiled_quantity(name, merged, backend, snapshot, points=points)

        def exact(point: Mapping[str, Any]) -> Any:
            from .run import evaluate_with_inputs

            return evaluate_with_inputs(snapshot, value, name, point)

        return sweep_quantity(
            snapshot,
            plan,
            merged,
            exact,
            executor=executor,
            zero_missing=zero_missing,
            chunksize=chunksize,
        )

    def linearize(
        self,
        values: Mapping[str, Any] | None = None,
        /,
        *,
        job: str | None = None,
        inputs: Any = None,
        symbolic: bool = False,
        zero_missing: bool | None = None,
        **overrides: Any,
    ) -> Any:
        """The ``CODE`` Dynamics/ODE job's equations of motion linearized
        about the point its Inputs and the values given here make (as for
        :meth:`run`): a :class:`.linearize.Linearization` with ``A``, ``B``
        and the names of the states and inputs (the Specified quantities
        with no equation, or the names in ``inputs``).  ``symbolic=True``
        keeps the constants as symbols (sympy matrices)."""
        from .linearize import linearize_job

        merged = dict(values or {})
        merged.update(overrides)
        return linearize_job(
            self.job(job),
            merged,
            inputs=inputs,
            symbolic=symbolic,
            zero_missing=zero_missing,
        )

    def compiled_quantity(
        self,
        name: str,
        given: Mapping[str, Any] = {},  # noqa: B006 - read only
        backend: str | None = None,
        job: Job | None = None,
        *,
        points: int | None = None,
    ) -> Any:
        """The named quantity compiled for values of the names in ``given``
        (a :class:`.quantities.CompiledQuantity`), built once and kept (on
        disk too: :func:`.quantities.plan_quantity`).  ``points``: the size
        of a sweep, which its numpy tape serves instead when
        :func:`.quantities.takes_tape` says so."""
        from .quantities import (
            plan_quantity,
            quantity_key,
            split_given,
            takes_tape,
            tape_quantity,
        )
        from .run import input_values

        job = job if job is not None else self._make_job("ALGEBRAIC", line=None)
        value = self._script.value(name)
        settable, free = split_given(job, given)
        _vals, keep = input_values(job, dict.fromkeys(settable, 0.0), False)
        key = quantity_key(name, free, frozenset(keep), backend)
        tape_key = (*key, "tape")
        cache = self._compiled

        def kept(slot: tuple) -> Any:
            found = cache.get(slot)
            return found if found is not None and found[0] is value else None

        numpy = backend is not None and backend.strip().lower() == "numpy"
        compiled = None if numpy else kept(key)
        tape = kept(tape_key)
        if tape is None and (compiled is None or points is not None):
            # the tape decides a sweep's way, and keys the disk cache
            made = tape_quantity(job, value, name, frozenset(free), frozenset(keep))
            cache[tape_key] = tape = (value, made)
        if takes_tape(tape[1] if tape else None, points, backend):
            return tape[1]
        if numpy:
            raise NumericsError(
                f"{name} holds an operation that numpy does not evaluate here;"
                " use another backend"
            )
        if compiled is not None:
            return compiled[1]
        plan = plan_quantity(
            job,
            value,
            name,
            frozenset(free),
            frozenset(keep),
            backend,
            tape=tape[1] if tape else None,
        )
        cache[key] = (value, plan)
        return plan


def _listing(jobs: list[Job]) -> str:
    """The jobs as messages list them: the name that picks each, with its
    CODE statement's file and line."""
    return ", ".join(f"{j.stem} ({j.where})" for j in jobs)


def _as_number(value: Any) -> Any:
    """A value of ``Input(X)``: an integer when it is one, else a float."""
    value = float(value)
    return sp.Integer(int(value)) if value.is_integer() else sp.Float(value)
