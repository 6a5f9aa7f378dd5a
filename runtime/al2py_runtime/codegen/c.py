"""The C99 spelling of a :class:`~.program.Program`."""

from __future__ import annotations

import json
import math
import textwrap
from typing import Any

import sympy as sp

from ..jobs import backends
from ..jobs.kutta import KUTTA_C
from .printers import PrintedOnce, holds_instance
from .program import Assign, Program

__all__ = ["c_source"]


class _Printer(PrintedOnce, backends.CPrinter):
    """The C backend's printer (strict), each part printed once per program
    (see :class:`.printers.PrintedOnce`)."""

    def __init__(self) -> None:
        backends.CPrinter.__init__(self)
        self.start_remembering(strict=True)
        self._re: dict = {}  # part -> whether it holds an re(...)

    # the backend's printing of sums, products, powers and calls, remembered
    def _print_Add(self, expr: Any, *args: Any, **kwargs: Any) -> str:  # noqa: N802
        return self.print_once(super()._print_Add, expr, *args, **kwargs)

    def _print_Mul(self, expr: Any, *args: Any, **kwargs: Any) -> str:  # noqa: N802
        return self.print_once(super()._print_Mul, expr, *args, **kwargs)

    def _print_Abs(self, expr: Any, *args: Any, **kwargs: Any) -> str:  # noqa: N802
        return self.print_once(super()._print_Abs, expr, *args, **kwargs)

    def _print_sign(self, expr: Any, *args: Any, **kwargs: Any) -> str:  # noqa: N802
        return self.print_once(super()._print_sign, expr, *args, **kwargs)

    def _print_sin(self, expr: Any, *args: Any, **kwargs: Any) -> str:  # noqa: N802
        return self.print_once(super()._print_sin, expr, *args, **kwargs)

    def _print_cos(self, expr: Any, *args: Any, **kwargs: Any) -> str:  # noqa: N802
        return self.print_once(super()._print_cos, expr, *args, **kwargs)

    def _print_tan(self, expr: Any, *args: Any, **kwargs: Any) -> str:  # noqa: N802
        return self.print_once(super()._print_tan, expr, *args, **kwargs)

    def _print_asin(self, expr: Any, *args: Any, **kwargs: Any) -> str:  # noqa: N802
        return self.print_once(super()._print_asin, expr, *args, **kwargs)

    def _print_acos(self, expr: Any, *args: Any, **kwargs: Any) -> str:  # noqa: N802
        return self.print_once(super()._print_acos, expr, *args, **kwargs)

    def _print_atan(self, expr: Any, *args: Any, **kwargs: Any) -> str:  # noqa: N802
        return self.print_once(super()._print_atan, expr, *args, **kwargs)

    def _print_atan2(self, expr: Any, *args: Any, **kwargs: Any) -> str:  # noqa: N802
        return self.print_once(super()._print_atan2, expr, *args, **kwargs)

    def _print_exp(self, expr: Any, *args: Any, **kwargs: Any) -> str:  # noqa: N802
        return self.print_once(super()._print_exp, expr, *args, **kwargs)

    def _print_log(self, expr: Any, *args: Any, **kwargs: Any) -> str:  # noqa: N802
        return self.print_once(super()._print_log, expr, *args, **kwargs)

    def _handle_UnevaluatedExpr(self, expr: Any) -> Any:  # noqa: N802 - sympy's
        # the backend's: nothing to do without re(...) (asked of each part
        # once per program, not walked again in each statement)
        if isinstance(expr, sp.Basic) and not holds_instance(expr, sp.re, self._re):
            return expr
        return super()._handle_UnevaluatedExpr(expr)


def _string(text: str) -> str:
    return json.dumps(text)  # a valid C string literal for ASCII text


def _block_comment(lines: list[str], first: str = "/* ") -> list[str]:
    out = [("   " if i else first) + ln for i, ln in enumerate(lines)]
    return out[:-1] + [out[-1] + " */"]


def _double(x: float) -> str:
    return repr(float(x)) if math.isfinite(x) else "0.0"


def _assign(a: Assign, printer: Any, n: int, texts: dict) -> str:
    """The C statement of ``a``; ``texts`` keeps each expression's text (the
    outputs routine declares again the intermediates that ``eqns`` has)."""
    kind = a.target[0]
    if kind == "ud":
        return f"    const double {a.target[2]} = ud[{a.target[1]}];"
    e = texts.get(a.expr)
    if e is None:
        e = texts[a.expr] = backends.c_expression(a.expr, printer)
    if kind == "tmp":
        return f"    const double {a.target[1]} = {e};"
    if kind == "m":
        return f"    mm[{a.target[1] * n + a.target[2]}] = {e};"
    if kind == "f":
        return f"    ud[{a.target[1]}] = {e};"
    return f"    {kind}[{a.target[1]}] = {e};"


