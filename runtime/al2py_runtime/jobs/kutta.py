"""Kutta-Merson with Autolev's step control: the integrator of ``run()``.

Autolev's generated programs integrate with Kutta-Merson (L. Fox, 1962): each
call of their ``kutta()`` advances the time by ``INTEGSTP`` in sub-steps that
are halved while an error estimate exceeds both ``ABSERR`` and
``RELERR*|y|``, and doubled (up to ``INTEGSTP``) while it is 64 times
smaller (see docs/semantics.md).  This module holds that integrator twice:

* :data:`KUTTA_C`, the C text that the programs of :mod:`..codegen` print
  and that the ``c`` backend compiles into its library, with
  :data:`ADVANCE_C` (``al_advance``: from one printed row to the next, with
  the run's evaluation and time budgets), so that ``run()`` integrates in
  one compiled call per printed row;
* :class:`KuttaMerson`, the same arithmetic in Python over any ``f(t, y)``,
  for the backends without a C compiler (their tables equal the ``c``
  backend's to round-off).

Both step from row to row as Autolev's main loop does, ``INTEGSTP`` at a time;
where ``TFINAL - TINITIAL`` is not a whole number of ``INTEGSTP``, the last
step is shorter and lands on ``TFINAL`` (``run()``'s last row is at
``TFINAL``).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

__all__ = ["ADVANCE_C", "KUTTA_C", "KuttaMerson", "StepError"]

#: ``al_f`` (the derivatives through ``eqns(t, y, p, dy, ud)``, noting the
#: time of a failing evaluation in ``al_t_error``) and ``kutta()``.  The
#: includer declares ``al_t_error``, ``eqns``, ``AL_NY`` and ``AL_NU``.
KUTTA_C = r"""/* Kutta-Merson (L. Fox, 1962), with the step control of Autolev's programs:
   one call advances *t by H, in sub-steps that are halved while an error
   estimate exceeds both ABSERR and RELERR*|y| and doubled (up to H) while
   it is 64 times smaller.  Returns 0, the eqns code, or 3 (step too small).
   *hc, the sub-step size, carries over from call to call. */
static int al_f(double t, const double *y, const double *p, double *dy)
{
    double ud[AL_NU > 0 ? AL_NU : 1];
    int code = eqns(t, y, p, dy, ud);
    if (code) al_t_error = t;
    return code;
}

static int kutta(double *t, double H, double *y, const double *p, double *hc,
                 int *cuts, double abserr, double relerr)
{
    double f0[AL_NY], f1[AL_NY], f2[AL_NY], y1[AL_NY], y2[AL_NY];
    double tend = *t + H, h, tt;
    int code;
    if (*hc * H < 0.0) *hc = -*hc;
    if (*hc == 0.0) *hc = H;
    h = *hc;
    tt = *t + h;
    while (tt + h != tt) {
        if ((code = al_f(tt - h, y, p, f0))) return code;
        for (int i = 0; i < AL_NY; i++) y1[i] = y[i] + h / 3.0 * f0[i];
        if ((code = al_f(tt - 2.0 * h / 3.0, y1, p, f1))) return code;
        for (int i = 0; i < AL_NY; i++) y1[i] = y[i] + h / 6.0 * (f0[i] + f1[i]);
        if ((code = al_f(tt - 2.0 * h / 3.0, y1, p, f1))) return code;
        for (int i = 0; i < AL_NY; i++) y1[i] = y[i] + h / 8.0 * (f0[i] + 3.0 * f1[i]);
        if ((code = al_f(tt - h / 2.0, y1, p, f2))) return code;
        for (int i = 0; i < AL_NY; i++)
            y1[i] = y[i] + h / 2.0 * (f0[i] - 3.0 * f1[i] + 4.0 * f2[i]);
        if ((code = al_f(tt, y1, p, f1))) return code;
        for (int i = 0; i < AL_NY; i++)
            y2[i] = y[i] + h / 6.0 * (f0[i] + 4.0 * f2[i] + f1[i]);
        int fail = 0, grow = 1;
        for (int i = 0; i < AL_NY && !fail; i++) {
            double err = 0.2 * fabs(y1[i] - y2[i]), rel = relerr * fabs(y1[i]);
            if (err >= rel && err >= abserr) fail = 1;
            else if (64.0 * err > rel && 64.0 * err > abserr) grow = 0;
        }
        if (fail) {  /* again from tt - h with half the step */
            tt -= h / 2.0;
            h = *hc = h / 2.0;
            if ((*cuts)-- > 0) continue;
            *t = tt - h;
            return 3;
        }
        memcpy(y, y2, sizeof y2);
        if (grow && fabs(2.0 * h) <= fabs(H) && (H > 0 ? tt + 2.0 * h <= tend
                                                       : tt + 2.0 * h >= tend)) {
            h = *hc = 2.0 * h;
            (*cuts)++;
        }
        if (tt == tend) {
            *t = tend;
            return 0;
        }
        tt += h;
        if ((h > 0 && tt > tend - 0.1 * h) || (h < 0 && tt < tend - 0.1 * h)) {
            h = tend - (tt - h);  /* land on tend */
            tt = tend;
        }
    }
    *t = tt;
    return 3;
}

"""

#: ``run()``'s driver in the ``c`` backend's library, around the model's
#: ``al_rhs``: ``al_advance`` integrates to the next printed row.  Codes as
#: ``kutta()`` (1 singular, 2 not finite, 3 step halved too often), and 4
#: (the evaluation budget) or 5 (the time budget, processor seconds).
ADVANCE_C = (
    r"""
