"""The jobs' parameters as the engine declares them (quasidev._engine.declaration(): names,
types, units, defaults, ranges and help), the keyword arguments as the engine takes them, and
the docstring text made from the declaration."""

from __future__ import annotations

import json
import numbers
import textwrap
import warnings

from . import _engine

DECLARATION: dict[str, list[dict]] = json.loads(_engine.declaration())


def report_of(text: str) -> dict:
    """The engine's JSON report as a dict; its warnings issued as UserWarning."""
    report = json.loads(text)
    for w in report.get("warnings", []):
        warnings.warn(w, UserWarning, stacklevel=3)
    return report


def engine_values(params: dict) -> dict:
    """Each keyword argument as a float (bool, int, float, numpy scalars) or a str; the engine
    checks names, types, ranges and choices."""
    out = {}
    for name, value in params.items():
        if isinstance(value, str):
            out[name] = value
        elif isinstance(value, (bool, numbers.Real)) or hasattr(value, "__float__"):
            out[name] = float(value)
        else:
            raise TypeError(f"{name} must be a number, a bool or a str, got {type(value).__name__}")
    return out


def _range_text(p: dict) -> str:
    lo, hi = p["min"], p["max"]
    parts = []
    if lo is not None:
        parts.append(("> " if p["min_open"] else ">= ") + f"{lo:g}")
    if hi is not None:
        parts.append(("< " if p["max_open"] else "<= ") + f"{hi:g}")
    return ", ".join(parts)


def python_type(p: dict) -> str:
    """The Python type of parameter p's value, as a stub writes it."""
    if p["type"] == "choice":
        return "Literal[" + ", ".join(repr(c) for c in p["choices"]) + "]"
    return {"real": "float", "integer": "int", "boolean": "bool"}.get(p["type"], "str")


def parameters_doc(job: str) -> str:
    """The numpydoc lines of job's keyword parameters: type, default, unit, range, help."""
    lines = []
    for p in DECLARATION[job]:
        facts = [f"default {p['default']!r}"]
        if p["unit"]:
            facts.append(f"unit: {p['unit']}")
        if _range_text(p):
            facts.append(f"range: {_range_text(p)}")
        lines.append(f"{p['name']} : {python_type(p)}")
        lines.append(textwrap.indent(textwrap.fill(p["help"] + " (" + "; ".join(facts) + ".)", 88), "    "))
    return "\n".join(lines)


MESH_DOC = """V : array_like, (n, 3)
    Vertex positions, any real dtype and memory order.
F : array_like, (m, 3)
    Triangles as vertex indices."""


CONTRACT_DOC = """The inputs are copied and never modified; the GIL is released while the engine runs. Bad
parameters and meshes the engine refuses raise ValueError with the engine's message."""

PARAMETERS_HEAD = """Keyword parameters (the engine's declaration; the same as the command's options)
----------------------------------------------------------------------------------
"""


def document(function, job: str) -> None:
    """Fills function's docstring: the mesh arrays at {mesh}, what every job promises at
    {contract}, job's parameters under their heading at {parameters}."""
    parts = {
        "{mesh}": MESH_DOC,
        "{contract}": CONTRACT_DOC,
        "{parameters}": PARAMETERS_HEAD + parameters_doc(job),
    }
    doc = function.__doc__
    for mark, text in parts.items():
        doc = doc.replace(mark, text.replace("\n", "\n    "))
    function.__doc__ = doc
