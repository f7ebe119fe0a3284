"""Minimal PLY reader for the end-to-end tests (ascii and both binary byte orders).

read_ply(path) -> (elements, comments): elements is a list of (name, count, props) where props is
a list of (name, type, is_list, values); a scalar's values are one number per element, a list's one
tuple per element. Independent of the C++ reader on purpose: the tests check the command's output
with a second implementation.
"""
import struct

_TYPES = {
    "char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
    "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
    "float": "f", "float32": "f", "double": "d", "float64": "d",
}


def _header(data):
    end = data.index(b"end_header")
    body = data.index(b"\n", end) + 1
    lines = data[:end].decode("ascii").splitlines()
    assert lines[0].strip() == "ply"
    fmt, elements, comments = None, [], []
    for line in lines[1:]:
        w = line.split()
        if not w:
            continue
        if w[0] == "format":
            fmt = w[1]
        elif w[0] == "comment":
            comments.append(line[len("comment "):])
        elif w[0] == "element":
            elements.append([w[1], int(w[2]), []])
        elif w[0] == "property":
            if w[1] == "list":
                elements[-1][2].append([w[4], (w[2], w[3]), True, []])
            else:
                elements[-1][2].append([w[2], w[1], False, []])
    return fmt, elements, comments, body


def read_ply(path):
    with open(path, "rb") as f:
        data = f.read()
    fmt, elements, comments, pos = _header(data)
    if fmt == "ascii":
        tokens = data[pos:].split()
        i = 0
        for _, count, props in elements:
            for _ in range(count):
                for p in props:
                    if p[2]:
                        n = int(tokens[i])
                        p[3].append(tuple(float(t) for t in tokens[i + 1:i + 1 + n]))
                        i += n + 1
                    else:
                        p[3].append(float(tokens[i]))
                        i += 1
        return elements, comments
    order = "<" if fmt == "binary_little_endian" else ">"
    for _, count, props in elements:
        for _ in range(count):
            for p in props:
                if p[2]:
                    ct, vt = (_TYPES[t] for t in p[1])
                    (n,) = struct.unpack_from(order + ct, data, pos)
                    pos += struct.calcsize(ct)
                    p[3].append(struct.unpack_from(order + vt * n, data, pos))
                    pos += struct.calcsize(vt) * n
                else:
                    t = _TYPES[p[1]]
                    (v,) = struct.unpack_from(order + t, data, pos)
                    pos += struct.calcsize(t)
                    p[3].append(v)
    assert pos == len(data), "trailing bytes after the last element"
    return elements, comments


def element(elements, name):
    for e in elements:
        if e[0] == name:
            return e
    raise KeyError(name)


def column(elements, element_name, prop):
    for p in element(elements, element_name)[2]:
        if p[0] == prop:
            return p[3]
    raise KeyError(prop)


def prop_type(elements, element_name, prop):
    for p in element(elements, element_name)[2]:
        if p[0] == prop:
            return p[1]
    raise KeyError(prop)


def has(elements, element_name, prop):
    return any(p[0] == prop for p in element(elements, element_name)[2])


def write_ply(path, elements, fmt, comments=()):
    """Writes tables as returned by read_ply in format fmt (ascii / binary_*_endian)."""
    head = ["ply", f"format {fmt} 1.0"] + [f"comment {c}" for c in comments]
    for name, count, props in elements:
        head.append(f"element {name} {count}")
        for pname, ptype, is_list, _ in props:
            head.append(f"property list {ptype[0]} {ptype[1]} {pname}" if is_list
                        else f"property {ptype} {pname}")
    head.append("end_header")
    out = ("\n".join(head) + "\n").encode()
    order = "<" if fmt == "binary_little_endian" else ">"
    rows = []
    for _, count, props in elements:
        for i in range(count):
            if fmt == "ascii":
                row = []
                for _, ptype, is_list, values in props:
                    vals = values[i] if is_list else [values[i]]
                    if is_list:
                        row.append(str(len(vals)))
                    row += [repr(v) for v in vals]
                rows.append((" ".join(row) + "\n").encode())
                continue
            for _, ptype, is_list, values in props:
                if is_list:
                    ct, vt = (_TYPES[t] for t in ptype)
                    rows.append(struct.pack(order + ct + vt * len(values[i]), len(values[i]),
                                            *values[i]))
                else:
                    rows.append(struct.pack(order + _TYPES[ptype], values[i]))
    with open(path, "wb") as f:
        f.write(out + b"".join(rows))
