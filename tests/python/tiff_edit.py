"""Reading and patching the first directory of a TIFF or BigTIFF in place, for tests that damage
files the way a broken writer or a bad disk does (TIFF 6.0 §2; BigTIFF's 8-byte layout)."""

import struct

# Bytes of one value by field type (TIFF 6.0 §2, BigTIFF 16-18), and its struct code.
TYPES = {1: "B", 2: "B", 3: "H", 4: "I", 6: "b", 7: "B", 8: "h", 9: "i", 16: "Q", 17: "q", 18: "Q"}


class Entry:
    def __init__(self, tag, type_, count, at, entry_at):
        self.tag, self.type, self.count, self.at, self.entry_at = tag, type_, count, at, entry_at


class Tiff:
    """The first directory of `data` (a bytearray, patched in place)."""

    def __init__(self, data):
        self.data = data
        self.order = "<" if data[:2] == b"II" else ">"
        self.big = struct.unpack(self.order + "H", data[2:4])[0] == 43
        if self.big:
            self.ifd = struct.unpack(self.order + "Q", data[8:16])[0]
            n = struct.unpack(self.order + "Q", data[self.ifd:self.ifd + 8])[0]
            first, size, field = self.ifd + 8, 20, "Q"
        else:
            self.ifd = struct.unpack(self.order + "I", data[4:8])[0]
            n = struct.unpack(self.order + "H", data[self.ifd:self.ifd + 2])[0]
            first, size, field = self.ifd + 2, 12, "I"
        self.entries = {}
        fsize = struct.calcsize(field)
        for i in range(n):
            e = first + size * i
            tag, type_ = struct.unpack(self.order + "HH", data[e:e + 4])
            count = struct.unpack(self.order + field, data[e + 4:e + 4 + fsize])[0]
            value_at = e + 4 + fsize
            nbytes = count * struct.calcsize(TYPES.get(type_, "B"))
            at = value_at if nbytes <= fsize else struct.unpack(self.order + field, data[value_at:value_at + fsize])[0]
            self.entries[tag] = Entry(tag, type_, count, at, e)
        self.ifd_end = first + size * n + fsize

    def values(self, tag):
        e = self.entries[tag]
        code = self.order + str(e.count) + TYPES[e.type]
        return list(struct.unpack(code, self.data[e.at:e.at + struct.calcsize(code)]))

    def set_values(self, tag, values):
        e = self.entries[tag]
        assert len(values) == e.count
        code = self.order + str(e.count) + TYPES[e.type]
        self.data[e.at:e.at + struct.calcsize(code)] = struct.pack(code, *values)

    def set_type(self, tag, type_):
        """Retypes an entry's field (its count and bytes unchanged)."""
        e = self.entries[tag]
        self.data[e.entry_at + 2:e.entry_at + 4] = struct.pack(self.order + "H", type_)
        e.type = type_


def with_entry(data, tag, type_, count, payload):
    """A classic TIFF whose first directory, rewritten at the end of the file, has one more entry
    (after those of lower or equal tags), its value `payload` (the raw bytes) stored after it."""
    t = Tiff(bytearray(data))
    assert not t.big
    o = t.order
    n = struct.unpack(o + "H", data[t.ifd:t.ifd + 2])[0]
    raw = [bytes(data[t.ifd + 2 + 12 * i:t.ifd + 14 + 12 * i]) for i in range(n)]
    next_ifd = data[t.ifd + 2 + 12 * n:t.ifd + 6 + 12 * n]
    out = bytearray(data)
    out += bytes(len(out) % 2)
    payload_at = len(out)
    out += payload + bytes(len(payload) % 2)
    new_ifd = len(out)
    value = payload_at if len(payload) > 4 else struct.unpack(o + "I", payload.ljust(4, b"\0"))[0]
    entry = struct.pack(o + "HHII", tag, type_, count, value)
    tags = [struct.unpack(o + "H", e[:2])[0] for e in raw]
    at = sum(1 for x in tags if x <= tag)
    entries = raw[:at] + [entry] + raw[at:]
    out += struct.pack(o + "H", n + 1) + b"".join(entries) + next_ifd
    out[4:8] = struct.pack(o + "I", new_ifd)
    return out