def _unpack(program: Program, block: list[Assign]) -> list[str]:
    lines = [
        f"    const double {e.ident} = p[{i}];  /* {e.name} */"
        for i, e in program.params_used(block)
    ]
    lines += [
        f"    const double {e.ident} = y[{i}];  /* {e.name} */"
        for i, e in program.states_used(block)
    ]
    return lines


def equations(program: Program, api: str) -> list[str]:
    """``eqns`` and ``outputs`` (with ``al_solve`` when needed)."""
    printer = _Printer()
    texts: dict = {}
    n = program.nu
    lines = [
        f"#define AL_NY {program.ny}  /* states */",
        f"#define AL_NU {n}  /* solved from M ud = f */",
        f"#define AL_NP {program.np}  /* constants */",
        f"#define AL_NOUT {program.nout}  /* outputs, all tables */",
    ]
    if n:
        lines.append(backends.SOLVE_C)
    used = [a.expr for a in program.eqns]
    lines += [
        *_block_comment(program.eqns_doc),
        f"{api}int eqns(double T, const double y[], const double p[], double dy[],",
        "         double ud[])",
        "{",
    ]
    if n:
        lines.append(f"    double mm[{n * n}];")
    lines += _unpack(program, program.eqns)
    lines.append("    (void)T; (void)y; (void)p; (void)ud;")
    for k, a in enumerate(program.eqns):
        if k == program.solve_at and n:
            lines.append(f"    if (al_solve({n}, mm, ud)) return 1;")
        lines.append(_assign(a, printer, n, texts))
    if program.solve_at == len(program.eqns) and n:
        lines.append(f"    if (al_solve({n}, mm, ud)) return 1;")
    lines += [
        "    for (int al_i = 0; al_i < AL_NY; al_i++)",
        "        if (!isfinite(dy[al_i])) return 2;",
        "    return 0;",
        "}",
        "",
        "/* The output quantities at (T, y), every table's columns in order. */",
        f"{api}int outputs(double T, const double y[], const double p[], double out[])",
        "{",
        f"    double dy[{max(program.ny, 1)}], ud[{max(n, 1)}];",
        "    int code = eqns(T, y, p, dy, ud);",
        "    if (code) return code;",
    ]
    lines += _unpack(program, program.outputs)
    lines.append("    (void)out;")
    lines += [_assign(a, printer, n, texts) for a in program.outputs]
    lines += ["    return 0;", "}", ""]
    del used
    return lines


