"""Playing a :class:`~al2py_runtime.jobs.scene.Scene`: an HTML player, GIF and MP4.

``result.animate()`` returns an :class:`Animation`.  In a notebook it shows
itself (``_repr_html_``: a canvas and a short script of our own, no network);
``save("x.html")`` writes a self-contained page that plays offline;
``save("x.gif")`` (Pillow) and ``save("x.mp4")`` (ffmpeg) write movies
through matplotlib (the ``plot`` extra).

The view is orthographic.  Up is against gravity when the script gives
``Gravity``; a motion in a plane of ``N`` is seen square on, any other from
an oblique angle; drag the picture to turn it.  Each frame's triad draws its
unit vectors 1, 2, 3 in red, green and blue.

A point on a rod turning at 1 rad/s (``Scene`` as :func:`.scene.scene`
computes it; the positions are measure numbers in ``N``):

>>> import numpy as np
>>> from sympy.physics.vector import Point, ReferenceFrame
>>> from al2py_runtime.jobs.scene import Layout, Scene
>>> N, O, P = ReferenceFrame("N"), Point("O"), Point("P")
>>> times = np.linspace(0.0, 1.0, 3)
>>> rod = np.stack([np.cos(times), np.sin(times), 0 * times], axis=1)
>>> positions = np.stack([0 * rod, rod], axis=1)  # (rows, points, 3)
>>> shown = Layout(N, O, [O, P], [], [], [], [(0, 1)])
>>> movie = Animation(Scene(shown, times, positions, np.zeros((3, 0, 3, 3)),
...                         np.zeros(3), "sec", "m"), title="rod")
>>> movie.view()["right"], movie.view()["up"]  # seen along N3, N2 up
([1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
>>> page = movie.html()
>>> page.startswith("<!DOCTYPE html>") and "<canvas" in page and "http" not in page
True
"""

from __future__ import annotations

import html
import itertools
import json
import math
from pathlib import Path
from typing import Any

import numpy as np

from .records import NumericsError
from .scene import Scene

__all__ = ["Animation"]

#: the player (ours, no library): ``DATA`` and ``ID`` are filled in
_PLAYER = r"""
(function () {
  var D = DATA, id = "ID";
  var cv = document.getElementById(id + "-c"), g = cv.getContext("2d");
  var sl = document.getElementById(id + "-s"), bt = document.getElementById(id + "-b");
  var lb = document.getElementById(id + "-t");
  var n = D.t.length, row = 0, playing = n > 1, t0 = null, from = D.t[0];
  var az = D.az * Math.PI / 180, el = D.el * Math.PI / 180, drag = null;
  var colors = ["#d62728", "#2ca02c", "#1f77b4"];
  function cross(a, b) {
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  }
  function dot(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  function basis() {
    var u = D.up, h = D.h, s = cross(u, h), v = [0, 0, 0];
    for (var i = 0; i < 3; i++)
      v[i] = Math.cos(el) * (Math.cos(az) * h[i] + Math.sin(az) * s[i]) + Math.sin(el) * u[i];
    var r = cross(u, v), m = Math.sqrt(dot(r, r)) || 1;
    r = [r[0] / m, r[1] / m, r[2] / m];
    return [r, cross(v, r)];
  }
  function pt(i) { var P = D.P[row]; return [P[3 * i], P[3 * i + 1], P[3 * i + 2]]; }
  function draw() {
    var b = basis(), r = b[0], u = b[1], w = cv.width, h = cv.height, c = D.center;
    if (D.follow) {  // the mean of the points but the origin
      var m = D.names.length, first = m > 1 ? 1 : 0;
      c = [0, 0, 0];
      for (var i = first; i < m; i++) {
        var p = pt(i);
        for (var k = 0; k < 3; k++) c[k] += p[k] / (m - first);
      }
    }
    var s = Math.min(w, h) / (2.2 * D.radius), cr = dot(c, r), cu = dot(c, u);
    function X(p) { return [w / 2 + s * (dot(p, r) - cr), h / 2 - s * (dot(p, u) - cu)]; }
    function seg(a, z, color, width) {
      g.strokeStyle = color; g.lineWidth = width; g.beginPath();
      g.moveTo(a[0], a[1]); g.lineTo(z[0], z[1]); g.stroke();
    }
    g.fillStyle = "#ffffff"; g.fillRect(0, 0, w, h);
    g.font = "12px sans-serif";
    D.lines.forEach(function (l) { seg(X(pt(l[0])), X(pt(l[1])), "#555555", 4); });
    var A = D.A[row];
    D.anchors.forEach(function (k, f) {
      var o = pt(k), a = X(o);
      for (var j = 0; j < 3; j++) {
        var e = [A[9 * f + j], A[9 * f + 3 + j], A[9 * f + 6 + j]];
        var z = X([o[0] + D.axis * e[0], o[1] + D.axis * e[1], o[2] + D.axis * e[2]]);
        seg(a, z, colors[j], 2);
        g.fillStyle = colors[j]; g.fillText(D.frames[f] + (j + 1), z[0] + 2, z[1] - 2);
      }
    });
    D.names.forEach(function (name, i) {
      var p = X(pt(i));
      g.fillStyle = "#000000"; g.beginPath(); g.arc(p[0], p[1], 4, 0, 2 * Math.PI); g.fill();
      g.fillText(name, p[0] + 6, p[1] + 14);
    });
    lb.textContent = "T = " + D.t[row].toPrecision(4) + (D.tu ? " " + D.tu : "");
    sl.value = row;
  }
  function at(tt) {
    var lo = 0, hi = n - 1;
    while (lo < hi) { var mid = (lo + hi + 1) >> 1; if (D.t[mid] <= tt) lo = mid; else hi = mid - 1; }
    return lo;
  }
  function tick(ts) {
    if (playing) {
      if (t0 === null) { t0 = ts; from = D.t[row]; }
      var tt = from + (ts - t0) / 1000 * D.speed;
      if (tt > D.t[n - 1]) { t0 = ts; from = D.t[0]; tt = from; }
      var next = at(tt);
      if (next !== row) { row = next; draw(); }
    }
    window.requestAnimationFrame(tick);
  }
  bt.onclick = function () { playing = !playing; t0 = null; bt.textContent = playing ? "Pause" : "Play"; };
  sl.oninput = function () { playing = false; bt.textContent = "Play"; row = +sl.value; draw(); };
  cv.onmousedown = function (e) { drag = [e.clientX, e.clientY]; };
  window.addEventListener("mouseup", function () { drag = null; });
  cv.onmousemove = function (e) {
    if (!drag) return;
    az -= (e.clientX - drag[0]) * 0.01;
    el = Math.max(-1.55, Math.min(1.55, el + (e.clientY - drag[1]) * 0.01));
    drag = [e.clientX, e.clientY]; draw();
  };
  bt.textContent = playing ? "Pause" : "Play";
  draw();
  window.requestAnimationFrame(tick);
})();
"""

