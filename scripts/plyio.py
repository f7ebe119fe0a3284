"""Small PLY reader/writer (Python standard library only).

Input:  a PLY file in ascii, binary_little_endian or binary_big_endian format with any
        elements and properties (scalar or list), e.g. the files MeshLab 2020.09 writes
        (float x y z, uchar red green blue alpha, float quality, camera element) or the
        double-precision files of sample_meshes/ and tests/data/.
Output: read_ply() -> PlyData, whose elements hold one Python list per property
        (a list of tuples for list properties); write_ply() writes such data back.
"""
from __future__ import annotations

import struct
from dataclasses import dataclass, field

# PLY type name -> struct code; both the classic and the sized names are accepted.
_TYPES = {
    "char": "b", "int8": "b", "uchar": "B", "uint8": "B",
    "short": "h", "int16": "h", "ushort": "H", "uint16": "H",
    "int": "i", "int32": "i", "uint": "I", "uint32": "I",
    "float": "f", "float32": "f", "double": "d", "float64": "d",
}
_FORMATS = {"ascii": None, "binary_little_endian": "<", "binary_big_endian": ">"}


class PlyError(ValueError):
    """The file is not a PLY this reader understands; the message says why."""


@dataclass
class PlyProperty:
    name: str
    type: str                      # value type, e.g. "double"
    count_type: str | None = None  # list length type ("uchar") or None for a scalar

    def header_line(self) -> str:
        if self.count_type is None:
            return f"property {self.type} {self.name}"
        return f"property list {self.count_type} {self.type} {self.name}"


@dataclass
class PlyElement:
    name: str
    count: int
    properties: list[PlyProperty] = field(default_factory=list)
    data: dict[str, list] = field(default_factory=dict)

    def property_names(self) -> list[str]:
        return [p.name for p in self.properties]


@dataclass
class PlyData:
    format: str = "binary_little_endian"
    comments: list[str] = field(default_factory=list)
    elements: dict[str, PlyElement] = field(default_factory=dict)

    def has(self, element: str, prop: str) -> bool:
        return element in self.elements and prop in self.elements[element].data

    def get(self, element: str, prop: str) -> list:
        if not self.has(element, prop):
            raise PlyError(f"PLY has no property '{prop}' in element '{element}'")
        return self.elements[element].data[prop]

    def count(self, element: str) -> int:
        return self.elements[element].count if element in self.elements else 0

    def vertices(self) -> list[tuple[float, float, float]]:
        """Vertex positions as (x, y, z) tuples."""
        return list(zip(self.get("vertex", "x"), self.get("vertex", "y"), self.get("vertex", "z")))

    def faces(self) -> list[tuple[int, ...]]:
        """Face vertex index tuples (property vertex_indices or vertex_index)."""
        for name in ("vertex_indices", "vertex_index"):
            if self.has("face", name):
                return list(self.get("face", name))
        return []


def _check_type(name: str) -> str:
    if name not in _TYPES:
        raise PlyError(f"unknown PLY property type '{name}'")
    return name


def _parse_header(f) -> tuple[PlyData, list[PlyElement]]:
    if f.readline().strip() != b"ply":
        raise PlyError("not a PLY file: first line is not 'ply'")
    ply = PlyData()
    order: list[PlyElement] = []
    while True:
        raw = f.readline()
        if not raw:
            raise PlyError("PLY header has no 'end_header' line")
        words = raw.decode("ascii", errors="replace").split()
        if not words:
            continue
        key = words[0]
        if key == "end_header":
            break
        if key == "format":
            if len(words) < 2 or words[1] not in _FORMATS:
                raise PlyError(f"unsupported PLY format line: {raw!r}")
            ply.format = words[1]
        elif key in ("comment", "obj_info"):
            ply.comments.append(raw.decode("ascii", errors="replace").rstrip("\r\n")[len(key) + 1:])
        elif key == "element":
            elem = PlyElement(words[1], int(words[2]))
            order.append(elem)
            ply.elements[elem.name] = elem
        elif key == "property":
            if not order:
                raise PlyError("PLY property line before any element line")
            if words[1] == "list":
                prop = PlyProperty(words[4], _check_type(words[3]), _check_type(words[2]))
            else:
                prop = PlyProperty(words[2], _check_type(words[1]))
            order[-1].properties.append(prop)
        else:
            raise PlyError(f"unknown PLY header line: {raw!r}")
    return ply, order


def _scalar_groups(props: list[PlyProperty], endian: str):
    """Split a record layout into runs of scalars (one struct each) and single lists."""
    groups, run = [], []
    for p in props:
        if p.count_type is None:
            run.append(p)
            continue
        if run:
            groups.append((run, struct.Struct(endian + "".join(_TYPES[q.type] for q in run))))
            run = []
        groups.append(([p], None))
    if run:
        groups.append((run, struct.Struct(endian + "".join(_TYPES[q.type] for q in run))))
    return groups