def c_source(program: Program, target: str) -> str:
    job = program.job
    head = [
        f"/* {target}: generated by al2py {program.version} from {program.source}",
        f"   ({job.where}); edit the .al file and generate again.",
        "",
    ]
    if program.nosubs:
        head += [
            "   NOSUBS: the equations only, no main program.  Link with your own:",
            "   eqns(T, y, p, dy, ud) and outputs(T, y, p, out); y holds the states",
            "   (Nonlinear: the unknowns), p the constants, in the order listed",
            "   below (internal units). */",
            "#include <math.h>",
            "",
        ]
        head += _listing(program)
        return "\n".join(head + equations(program, "")) + "\n"
    head += [
        f"   Build: cc -O2 -std=c99 -o {program.stem} {target} -lm",
        f"   Run:   ./{program.stem} [NAME=VALUE ...]",
        "",
        f"   Reads {program.stem}.in when it is in the current folder (the values",
        "   from column 60 on, a blank line after each group), else starts from",
        "   the script's Input values; NAME=VALUE changes one (in its Input's",
        "   unit).",
        *_block_comment(textwrap.wrap(program.task, 72), "   "),
        "#include <ctype.h>",
        "#include <math.h>",
        "#include <stdio.h>",
        "#include <stdlib.h>",
        "#include <string.h>",
        "",
    ]
    lines = head + equations(program, "static ")
    entries = program.entries
    lines += [
        "/* Inputs: name, value (in the Input's unit), factor to internal units */",
        "typedef struct {",
        "    const char *name;",
        "    double value;",
        "    double factor;",
        "} al_input;",
        "",
        f"#define AL_NIN {len(entries)}",
        "static al_input al_inputs[AL_NIN] = {",
    ]
    for e in entries:
        lines.append(
            f"    {{{_string(e.setting)}, {_double(e.value)}, {_double(e.factor)}}},"
        )
    groups = [len(g) for g in program.groups]
    tables = program.tables
    nt = len(tables)
    factors = [x for t in tables for x in t.factors] or [1.0]

    def ints(xs: list[int]) -> str:
        return ", ".join(str(x) for x in xs or [0])

    lines += [
        "};",
        f"#define AL_NGROUP {len(groups)}",
        f"static const int al_group[AL_NGROUP] = {{{ints(groups)}}};",
        f"#define AL_NTABLE {nt}",
        f"static const double al_factor[{len(factors)}] = {{"
        + ", ".join(_double(x) for x in factors)
        + "};",
        f"static const int al_columns[{max(nt, 1)}] = {{{ints([t.columns for t in tables])}}};",
        f"static const int al_width[{max(nt, 1)}] = {{{ints([t.width for t in tables])}}};",
        f"static const int al_written[{max(nt, 1)}] = "
        f"{{{ints([int(t.written) for t in tables])}}};",
        f"static const char *al_header[{max(nt, 1)}] = {{",
    ]
    for t in tables or [None]:
        lines.append(f"    {_string(t.header if t else '')},")
    lines += [
        "};",
        f"#define AL_NNOTE {len(program.notes)}  /* values taken as 0 */",
        f"static const char *al_note[{max(len(program.notes), 1)}] = {{"
        + ", ".join(_string(x) for x in program.notes or [""])
        + "};",
        f"#define AL_DIGITS {program.digits}",
        f"#define AL_STEM {_string(program.stem)}",
        f"#define AL_WHERE {_string(job.where)}",
        f"#define AL_I_STATE {len(program.inputs)}  /* first state in al_inputs */",
        f"#define AL_I_INTEG {len(program.inputs) + program.ny}  /* after the states:"
        " the range or the integration parameters */",
    ]
    if program.kind == "NONLINEAR":
        labels = ", ".join(_string(x) for x in program.labels)
        lines += [
            f"#define AL_T0 {_double(program.t0)}  /* T in the equations */",
            f"static const char *al_label[AL_NY] = {{{labels}}};",
            _COMMON_C + _NEWTON_C,
        ]
    elif program.kind == "ALGEBRAIC":
        lines += [
            f"#define AL_T0 {_double(program.t0)}  /* T in the equations */",
            _COMMON_C + _algebraic_main(program),
        ]
    else:
        lines.append(_COMMON_C + _KUTTA_C + _MAIN_DYNAMICS_C)
    return "\n".join(lines)


def _algebraic_main(program: Program) -> str:
    """One row, or one per value of the range ``[PHI deg=0,360,1]`` (the
    last constant) with run()'s values: start + k*step while within the
    final value (plus 1e-9 of a step), and the final value last."""
    at, args = "", ", AL_WHERE"
    if not program.ranges:
        loop = [
            "    if (al_open(files)) return 2;",
            "    code = al_write_row(files, AL_T0, y, p);",
        ]
    else:
        at, args = " at %s = %g", ", AL_WHERE, r[0].name, x"
        loop = [
            "    const al_input *r = &al_inputs[AL_I_INTEG];  /* start, final, step */",
            "    double start = r[0].value, final = r[1].value, step = r[2].value, x = 0;",
            "    if (step == 0.0 && final != start) {",
            r'        fprintf(stderr, "error: the range step must not be 0\n");',
            "        return 2;",
            "    }",
            "    if ((final - start) * step < 0) step = -step;",
            "    long n = final == start ? 0 : (long)floor((final - start) / step + 1e-9);",
            "    int extra = fabs(start + (double)n * step - final)"
            " > 1e-9 * fmax(1.0, fabs(final));",
            "    if (al_open(files)) return 2;",
            "    for (long k = 0; k <= n + extra && !code; k++) {",
            "        x = k < n || (k == n && extra) ? start + (double)k * step : final;",
            "        p[AL_NP - 1] = x * r[0].factor;",
            "        code = al_write_row(files, AL_T0, y, p);",
            "    }",
        ]
    lines = [
        "",
        "int main(int argc, char **argv)",
        "{",
        "    double v[AL_NIN], p[AL_NP > 0 ? AL_NP : 1], y[1] = {0.0};",
        "    FILE *files[AL_NTABLE > 0 ? AL_NTABLE : 1];",
        "    int code = al_start(argc, argv, v);",
        "    if (code) return code == 1 ? 0 : 2;",
        f"    for (int i = 0; i < {len(program.inputs)}; i++) p[i] = v[i];",
        *loop,
        "    al_close(files, code);",
        "    if (code == 1)",
        '        fprintf(stderr, "error: %s: the equations are singular'
        f' (no unique solution){at}\\n"{args});',
        "    else if (code == 2)",
        f'        fprintf(stderr, "error: %s: a value is not finite{at}\\n"{args});',
        "    return code ? 2 : 0;",
        "}",
        "",
    ]
    return "\n".join(lines)


