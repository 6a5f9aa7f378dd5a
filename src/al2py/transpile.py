"""The pipeline: parse -> expand macros -> analyse the whole file -> generate -> template -> black."""

from __future__ import annotations

import re
import sys
import textwrap
from collections.abc import Callable
from dataclasses import dataclass
from functools import cache, partial
from pathlib import Path

import jinja2
from al2py_runtime import collector
from al2py_runtime.cli import help_text

from . import __version__, ir, static_checks
from .analysis import Analysis
from .errors import AutolevError, ErrorList, InternalError, errors_of
from .generator import Generator, attach_echoes
from .macros import expand
from .parser import parse, parse_partial

__all__ = ["convert", "Conversion"]


@dataclass(frozen=True)
class Conversion:
    """The result of converting one ``.al`` file."""

    code: str
    module: str


@cache
def _template() -> jinja2.Template:
    env = jinja2.Environment(
        loader=jinja2.PackageLoader("al2py", "templates"),
        autoescape=False,
        keep_trailing_newline=True,
        undefined=jinja2.StrictUndefined,
    )
    return env.get_template("module.py.j2")


_HELP_WIDTH = 86  # columns of a help line in the module (88 with its backslash)


def _escaped(text: str) -> str:
    """``text`` as it is written inside a triple-quoted string (trailing
    spaces escaped, so that no line of the module ends in whitespace)."""
    code = text.encode("unicode_escape").decode("ascii").replace('"', '\\"')
    stripped = code.rstrip(" ")
    return stripped + "\\x20" * (len(code) - len(stripped))


def _help_literal(text: str) -> str:
    """The ``--help`` text as one triple-quoted string, a line of the module
    per line of help.  A line too long for 88 columns goes on after a
    backslash (a line continuation inside the string), between two words."""
    out = []
    for line in text.splitlines(keepends=True):
        rest = line.rstrip("\n")
        while len(_escaped(rest)) > _HELP_WIDTH:
            cut = rest.rfind(" ", 1, _HELP_WIDTH)
            while cut > 0 and len(_escaped(rest[:cut])) > _HELP_WIDTH:
                cut = rest.rfind(" ", 1, cut)
            if cut <= 0:  # one long word: cut it where it fits
                cut = _HELP_WIDTH
                while cut > 1 and len(_escaped(rest[:cut])) > _HELP_WIDTH:
                    cut -= 1
            out.append(_escaped(rest[:cut]) + "\\\n")
            rest = rest[cut:]
        out.append(_escaped(rest) + ("\n" if line.endswith("\n") else "\\\n"))
    return '"""\\\n' + "".join(out) + '"""'


def _docstring(source_name: str, module: str, has_job: bool) -> str:
    """The module's docstring: where it came from and how it is used."""
    fill = partial(
        textwrap.fill, width=79, break_long_words=False, break_on_hyphens=False
    )
    use = (
        f"``import {module}`` runs the symbolic part silently; ``AUTOLEV`` maps"
        ' Autolev names (``"ZERO[1]"``, ``"X\'"``) to their current values.'
        f"  ``python {module}.py`` prints the transcript Autolev would print"
    )
    if has_job:
        use += (
            " and runs the CODE job (``--help`` lists its options); ``run()``"
            " runs it from Python"
        )
    head = f"Autolev script {source_name} converted by al2py {__version__}: edit"
    return f"{fill(head + ' the .al file instead.')}\n\n{fill(use + '.')}"


def module_name(filename: str) -> str:
    """A Python module name for ``filename`` (``tutor6.al`` -> ``tutor6``)."""
    stem = Path(filename).stem or "autolev"
    name = re.sub(r"\W", "_", stem)
    return name if not name[0].isdigit() else "m_" + name


def _attach_line(exc: AutolevError, lines: tuple[str, ...], filename: str) -> None:
    """Give an error its source line, for the caret."""
    if not exc.line_text and exc.span is not None and exc.span.file == filename:
        if 0 < exc.span.line <= len(lines):
            exc.line_text = lines[exc.span.line - 1]


def _names_on_lines(script: ir.Script, errors: list[AutolevError]) -> set[str]:
    """Every name on the lines of syntax errors (their statements are skipped)."""
    names: set[str] = set()
    for err in errors:
        if err.span is not None and 0 < err.span.line <= len(script.lines):
            code = script.lines[err.span.line - 1].split("%", 1)[0]
            names.update(w.upper() for w in re.findall(r"[A-Za-z]\w*", code))
    return names