def _read_binary_element(buf: bytes, pos: int, elem: PlyElement, endian: str) -> int:
    cols = {p.name: [] for p in elem.properties}
    if all(p.count_type is None for p in elem.properties):
        rec = struct.Struct(endian + "".join(_TYPES[p.type] for p in elem.properties))
        end = pos + rec.size * elem.count
        if end > len(buf):
            raise PlyError(f"PLY file is truncated in element '{elem.name}'")
        rows = list(rec.iter_unpack(buf[pos:end])) if rec.size else []
        for k, p in enumerate(elem.properties):
            cols[p.name] = [r[k] for r in rows]
        elem.data = cols
        return end
    groups = _scalar_groups(elem.properties, endian)
    lists = {}
    for props, st in groups:
        if st is None:
            p = props[0]
            lists[p.name] = (struct.Struct(endian + _TYPES[p.count_type]), _TYPES[p.type],
                             struct.calcsize(_TYPES[p.type]))
    try:
        for _ in range(elem.count):
            for props, st in groups:
                if st is not None:
                    vals = st.unpack_from(buf, pos)
                    pos += st.size
                    for p, v in zip(props, vals):
                        cols[p.name].append(v)
                else:
                    cst, code, size = lists[props[0].name]
                    (n,) = cst.unpack_from(buf, pos)
                    pos += cst.size
                    cols[props[0].name].append(struct.unpack_from(f"{endian}{n}{code}", buf, pos))
                    pos += n * size
    except struct.error as exc:
        raise PlyError(f"PLY file is truncated in element '{elem.name}'") from exc
    elem.data = cols
    return pos


def _convert(token: str, ptype: str):
    return float(token) if _TYPES[ptype] in "fd" else int(token)


def _read_ascii_elements(body: bytes, order: list[PlyElement]) -> None:
    tokens = body.split()
    i = 0
    try:
        for elem in order:
            cols = {p.name: [] for p in elem.properties}
            for _ in range(elem.count):
                for p in elem.properties:
                    if p.count_type is None:
                        cols[p.name].append(_convert(tokens[i].decode(), p.type))
                        i += 1
                    else:
                        n = int(tokens[i])
                        cols[p.name].append(tuple(_convert(t.decode(), p.type)
                                                  for t in tokens[i + 1:i + 1 + n]))
                        i += 1 + n
            elem.data = cols
    except (IndexError, ValueError) as exc:
        raise PlyError(f"ASCII PLY body is truncated or malformed in element '{elem.name}'") from exc


def read_ply(path) -> PlyData:
    """Read every element and property of a PLY file."""
    with open(path, "rb") as f:
        ply, order = _parse_header(f)
        body = f.read()
    endian = _FORMATS[ply.format]
    if endian is None:
        _read_ascii_elements(body, order)
    else:
        pos = 0
        for elem in order:
            pos = _read_binary_element(body, pos, elem, endian)
    return ply


def _header(ply: PlyData) -> bytes:
    lines = ["ply", f"format {ply.format} 1.0"]
    lines += [f"comment {c}" for c in ply.comments]
    for elem in ply.elements.values():
        lines.append(f"element {elem.name} {elem.count}")
        lines += [p.header_line() for p in elem.properties]
    lines.append("end_header")
    return ("\n".join(lines) + "\n").encode("ascii")


def _ascii_value(v, ptype: str) -> str:
    return repr(float(v)) if _TYPES[ptype] in "fd" else str(int(v))


def _body(ply: PlyData) -> bytes:
    endian = _FORMATS[ply.format]
    out = []
    for elem in ply.elements.values():
        for name in elem.property_names():
            if len(elem.data.get(name, ())) != elem.count:
                raise PlyError(f"element '{elem.name}' property '{name}' needs {elem.count} values")
        columns = [elem.data[p.name] for p in elem.properties]
        for row in zip(*columns):
            if endian is None:
                words = []
                for p, v in zip(elem.properties, row):
                    if p.count_type is None:
                        words.append(_ascii_value(v, p.type))
                    else:
                        words += [str(len(v))] + [_ascii_value(x, p.type) for x in v]
                out.append((" ".join(words) + "\n").encode("ascii"))
                continue
            fmt, vals = endian, []
            for p, v in zip(elem.properties, row):
                if p.count_type is None:
                    fmt += _TYPES[p.type]
                    vals.append(v)
                else:
                    fmt += _TYPES[p.count_type] + _TYPES[p.type] * len(v)
                    vals += [len(v), *v]
            out.append(struct.pack(fmt, *vals))
    return b"".join(out)


def ply_bytes(ply: PlyData) -> bytes:
    """The complete file content of ply (header + body)."""
    if ply.format not in _FORMATS:
        raise PlyError(f"unsupported PLY format '{ply.format}'")
    return _header(ply) + _body(ply)


def write_ply(path, ply: PlyData) -> None:
    """Write ply to path; the element order is the insertion order of ply.elements."""
    with open(path, "wb") as f:
        f.write(ply_bytes(ply))