def _listing(program: Program) -> list[str]:
    lines = ["/* p[]:"]
    lines += [
        f"     {i:3d}  {e.name} ({e.unit or 'UNITS'})"
        for i, e in enumerate(program.constants)
    ]
    lines.append("   y[]:")
    lines += [
        f"     {i:3d}  {e.name} ({e.unit or 'UNITS'})"
        for i, e in enumerate(program.initials)
    ]
    if program.kind == "ALGEBRAIC":
        lines.append("   ud[] (solved by eqns): " + ", ".join(program.unknowns))
    lines.append("   out[]:")
    k = 0
    for t in program.tables:
        lines.append(f"     {k:3d}..{k + t.columns - 1}  table {t.number}")
        k += t.columns
    return lines + ["*/", ""]


_COMMON_C = r"""
static double al_t_error;  /* time of the failing evaluation */

static int al_same(const char *a, const char *b, size_t n)
{
    if (strlen(b) != n) return 0;
    for (size_t i = 0; i < n; i++)
        if (toupper((unsigned char)a[i]) != toupper((unsigned char)b[i])) return 0;
    return 1;
}

static int al_set(const char *arg)
{
    const char *eq = strchr(arg, '=');
    char *end;
    if (!eq || eq == arg) {
        fprintf(stderr, "error: %s: expected NAME=VALUE\n", arg);
        return 1;
    }
    double v = strtod(eq + 1, &end);
    if (end == eq + 1 || *end) {
        fprintf(stderr, "error: %s: '%s' is not a number\n", arg, eq + 1);
        return 1;
    }
    for (int i = 0; i < AL_NIN; i++)
        if (al_same(arg, al_inputs[i].name, (size_t)(eq - arg))) {
            al_inputs[i].value = v;
            return 0;
        }
    fprintf(stderr, "error: %.*s is not an input; inputs:", (int)(eq - arg), arg);
    for (int i = 0; i < AL_NIN; i++) fprintf(stderr, " %s", al_inputs[i].name);
    fprintf(stderr, "\n");
    return 1;
}

/* STEM.in: 6 header lines, then each group's values from column 60, one
   line after each group.  Returns 0 (or 0 with nothing read: no file). */
static int al_read_in(const char *name)
{
    char line[4096];
    long number = 0;
    FILE *in = fopen(name, "r");
    if (!in) return 0;
    for (int i = 0; i < 6; i++, number++)
        if (!fgets(line, sizeof line, in)) goto short_file;
    for (int g = 0, k = 0; g < AL_NGROUP; g++) {
        for (int i = 0; i < al_group[g]; i++, k++) {
            char *end;
            number++;
            if (!fgets(line, sizeof line, in)) goto short_file;
            if (strlen(line) < 60) goto bad;
            al_inputs[k].value = strtod(line + 59, &end);
            if (end == line + 59) goto bad;
            while (isspace((unsigned char)*end)) end++;
            if (*end) goto bad;
        }
        number++;
        if (!fgets(line, sizeof line, in)) goto short_file;
    }
    fclose(in);
    return 0;
bad:
    fprintf(stderr, "error: %s line %ld: expected one number from column 60: %s",
            name, number, line);
    fclose(in);
    return 1;
short_file:
    fprintf(stderr, "error: %s ends at line %ld, before its last value\n", name,
            number);
    fclose(in);
    return 1;
}

static int al_write_row(FILE **files, double t, const double *y, const double *p)
{
    double out[AL_NOUT > 0 ? AL_NOUT : 1];
    int code = outputs(t, y, p, out);
    if (code) {
        al_t_error = t;
        return code;
    }
    for (int k = 0, j = 0; k < AL_NTABLE; j += al_columns[k], k++) {
        if (!files[k]) continue;  /* Encode's quantities: no file */
        fputc(' ', files[k]);
        for (int c = 0; c < al_columns[k]; c++)
            fprintf(files[k], "%*.*E", al_width[k], AL_DIGITS - 1,
                    out[j + c] * al_factor[j + c]);
        fputc('\n', files[k]);
    }
    return 0;
}

/* --help, STEM.in, then NAME=VALUE arguments; v: the inputs in internal
   units.  Returns 0, 1 after --help, 2 after an error. */
static int al_start(int argc, char **argv, double v[])
{
    if (argc > 1 && (!strcmp(argv[1], "-h") || !strcmp(argv[1], "--help"))) {
        printf("usage: %s [NAME=VALUE ...]\n"
               "reads %s.in if present; inputs (in their Input units):\n",
               argv[0], AL_STEM);
        for (int i = 0; i < AL_NIN; i++)
            printf("  %s = %.15g\n", al_inputs[i].name, al_inputs[i].value);
        return 1;
    }
    if (al_read_in(AL_STEM ".in")) return 2;
    for (int i = 1; i < argc; i++)
        if (al_set(argv[i])) return 2;
    for (int i = 0; i < AL_NNOTE; i++) fprintf(stderr, "note: %s\n", al_note[i]);
    for (int i = 0; i < AL_NIN; i++) v[i] = al_inputs[i].value * al_inputs[i].factor;
    return 0;
}

/* Opens the output files (not Encode's) and writes their headers. */
static int al_open(FILE **files)
{
    for (int k = 0; k < AL_NTABLE; k++) {
        char name[4096];
        files[k] = 0;
        if (!al_written[k]) continue;
        snprintf(name, sizeof name, "%s.%d", AL_STEM, k + 1);
        files[k] = fopen(name, "w");
        if (!files[k]) {
            perror(name);
            return 2;
        }
        fputs(al_header[k], files[k]);
    }
    return 0;
}

/* Closes the output files; lists them when code is 0. */
static void al_close(FILE **files, int code)
{
    for (int k = 0; k < AL_NTABLE; k++)
        if (files[k]) fclose(files[k]);
    for (int k = 0; k < AL_NTABLE && !code; k++)
        if (al_written[k]) printf("Wrote %s.%d\n", AL_STEM, k + 1);
}
"""