def convert(
    text: str,
    filename: str = "<stdin>",
    *,
    script_dir: Path | None = None,
    autolevpath: str | None = None,
    formatted: bool = True,
    step: Callable[[str], None] | None = None,
) -> Conversion:
    """Convert Autolev source ``text`` into the source of a Python module
    (formatted by black unless ``formatted`` is false: ``al2py code`` runs
    the module without showing it, as modules over :data:`BLACK_LIMIT` are).
    ``step(what)`` is told as each of the :data:`STEPS` begins (progress).

    Raises :class:`al2py.errors.AutolevError` (with a source span) for input
    that is malformed or not supported.
    """
    # Python's cycle collector paused: its full collections walk every
    # object of the process (sympy's, hundreds of thousands, and the
    # conversion's growing trees) again and again while the parser and black
    # make and drop theirs (a fifth of converting Moore's Whipple, half of a
    # 180 kB script); the conversion's cyclic garbage waits for the next
    # collection (a tenth more memory at the peak)
    with collector.paused():
        return _convert(
            text, filename, script_dir, autolevpath, formatted, step or _no_step
        )


#: the steps of a conversion, as ``convert`` tells its ``step``
STEPS = ("parsing", "expanding", "analysing", "generating", "formatting")


def _no_step(what: str) -> None:
    pass


def _convert(
    text: str,
    filename: str,
    script_dir: Path | None,
    autolevpath: str | None,
    formatted: bool,
    step: Callable[[str], None],
) -> Conversion:
    text = text.removeprefix("\ufeff")  # a byte-order mark (Windows editors)
    # Long flat sums make deep (left-leaning) trees; give the walk room.
    sys.setrecursionlimit(max(sys.getrecursionlimit(), 20_000))
    step("parsing")
    static_checks.check_text(text, filename)
    script, errors = parse_partial(text, filename)
    if script_dir is None:
        script_dir = (
            Path(filename).parent if filename not in ("-", "<stdin>") else Path.cwd()
        )
    try:
        step("expanding")
        stmts = expand(script, parse, script_dir=script_dir, autolevpath=autolevpath)
        step("analysing")
        for check in (static_checks.check_statements, static_checks.check_orientations):
            try:
                check(stmts)
            except AutolevError as exc:
                errors = errors + errors_of(exc)
        facts = Analysis(stmts).run(stmts, poisoned=_names_on_lines(script, errors))
    except AutolevError as exc:
        errors = errors + errors_of(exc)
    if errors:
        for err in errors:
            _attach_line(err, script.lines, filename)
        raise errors[0] if len(errors) == 1 else ErrorList(errors)
    step("generating")
    generator = Generator(facts, script.lines)
    try:
        body = generator.body(stmts)
    except AutolevError as exc:
        _attach_line(exc, script.lines, filename)
        raise
    source_name = (
        Path(filename).name if filename not in ("-", "<stdin>") else "stdin.al"
    )
    module = module_name(source_name)
    safe_name = re.sub(r"[^\w.\-]", "_", source_name)
    code = _template().render(
        docstring=_docstring(safe_name, module, generator.has_job),
        source_name=safe_name,
        source_name_repr=repr(source_name),
        module=module,
        version=__version__,
        imports=generator.imports.lines(),
        body="\n".join(body),
        has_job=generator.has_job,
        help_text=_help_literal(
            help_text(source_name, generator.help_inputs, generator.help_jobs)
        ),
        has_kane=generator.has_kane,
    )
    try:
        if formatted and len(code) <= BLACK_LIMIT:
            step("formatting")
            code = _black(code)
        code = attach_echoes(code)  # after black: only lines that fit move
        # Python itself must load the module: an expression nested too deeply
        # for its parser (a 3,000-term power chain) is refused here, located,
        # rather than as a MemoryError traceback at import
        compile(code, f"{module}.py", "exec", dont_inherit=True)
    except (MemoryError, RecursionError):
        raise static_checks.too_deep(filename, text) from None
    except SyntaxError as exc:
        if "nested" in str(exc.msg):  # "too many nested parentheses"
            raise static_checks.too_deep(filename, text) from None
        raise InternalError(f"generated code does not parse: {exc}") from None
    return Conversion(code, module)


def _black(code: str) -> str:
    """``code`` formatted by black, imported only here: ``al2py code`` runs
    its module unformatted and never loads black (a tenth of a second)."""
    import black

    try:
        return black.format_str(code, mode=black.Mode())
    except black.InvalidInput as exc:  # invalid generated code
        raise InternalError(f"generated code does not parse: {exc}") from None


#: generated modules larger than this (characters) skip black, which needs
#: about 1.5 ms per term of a long sum (docs/semantics.md)
BLACK_LIMIT = 300_000
