"""The programs of CODE jobs, in each language: what tests compare."""

from __future__ import annotations


def every_language(jobs: list) -> list[str]:
    """The text of each job's program in C, MATLAB and Fortran, in order.

    >>> every_language([])
    []
    """
    from al2py_runtime.codegen import program_source, target_file
    from al2py_runtime.codegen.program import describe
    from al2py_runtime.codegen.static import describe_static

    out = []
    for job in jobs:
        static = job.kind in ("ALGEBRAIC", "NONLINEAR")
        program = (describe_static if static else describe)(job)
        for lang in ("c", "m", "f"):
            out.append(program_source(program, target_file(job, lang)))
    return out
