"""The program of a ``CODE Algebraic`` or ``CODE Nonlinear`` job.

Both are spelled with the pieces of a Dynamics program (see
:class:`~.program.Program`): ``eqns`` fills ``M`` and ``f`` and solves
``M ud = f``; ``outputs`` calls it and evaluates the Outputs.

* Algebraic: ``M`` is the equations' matrix in the unknowns and ``f`` minus
  their value at zero unknowns, so ``ud`` holds the solution (the unknowns
  keep the script's names, unpacked from ``ud``).  A range
  ``[PHI deg=0,360,1]`` makes ``PHI`` the last constant, stepped by the
  driver as ``run()`` steps it.
* Nonlinear: the unknowns are the "states" ``y`` (their Input values the
  guesses), ``dy`` the residuals ``F(y)``, ``M`` their Jacobian and ``f``
  ``-F``, so the solve leaves Newton's step in ``ud``.

Without an Output the program writes the unknowns (after the range's
quantity), as ``run()`` does.
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from ..jobs.records import normalize_name
from ..jobs.run import (
    Column,
    Job,
    NumericsError,
    eq_labels,
    input_values,
    integration_parameters,
    label_of,
    static_equations,
)
from ..jobs.units import UnitError
from .program import (
    Assign,
    Entries,
    Entry,
    Program,
    assignments,
    identifier,
    in_order,
    iter_names,
    named_intermediates,
    new_program,
    output_block,
    output_tables,
    renamed_evaluated,
)

__all__ = ["describe_static"]


def describe_static(
    job: Job, source: str | None = None, nosubs: bool | None = None
) -> Program:
    free: dict = {}  # the program's free symbols (Program.free)
    vals, keep = input_values(job, {})
    spec = static_equations(job, frozenset(keep), deferred=True)
    made = Entries(job, vals)
    taken = made.taken
    nonlinear = job.kind == "NONLINEAR"
    sweep = job.sweep[0] if job.sweep is not None else None
    pairs = sorted(
        zip(spec.params, spec.param_dummies, strict=True),
        key=lambda od: static_in_order(job, label_of(od[0], job.names)),
    )
    params = [obj for obj, _d in pairs]
    dummies = [d for _obj, d in pairs]
    if sweep is not None:  # the range's quantity: the last constant
        if sweep in params:
            k = params.index(sweep)
            params.append(params.pop(k))
            dummies.append(dummies.pop(k))
        else:  # the equations and outputs do not use it
            params.append(sweep)
            dummies.append(sp.Dummy("sweep"))
    rename: dict[Any, Any] = {spec.time: sp.Symbol("T", real=True)}
    constants = []
    for obj, d in zip(params, dummies, strict=True):
        name = label_of(obj, job.names)
        value = 0.0 if obj is sweep else vals.param(obj)
        e = made.entry("Constant", name, value)
        constants.append(e)
        rename[d] = sp.Symbol(e.ident, real=True)
    names = [label_of(u, job.names) for u in spec.unknowns]
    initials: list[Entry] = []
    unpack: list[Assign] = []
    if nonlinear:
        for name, d in zip(names, spec.xs, strict=True):
            e = made.entry("Guess", name, vals.get(name, note=False))
            initials.append(e)
            rename[d] = sp.Symbol(e.ident, real=True)
        integration = made.integration(["ABSERR", "RELERR"])
    else:
        for k, (name, d) in enumerate(zip(names, spec.xs, strict=True)):
            ident = identifier(name, taken)
            rename[d] = sp.Symbol(ident, real=True)
            unpack.append(Assign(("ud", k, ident), 0))
        integration = []
    ranges = _ranges(job, constants[-1]) if sweep is not None else []
    memo: dict = {}  # renamed parts (program.named_intermediates)
    inter = named_intermediates(spec.intermediates, rename, taken, memo)

    def sub(e: Any) -> Any:
        return renamed_evaluated(sp.sympify(e), rename, memo)

    n = len(spec.xs)
    x_names = iter_names("x", taken)
    eqs = [sub(e) for e in spec.eqs]
    first = [sub(e) for e in spec.jac]
    targets: list[tuple] = [("m", i // n, i % n) for i in range(n * n)]
    if nonlinear:
        first += [-e for e in eqs] + eqs
        targets += [("f", i) for i in range(n)] + [("dy", i) for i in range(n)]
    else:
        at0 = {rename[x]: 0 for x in spec.xs}
        first += [-e.xreplace(at0) for e in eqs]
        targets += [("f", i) for i in range(n)]
    eqns, _ = assignments(first, targets, inter, x_names, set(), free)
    flat = [sub(e) for row in spec.outputs for e in row]
    columns = None
    if names and not any(not o.encoded for o in job.outputs):
        # run()'s table of the unknowns (after the range's quantity)
        cols = [Column(name, vals.units.get(name)) for name in names]
        if nonlinear:
            flat = [sp.Symbol(e.ident, real=True) for e in initials]
        else:
            flat = [sp.Symbol(a.target[2], real=True) for a in unpack]
        if sweep is not None:
            cols.insert(0, Column(constants[-1].name, job.sweep[1]))
            flat.insert(0, sp.Symbol(constants[-1].ident, real=True))
        columns = [cols]
    outputs = output_block(flat, unpack, inter, x_names, free)
    try:
        tables = output_tables(job, vals, columns)
    except UnitError as exc:
        raise NumericsError(f"{job.where}: {exc}") from None
    return new_program(
        job,
        source,
        nosubs,
        (constants, initials, integration),
        (n, eqns, len(eqns), outputs),
        tables,
        kind=job.kind,
        ranges=ranges,
        t0=integration_parameters(vals)["TINITIAL"],
        labels=eq_labels(job),
        unknowns=names,
        free=free,
    )


def static_in_order(job: Job, name: str) -> tuple[int, str]:
    """Autolev's ``.in`` order of an Algebraic or Nonlinear program: the
    constants (and Specified quantities), then the variables, then their
    first and their second derivatives, each group sorted without case
    (BioMAC's gait2d_osim_NoDer_raw.c reads ``par__wind``, then ``G1 .. G6``
    and ``q1 .. q9`` though the script declares ``q`` before ``G``, then
    ``q1p ..``, ``q1pp ..``; docs/semantics.md)."""
    primes, low = in_order(name)
    base = normalize_name(name).rstrip("'")
    variable = primes or job.entries.get(base, ("",))[0] == "variable"
    return (1 + primes if variable else 0), low


def _ranges(job: Job, quantity: Entry) -> list[Entry]:
    """``[PHI deg=0,360,1]``: three ``.in`` lines, in the range's unit."""
    _obj, unit, start, stop, step = job.sweep
    try:
        f = job.unit_system.to_internal(unit)
    except UnitError as exc:
        raise NumericsError(f"{job.where}: {exc}") from None
    quantity.unit, quantity.factor = unit, f
    return [
        Entry(group, quantity.name, quantity.ident, unit, float(value), f, key)
        for group, key, value in (
            ("Range Start", f"{quantity.name}_START", start),
            ("Range Final", f"{quantity.name}_FINAL", stop),
            ("Range Step", f"{quantity.name}_STEP", step),
        )
    ]
