"""A batch's parameters per step, checked against the engine's declaration before any file runs,
and the command line's NAME=VALUE texts as the declared types."""

from __future__ import annotations

from ._params import DECLARATION


def _declared(step: str) -> dict:
    return {p["name"]: p for p in DECLARATION[step]}


def _check(step: str, name: str, value) -> None:
    """Raises ValueError when value is not one of a choice's values or out of the range."""
    p = _declared(step)[name]
    if p["type"] == "choice" and value not in p["choices"]:
        raise ValueError(f"{step}.{name} must be one of {p['choices']}, got {value!r}")
    if p["type"] in ("real", "integer"):
        if isinstance(value, str):
            raise ValueError(f"{step}.{name} must be a number, got {value!r}")
        lo, hi = p["min"], p["max"]
        low = lo is not None and (value <= lo if p["min_open"] else value < lo)
        high = hi is not None and (value >= hi if p["max_open"] else value > hi)
        if low or high:
            raise ValueError(f"{step}.{name} = {value} is out of its range")


def flat(params: dict) -> dict:
    """params as one flat dict: {"approximate": {...}, ...} becomes {"approximate.NAME": ...}."""
    nested = params and all(k in DECLARATION and isinstance(v, dict) for k, v in params.items())
    return {f"{s}.{k}": v for s, d in params.items() for k, v in d.items()} if nested else dict(params)


def _split(full: str) -> tuple[str, str]:
    """"[step.]name" as (step or "", name with - read as _)."""
    step, _, name = full.strip().rpartition(".")
    return step, name.replace("-", "_")


def per_step(steps: tuple, params: dict) -> dict:
    """{step: {name: value}} for the chosen steps from either that shape or one flat dict (a
    name goes to every chosen step that declares it; "step.name" to that step only). Each step
    runs on one engine thread (one file per core) unless threads is given. Raises ValueError
    for a name no chosen step declares and for a value out of its choices or range."""
    out: dict = {s: {"threads": 1} for s in steps if "threads" in _declared(s)}
    for s in steps:
        out.setdefault(s, {})
    for full, value in flat(params).items():
        step, name = _split(full)
        targets = [step] if step else [s for s in steps if name in _declared(s)]
        if step and step not in steps:
            raise ValueError(f"{full}: {step} is not one of the batch's steps {list(steps)}")
        if not targets or name not in _declared(targets[0]):
            raise ValueError(f"{full}: no parameter of that name in {', '.join(steps)}")
        for s in targets:
            _check(s, name, value)
            out[s][name] = value
    return out


def parse_setting(text: str, steps: tuple) -> tuple[str, object]:
    """"[step.]name=value" as (name, value), the value as the declared type of the first
    chosen step that declares name."""
    full, sep, raw = text.partition("=")
    if not sep:
        raise ValueError(f"--set {text}: expected NAME=VALUE")
    step, name = _split(full)
    kinds = [_declared(s)[name]["type"] for s in ([step] if step else steps)
             if s in DECLARATION and name in _declared(s)]
    kind = kinds[0] if kinds else "str"
    raw = raw.strip()
    if kind == "boolean":
        if raw.lower() not in ("true", "false", "1", "0", "yes", "no", "on", "off"):
            raise ValueError(f"--set {text}: {name} takes true or false")
        return full.strip(), raw.lower() in ("true", "1", "yes", "on")
    if kind in ("real", "integer"):
        try:
            return full.strip(), int(raw) if kind == "integer" else float(raw)
        except ValueError:
            raise ValueError(f"--set {text}: {name} takes a number") from None
    return full.strip(), raw