#include <string.h>
#include <time.h>

static double al_t_error;  /* time of the failing evaluation */
static long long al_evals, al_max_evals;
static clock_t al_deadline;

static int eqns(double t, const double *y, const double *p, double *dy,
                double *ud)
{
    (void)ud;
    if (++al_evals > al_max_evals) return 4;
    if (!(al_evals & 255) && al_deadline && clock() > al_deadline) return 5;
    return al_rhs(t, y, p, dy);
}
"""
    + KUTTA_C
    + r"""
/* From s[0] to target in steps of step (the last one shorter, landing on
   target; a sub-step within round-off of it is made equal to it, else the
   sub-step would end a few units of round-off short of the end and leave a
   last sub-step too small to move t).  s: t, the sub-step carried over, the time of a failure, the
   processor seconds left (0: no limit); n: net halvings left, evaluations
   so far, the evaluation budget.  Not reentrant: one call at a time. */
int al_advance(double target, double step, double abserr, double relerr,
               const double *p, double *y, double *s, long long *n)
{
    int cuts = (int)n[0], code = 0;
    al_evals = n[1];
    al_max_evals = n[2];
    al_deadline = s[3] > 0 ? clock() + (clock_t)(s[3] * CLOCKS_PER_SEC) : 0;
    while (!code && s[0] != target) {
        double left = target - s[0];
        double h = fabs(left) <= fabs(step) * (1.0 + 1e-9) ? left : step;
        if (fabs(s[1]) >= fabs(h) * (1.0 - 1e-9)) s[1] = h;  /* no sliver */
        code = kutta(&s[0], h, y, p, &s[1], &cuts, abserr, relerr);
        if (!code && h == left) s[0] = target;
    }
    n[0] = cuts;
    n[1] = al_evals > al_max_evals ? al_max_evals : al_evals;
    s[2] = code == 3 ? s[0] : al_t_error;
    return code;
}
"""
)


class StepError(ArithmeticError):
    """Kutta-Merson stopped: ``code`` 3 (the step was halved 20 times more
    than doubled), 4 (evaluation budget) or 5 (time budget) at ``t``."""

    def __init__(self, code: int, t: float) -> None:
        super().__init__(f"integration stopped (code {code}) at t = {t:g}")
        self.code = code
        self.t = t


class KuttaMerson:
    """:data:`KUTTA_C`'s ``kutta()`` and ``al_advance`` over a Python
    ``f(t, y) -> array``, the same operations in the same order."""

    def __init__(
        self,
        f: Callable[[float, Any], Any],
        t0: float,
        y0: Any,
        step: float,
        abserr: float,
        relerr: float,
    ) -> None:
        import numpy as np

        self.f = f
        self.t = float(t0)
        self.y = np.array(y0, dtype=float)
        self.step, self.abserr, self.relerr = step, abserr, relerr
        self.hc = 0.0
        self.cuts = 20

    def advance(self, target: float) -> None:
        """Integrate to ``target``; raises :class:`StepError` (code 3)."""
        step = self.step
        while self.t != target:
            left = target - self.t
            h = left if abs(left) <= abs(step) * (1.0 + 1e-9) else step
            if abs(self.hc) >= abs(h) * (1.0 - 1e-9):
                self.hc = h
            self._kutta(h)
            if h == left:
                self.t = target

    def _kutta(self, big: float) -> None:
        import numpy as np

        f, y, abserr, relerr = self.f, self.y, self.abserr, self.relerr
        tend = self.t + big
        if self.hc * big < 0.0:
            self.hc = -self.hc
        if self.hc == 0.0:
            self.hc = big
        h = self.hc
        tt = self.t + h
        while tt + h != tt:
            f0 = np.asarray(f(tt - h, y), dtype=float)
            y1 = y + h / 3.0 * f0
            f1 = np.asarray(f(tt - 2.0 * h / 3.0, y1), dtype=float)
            y1 = y + h / 6.0 * (f0 + f1)
            f1 = np.asarray(f(tt - 2.0 * h / 3.0, y1), dtype=float)
            y1 = y + h / 8.0 * (f0 + 3.0 * f1)
            f2 = np.asarray(f(tt - h / 2.0, y1), dtype=float)
            y1 = y + h / 2.0 * (f0 - 3.0 * f1 + 4.0 * f2)
            f1 = np.asarray(f(tt, y1), dtype=float)
            y2 = y + h / 6.0 * (f0 + 4.0 * f2 + f1)
            err = 0.2 * np.abs(y1 - y2)
            rel = relerr * np.abs(y1)
            if np.any((err >= rel) & (err >= abserr)):
                tt -= h / 2.0
                h = self.hc = h / 2.0
                self.cuts -= 1
                if self.cuts + 1 > 0:
                    continue
                self.t = tt - h
                raise StepError(3, self.t)
            y = self.y = y2
            grow = not np.any((64.0 * err > rel) & (64.0 * err > abserr))
            ahead = tt + 2.0 * h <= tend if big > 0 else tt + 2.0 * h >= tend
            if grow and abs(2.0 * h) <= abs(big) and ahead:
                h = self.hc = 2.0 * h
                self.cuts += 1
            if tt == tend:
                self.t = tend
                return
            tt += h
            if (h > 0 and tt > tend - 0.1 * h) or (h < 0 and tt < tend - 0.1 * h):
                h = tend - (tt - h)
                tt = tend
        self.t = tt
        raise StepError(3, tt)