_KUTTA_C = "\n" + KUTTA_C  # the C text that run() compiles too

_MAIN_DYNAMICS_C = r"""
int main(int argc, char **argv)
{
    double v[AL_NIN], p[AL_NP > 0 ? AL_NP : 1], y[AL_NY];
    FILE *files[AL_NTABLE > 0 ? AL_NTABLE : 1];
    int code = al_start(argc, argv, v);
    if (code) return code == 1 ? 0 : 2;
    for (int i = 0; i < AL_NP; i++) p[i] = v[i];
    for (int i = 0; i < AL_NY; i++) y[i] = v[AL_I_STATE + i];
    double t0 = v[AL_I_INTEG], t1 = v[AL_I_INTEG + 1], step = v[AL_I_INTEG + 2];
    double print = v[AL_I_INTEG + 3], atol = v[AL_I_INTEG + 4];
    double rtol = v[AL_I_INTEG + 5];
    if (step == 0.0 || print <= 0 || atol <= 0 || rtol <= 0) {
        fprintf(stderr, "error: INTEGSTP must not be 0; PRINTINT, ABSERR and"
                        " RELERR must be positive\n");
        return 2;
    }
    if (print != floor(print)) {
        fprintf(stderr, "error: PRINTINT is a whole number of integration steps,"
                        " not %g\n", print);
        return 2;
    }
    if ((t1 - t0) * step < 0) step = -step;  /* toward TFINAL */
    if (al_open(files)) return 2;
    /* As Autolev's programs: a row at TINITIAL, after every PRINTINT steps
       of INTEGSTP, and at the first step within INTEGSTP/100 of TFINAL. */
    double t = t0, hc = 0.0;
    int cuts = 20;
    long count = 0;
    double dy[AL_NY];
    code = al_f(t, y, p, dy);
    while (!code) {
        int last = t1 >= t0 ? t + 0.01 * fabs(step) >= t1 : t - 0.01 * fabs(step) <= t1;
        if (count <= 0 || last) {
            if ((code = al_write_row(files, t, y, p))) break;
            if (last) break;
            count = (long)print;
        }
        code = kutta(&t, step, y, p, &hc, &cuts, atol, rtol);
        count--;
    }
    al_close(files, code);
    if (code == 1)
        fprintf(stderr, "error: the mass matrix is singular at t = %g\n", al_t_error);
    else if (code == 2)
        fprintf(stderr, "error: a value is not finite at t = %g\n", al_t_error);
    else if (code == 3)
        fprintf(stderr, "error: integration failed at t = %g: the step was halved"
                        " too often (ABSERR, RELERR)\n", t);
    return code ? 2 : 0;
}
"""

