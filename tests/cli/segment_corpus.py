"""The bad-input corpus (make_bad_corpus.py) for the segmentation, shared by its command,
meshlabserver and pymeshlab tests: each case's approximation options become the segmentation's
own bad value of the same kind (options that only steer the approximation are dropped), as
command-line options or as the filter's parameters."""
from __future__ import annotations

# The approximation's options in the corpus -> the segmentation's option, its filter parameter
# and the parameter's type.
_SEGMENT = {("--tolerance", "-1"): ("--max-error", "-1", "max_error_deg", float),
            ("--max-iter", "0"): ("--min-faces", "0", "min_faces", int),
            ("--weight", "nan"): ("--crease", "nan", "crease_deg", float),
            ("--developability", "curve"): None}


def _pairs(args):
    return [_SEGMENT[pair] for pair in zip(args[::2], args[1::2]) if _SEGMENT[pair] is not None]


def segment_options(args: list[str]) -> list[str]:
    """`quasidev segment` options for a case's arguments."""
    return [word for option, value, _, _ in _pairs(args) for word in (option, value)]


def segment_parameters(args: list[str]) -> dict:
    """{filter parameter name: value} for a case's arguments."""
    return {name: kind(value) for _, value, name, kind in _pairs(args)}