_FRAGMENT = """\
<div id="{id}" style="font-family: sans-serif; display: inline-block">
<div style="font-weight: bold">{title}</div>
<canvas id="{id}-c" width="{width}" height="{height}" \
style="border: 1px solid #cccccc; cursor: move"></canvas>
<div><button id="{id}-b">Pause</button> \
<input id="{id}-s" type="range" min="0" max="{last}" value="0" style="width: 60%"> \
<span id="{id}-t"></span></div>
<div style="font-size: small; color: #666666">{legend}</div>
<script>{script}</script>
</div>"""

_PAGE = """\
<!DOCTYPE html>
<html>
<head>
<meta charset="utf-8">
<title>{title}</title>
</head>
<body>
{fragment}
</body>
</html>
"""

_ids = itertools.count(1)


def _unit(v: np.ndarray) -> np.ndarray:
    norm = float(np.linalg.norm(v))
    return v / norm if norm > 0 else v


def _nums(a: np.ndarray) -> list[float]:
    """Values with 6 significant digits (the page stays small)."""
    return [float(f"{x:.6g}") for x in np.asarray(a, dtype=float).ravel()]


class Animation:
    """A scene to play: ``_repr_html_`` in a notebook, :meth:`save` to a
    file (``.html``, ``.gif``, ``.mp4``), :meth:`html` for the page.

    ``speed`` is simulated seconds per second of playing; ``follow`` keeps
    the mean of the points (but the origin) at the center (by default when the motion wanders
    more than twice the model's size: a bicycle that rides off)."""

    def __init__(
        self,
        scene: Scene,
        *,
        title: str = "",
        speed: float = 1.0,
        width: int = 640,
        height: int = 480,
        follow: bool | None = None,
    ) -> None:
        if not speed > 0:
            raise NumericsError(f"animate: speed must be positive, not {speed}")
        self.scene = scene
        self.title = title
        self.speed = float(speed)
        self.width, self.height = int(width), int(height)
        self.follow = follow
        #: the file :meth:`save` wrote last
        self.path: Path | None = None

    # ------------------------------------------------------------- data

    @property
    def times(self) -> np.ndarray:
        return self.scene.times

    @property
    def positions(self) -> dict[str, np.ndarray]:
        """Each point's position from the origin, (rows, 3) in ``N``."""
        return {n: self.scene.positions[:, i] for i, n in enumerate(self.scene.names)}

    def view(self) -> dict[str, Any]:
        """The camera: world ``up``, the horizontal ``h`` looked along at
        azimuth and elevation 0, the starting ``az``/``el`` (degrees), and the
        screen's ``right`` and ``up`` at the start (measure numbers in N)."""
        pos = self.scene.positions.reshape(-1, 3)
        spread = np.ptp(pos, axis=0) if len(pos) else np.zeros(3)
        size = float(spread.max()) if spread.size else 0.0
        gravity = self.scene.gravity
        up = -_unit(gravity) if np.linalg.norm(gravity) > 0 else None
        flat = [k for k in range(3) if spread[k] <= 1e-9 * max(size, 1e-300)]
        eye = np.eye(3)
        if flat and size > 0:  # a motion in a plane of N: seen square on
            normal = eye[flat[-1]]
            if up is None or abs(float(up @ normal)) > 1e-6:
                up = eye[(flat[-1] + 2) % 3]
            up = _unit(up - (up @ normal) * normal)
            h, az, el = normal, 0.0, 0.0
        else:
            if up is None:
                up = eye[2]
            k = int(np.argmin(np.abs(eye @ up)))
            h = _unit(eye[k] - (eye[k] @ up) * up)
            az, el = -35.0, 20.0
        s = np.cross(up, h)
        a, e = math.radians(az), math.radians(el)
        v = math.cos(e) * (math.cos(a) * h + math.sin(a) * s) + math.sin(e) * up
        right = _unit(np.cross(up, v))
        return {
            "up": _nums(up),
            "h": _nums(h),
            "az": az,
            "el": el,
            "right": _nums(right),
            "screen_up": _nums(np.cross(v, right)),
        }

    def _extent(self) -> tuple[list[float], float, bool, float]:
        """Center, radius, whether to follow, triad length."""
        pos = self.scene.positions
        if pos.size == 0:
            return [0.0, 0.0, 0.0], 1.0, False, 0.2
        flat = pos.reshape(-1, 3)
        lo, hi = flat.min(axis=0), flat.max(axis=0)
        center = (lo + hi) / 2
        whole = float(np.linalg.norm(flat - center, axis=1).max())
        moving = pos[:, 1:] if pos.shape[1] > 1 else pos  # all but the origin
        means = moving.mean(axis=1, keepdims=True)
        local = float(np.linalg.norm(moving - means, axis=2).max())
        follow = self.follow
        if follow is None:
            follow = local > 0 and whole > 2 * local
        radius = local if follow else whole
        radius = radius if radius > 0 else 1.0
        axis = 0.2 * radius
        return _nums(center), 1.15 * radius + axis, bool(follow), axis

    def data(self) -> dict[str, Any]:
        """What the player reads (JSON)."""
        sc = self.scene
        center, radius, follow, axis = self._extent()
        view = self.view()
        rows = len(sc.times)
        return {
            "title": self.title,
            "t": _nums(sc.times),
            "tu": sc.time_unit or "",
            "lu": sc.length_unit or "",
            "names": sc.names,
            "P": [_nums(sc.positions[r]) for r in range(rows)],
            "lines": [list(pq) for pq in sc.layout.lines],
            "frames": sc.frame_names,
            "anchors": list(sc.layout.anchors),
            "A": [_nums(sc.axes[r]) for r in range(rows)],
            "up": view["up"],
            "h": view["h"],
            "az": view["az"],
            "el": view["el"],
            "center": center,
            "radius": float(f"{radius:.6g}"),
            "axis": float(f"{axis:.6g}"),
            "follow": follow,
            "speed": self.speed,
        }

    # ------------------------------------------------------------- html

    def fragment(self, element_id: str = "al2py-animation") -> str:
        """The player as an HTML fragment (a ``<div>`` with its script)."""
        data = json.dumps(self.data(), separators=(",", ":"), allow_nan=True)
        script = _PLAYER.replace("DATA", data).replace('"ID"', json.dumps(element_id))
        script = script.replace("</", "<\\/")
        sc = self.scene
        unit = f" ({sc.length_unit})" if sc.length_unit else ""
        legend = (
            f"positions from {sc.layout.origin.name} in {sc.layout.newtonian.name}"
            f"{unit}; frames {', '.join(sc.frame_names) or 'none'}"
            " (1 red, 2 green, 3 blue); drag to turn"
        )
        return _FRAGMENT.format(
            id=element_id,
            title=html.escape(self.title),
            width=self.width,
            height=self.height,
            last=max(len(sc.times) - 1, 0),
            legend=html.escape(legend),
            script=script,
        )

    def html(self) -> str:
        """A self-contained page (no network) that plays the animation."""
        return _PAGE.format(title=html.escape(self.title), fragment=self.fragment())

    def _repr_html_(self) -> str:
        return self.fragment(f"al2py-animation-{next(_ids)}")

    def __repr__(self) -> str:
        sc = self.scene
        return (
            f"<Animation {self.title}: {len(sc.times)} rows of "
            f"{', '.join(sc.names)}; frames {', '.join(sc.frame_names) or 'none'}>"
        )

    # ------------------------------------------------------------- files

    def save(self, path: str | Path) -> Path:
        """Write ``path``: ``.html`` (self-contained), ``.gif`` (Pillow) or
        ``.mp4`` (ffmpeg), by its suffix."""
        path = Path(path)
        suffix = path.suffix.lower()
        if suffix in (".html", ".htm"):
            path.write_text(self.html(), encoding="utf-8")
        elif suffix in (".gif", ".mp4"):
            self._movie(path, suffix)
        else:
            raise NumericsError(
                f"animate: cannot write {path.name}; use .html, .gif or .mp4"
            )
        self.path = path
        return path

    def _movie(self, path: Path, suffix: str) -> None:
        try:
            from matplotlib import animation as mpl_animation
            from matplotlib.backends.backend_agg import FigureCanvasAgg
            from matplotlib.figure import Figure
        except ImportError:
            raise NumericsError(
                f"animate: writing {suffix} needs matplotlib:"
                " pip install 'al2py-runtime[plot]'"
            ) from None
        if suffix == ".gif":
            if not mpl_animation.writers.is_available("pillow"):
                raise NumericsError("animate: writing .gif needs Pillow")
            writer_class: Any = mpl_animation.PillowWriter
        else:
            if not mpl_animation.writers.is_available("ffmpeg"):
                raise NumericsError(
                    "animate: writing .mp4 needs ffmpeg on the PATH; write .html"
                    " or .gif instead"
                )
            writer_class = mpl_animation.FFMpegWriter
        sc = self.scene
        rows = len(sc.times)
        step = 1
        if rows > 1:
            dt = float(np.median(np.diff(sc.times))) or 1.0
            step = max(1, math.ceil((self.speed / abs(dt)) / 25))
            fps = max(1, round(self.speed / abs(dt) / step))
        else:
            fps = 1
        view = self.view()
        right, up = np.array(view["right"]), np.array(view["screen_up"])
        screen = np.stack(
            [sc.positions @ right, sc.positions @ up], axis=-1
        )  # (rows, points, 2)
        center, radius, follow, axis = self._extent()
        fig = Figure(figsize=(self.width / 100, self.height / 100), dpi=100)
        FigureCanvasAgg(fig)
        ax = fig.add_axes((0, 0, 1, 1))
        ax.set_aspect("equal")
        ax.axis("off")
        lines = [ax.plot([], [], color="#555555", lw=3)[0] for _ in sc.layout.lines]
        colors = ("#d62728", "#2ca02c", "#1f77b4")
        triads = [
            [ax.plot([], [], color=c, lw=1.5)[0] for c in colors]
            for _ in sc.layout.frames
        ]
        dots = ax.plot([], [], "o", color="black", ms=5)[0]
        label = ax.text(0.02, 0.95, "", transform=ax.transAxes)

        fixed = np.array([np.array(center) @ right, np.array(center) @ up])

        def update(r: int) -> list:
            xy = screen[r]
            mid = (xy[1:] if len(xy) > 1 else xy).mean(axis=0) if follow else fixed
            ax.set_xlim(mid[0] - radius, mid[0] + radius)
            ax.set_ylim(mid[1] - radius, mid[1] + radius)
            for art, (i, j) in zip(lines, sc.layout.lines, strict=True):
                art.set_data([xy[i, 0], xy[j, 0]], [xy[i, 1], xy[j, 1]])
            for arts, k, f in zip(
                triads, sc.layout.anchors, range(len(triads)), strict=True
            ):
                for j, art in enumerate(arts):
                    e = sc.axes[r, f, :, j] * axis
                    tip = xy[k] + np.array([e @ right, e @ up])
                    art.set_data([xy[k, 0], tip[0]], [xy[k, 1], tip[1]])
            dots.set_data(xy[:, 0], xy[:, 1])
            unit = f" {sc.time_unit}" if sc.time_unit else ""
            label.set_text(f"{self.title}  T = {sc.times[r]:.4g}{unit}")
            return []

        movie = mpl_animation.FuncAnimation(
            fig, update, frames=range(0, rows, step), blit=False
        )
        movie.save(str(path), writer=writer_class(fps=fps))