_NEWTON_C = r"""
#define AL_MAXIT 100  /* Newton iterations */
#define AL_HALVINGS 30  /* of one step, while max|F| does not decrease */

static double al_norm(const double *f, int *worst)
{
    double m = 0.0;
    for (int i = 0; i < AL_NY; i++)
        if (!(fabs(f[i]) <= m)) {  /* a NaN is the largest */
            m = fabs(f[i]);
            *worst = i;
        }
    return m;
}

/* Newton's method from the guesses y: eqns leaves the residuals F in f and
   the step dx solving J dx = -F in dx.  A step is halved (up to
   AL_HALVINGS times) until max|F| decreases.  Converged when max|F| <=
   ABSERR * max(1, max|F(guesses)|) and every |dx[i]| <= ABSERR +
   RELERR*|y[i]|; that last step is taken.  Returns 0, 1 (J singular), 2 (a
   value not finite) or 4 (no convergence); *res: max|F|, *worst: its i. */
static int al_newton(double *y, const double *p, double abserr, double relerr,
                     double *res, int *worst, int *iters)
{
    double f[AL_NY], dx[AL_NY], yn[AL_NY], fn[AL_NY], dxn[AL_NY];
    int code = eqns(AL_T0, y, p, f, dx);
    double norm = *res = al_norm(f, worst);
    double tol = abserr * (norm > 1.0 ? norm : 1.0);
    for (*iters = 0; *iters < AL_MAXIT; (*iters)++) {
        if (code) return code;
        int small = 1;
        for (int i = 0; i < AL_NY; i++)
            if (fabs(dx[i]) > abserr + relerr * fabs(y[i])) small = 0;
        if (small && norm <= tol) {
            for (int i = 0; i < AL_NY; i++) y[i] += dx[i];
            return 0;
        }
        double lambda = 1.0;
        for (int half = 0;; half++) {
            for (int i = 0; i < AL_NY; i++) yn[i] = y[i] + lambda * dx[i];
            int w = 0, c = eqns(AL_T0, yn, p, fn, dxn);
            double next = al_norm(fn, &w);
            if (c != 2 && next < norm) {
                memcpy(y, yn, sizeof yn);
                memcpy(f, fn, sizeof fn);
                memcpy(dx, dxn, sizeof dxn);
                norm = *res = next;
                *worst = w;
                code = c;
                break;
            }
            if (half == AL_HALVINGS) return 4;
            lambda /= 2.0;
        }
    }
    return 4;
}

int main(int argc, char **argv)
{
    double v[AL_NIN], p[AL_NP > 0 ? AL_NP : 1], y[AL_NY], res = 0.0;
    FILE *files[AL_NTABLE > 0 ? AL_NTABLE : 1];
    int code = al_start(argc, argv, v), worst = 0, iters = 0;
    if (code) return code == 1 ? 0 : 2;
    for (int i = 0; i < AL_NP; i++) p[i] = v[i];
    for (int i = 0; i < AL_NY; i++) y[i] = v[AL_I_STATE + i];
    double abserr = v[AL_I_INTEG], relerr = v[AL_I_INTEG + 1];
    if (abserr <= 0 || relerr <= 0) {
        fprintf(stderr, "error: ABSERR and RELERR must be positive\n");
        return 2;
    }
    code = al_newton(y, p, abserr, relerr, &res, &worst, &iters);
    if (code == 1) {
        fprintf(stderr, "error: %s: the Jacobian of the equations is singular"
                        " after %d Newton iterations; try other guesses in %s.in\n",
                AL_WHERE, iters, AL_STEM);
        return 2;
    }
    if (code) {
        fprintf(stderr, "error: %s: no solution found from the guesses in %s.in:"
                        " |%s| = %.3g after %d Newton iterations; try other"
                        " guesses\n", AL_WHERE, AL_STEM, al_label[worst], res, iters);
        return 2;
    }
    if (al_open(files)) return 2;
    code = al_write_row(files, AL_T0, y, p);
    al_close(files, code);
    if (code) {
        fprintf(stderr, "error: %s: an output is not finite at the solution\n",
                AL_WHERE);
        return 2;
    }
    return 0;
}
"""
