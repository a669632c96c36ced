"""Read a debrisflow .vtu frame (raw appended binary) into numpy arrays: read_vtu(path) -> dict."""
import re
import sys

import numpy as np

TYPES = {"Float32": np.float32, "Float64": np.float64, "Int32": np.int32, "UInt8": np.uint8,
         "UInt32": np.uint32, "Int64": np.int64,
         "UInt64": np.uint64}


def read_vtu(path):
    data = open(path, "rb").read()
    head_end = data.index(b'<AppendedData encoding="raw">')
    header = data[:head_end].decode()
    base = data.index(b"_", head_end) + 1
    out = {}
    for m in re.finditer(r'<DataArray type="(\w+)" Name="(\w+)" NumberOfComponents="(\d+)" '
                         r'format="appended" offset="(\d+)"', header):
        typ, name, comps, off = m.group(1), m.group(2), int(m.group(3)), int(m.group(4))
        size = int(np.frombuffer(data, np.uint64, 1, base + off)[0])
        arr = np.frombuffer(data, TYPES[typ], size // np.dtype(TYPES[typ]).itemsize, base + off + 8)
        out[name] = arr.reshape(-1, comps) if comps > 1 else arr
    return out


if __name__ == "__main__":
    d = read_vtu(sys.argv[1])
    for k, v in d.items():
        print(k, v.shape, v.min(axis=0), v.max(axis=0))
