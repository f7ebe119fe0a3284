#!/usr/bin/env python3
"""Rewrites the parameter lists of .mlx filter scripts from the parameter declarations.

Every filter of this plugin in a script gets exactly its declared parameters (those MeshLab
has), in order, with their .mlx types, enum items and labels, so meshlabserver 2020.09 (which
aborts on a missing parameter) and pymeshlab read it. A value the script sets is kept (by name;
RENAMED maps the names of earlier versions to today's), a parameter it lacks gets its default.
The comment and the other filters of the script are kept.

Input: the declarations as `qd_reference --json` writes them, and the .mlx files (rewritten in
place). scripts/make_reference.sh runs it on sample_meshes/*.mlx; it also brings a user's own
scripts up to date.

Usage: scripts/update_mlx.py DECLARATIONS.json FILE.mlx [FILE.mlx ...]
"""
from __future__ import annotations

import json
import sys
import xml.etree.ElementTree as ET
from xml.sax.saxutils import quoteattr

# filter -> {name in earlier versions: name now}, for values to keep across a rename.
RENAMED = {
    "Quasi-Developable Approximation": {"tolerance": "tolerance_model"},
    "Quasi-Developable Flattening": {"max_iter": "arap_max_iter", "tolerance": "arap_tolerance"},
}
MLX_TYPES = {"real": "RichFloat", "integer": "RichInt", "boolean": "RichBool", "choice": "RichEnum",
             "text": "RichString", "save_file": "RichSaveFile"}


def default_text(p: dict) -> str:
    """The declared default as an .mlx value."""
    d = p["default"]
    if p["type"] == "boolean":
        return "true" if d else "false"
    if p["type"] == "choice":
        return str(p["choices"].index(d))
    if p["type"] == "real":
        return repr(float(d))
    return str(d)


def param_line(p: dict, value: str) -> str:
    attrs = [("name", p["name"]), ("type", MLX_TYPES[p["type"]]), ("value", value)]
    if p["type"] == "choice":
        attrs.append(("enum_cardinality", str(len(p["choices"]))))
        attrs += [(f"enum_val{i}", c) for i, c in enumerate(p["choices"])]
    if p["type"] == "save_file":
        attrs.append(("ext", p["extension"]))
    attrs.append(("description", p["label"]))
    return "  <Param " + " ".join(f"{k}={quoteattr(v)}" for k, v in attrs) + "/>"


def filter_block(node: ET.Element, declared: list[dict]) -> list[str]:
    """The <filter> element with the declared parameters, keeping the values node sets."""
    renamed = RENAMED.get(node.get("name"), {})
    given = {}
    for p in node.iter("Param"):
        given[renamed.get(p.get("name"), p.get("name"))] = p.get("value")
    lines = [f" <filter name={quoteattr(node.get('name'))}>"]
    lines += [param_line(p, given.get(p["name"], default_text(p))) for p in declared]
    return lines + [" </filter>"]


def rewrite(text: str, filters: dict[str, list[dict]]) -> str:
    """The script `text` with the parameter lists of our filters rewritten."""
    comments = [line.strip() for line in text.splitlines() if line.strip().startswith("<!--")]
    root = ET.fromstring(text)
    lines = ["<!DOCTYPE FilterScript>", "<FilterScript>"] + [" " + c for c in comments]
    for node in root.iter("filter"):
        if node.get("name") in filters:
            lines += filter_block(node, filters[node.get("name")])
        else:
            lines.append(" " + ET.tostring(node, encoding="unicode").strip())
    return "\n".join(lines + ["</FilterScript>"]) + "\n"


def main(argv: list[str]) -> int:
    if len(argv) < 3:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    with open(argv[1]) as f:
        jobs = json.load(f)
    filters = {job["filter"]: [p for p in job["parameters"] if p["fronts"] != "command"]
               for job in jobs.values()}
    for path in argv[2:]:
        with open(path) as f:
            text = f.read()
        new = rewrite(text, filters)
        if new != text:
            with open(path, "w") as f:
                f.write(new)
            print(f"updated {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
