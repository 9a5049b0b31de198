"""The binary side of the test scenes' generated glTF files: one buffer, embedded as a data
URI, that grows a view and an accessor per array. Standard library only."""
import base64
import json
import struct


class GltfBuffer:
    def __init__(self):
        self.data = bytearray()
        self.views, self.accessors = [], []

    def add_floats(self, values, kind, count):
        """A float accessor (kind "VEC3") with its min and max, as glTF requires for POSITION."""
        offset = len(self.data)
        self.data.extend(struct.pack("<%df" % len(values), *values))
        self.views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(values) * 4})
        n = {"VEC3": 3}[kind]
        lo = [min(values[i::n]) for i in range(n)]
        hi = [max(values[i::n]) for i in range(n)]
        self.accessors.append({"bufferView": len(self.views) - 1, "componentType": 5126,
                               "count": count, "type": kind, "min": lo, "max": hi})
        return len(self.accessors) - 1

    def add_points(self, points):
        return self.add_floats([c for p in points for c in p], "VEC3", len(points))

    def add_indices(self, values):
        """16-bit indices, padded so the next view stays 4-byte aligned."""
        offset = len(self.data)
        self.data.extend(struct.pack("<%dH" % len(values), *values))
        while len(self.data) % 4:
            self.data.append(0)
        self.views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(values) * 2})
        self.accessors.append({"bufferView": len(self.views) - 1, "componentType": 5123,
                               "count": len(values), "type": "SCALAR"})
        return len(self.accessors) - 1

    def add_ground(self, half_size):
        """A square at y = 0 facing up: (positions, normals, indices) accessors."""
        h = half_size
        positions = self.add_floats([-h, 0, -h, h, 0, -h, h, 0, h, -h, 0, h], "VEC3", 4)
        normals = self.add_floats([0, 1, 0] * 4, "VEC3", 4)
        return positions, normals, self.add_indices([0, 2, 1, 0, 3, 2])

    def write(self, doc, path):
        """Adds the accessors, views and the buffer to `doc` and writes it as JSON."""
        doc["accessors"] = self.accessors
        doc["bufferViews"] = self.views
        doc["buffers"] = [{"byteLength": len(self.data),
                           "uri": "data:application/octet-stream;base64," +
                                  base64.b64encode(bytes(self.data)).decode()}]
        with open(path, "w") as f:
            json.dump(doc, f, indent=1)
            f.write("\n")
