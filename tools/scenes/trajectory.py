"""Reads FOSSSim trajectory files (docs/command-line.md, 'Trajectory files'): frames of 2N
positions then 2N velocities, little-endian IEEE doubles, no header; frame 0 is the initial
state."""

import struct


def read_frames(path, num_particles, dim=2):
    """Returns a list of (q, v) frames, q and v lists of dim * num_particles floats."""
    dofs = dim * num_particles
    size = 2 * dofs * 8
    with open(path, "rb") as f:
        data = f.read()
    if len(data) % size:
        raise ValueError(f"{path}: {len(data)} bytes is not a whole number of {size}-byte frames")
    frames = []
    layout = struct.Struct(f"<{2 * dofs}d")
    for offset in range(0, len(data), size):
        values = layout.unpack_from(data, offset)
        frames.append((values[:dofs], values[dofs:]))
    return frames


def point(vector, i, dim=2):
    return vector[dim * i:dim * i + dim]


def read_records(path, num_particles, dim=2, layout="frames"):
    """Reads every record of a trajectory in one of the layouts of docs/collisions.md: "frames"
    (Theme 1), "collisions" (type simple) or "polynomials" (continuous-time and hybrid: the
    initial record, then a sync record and an end-of-step record per step). Returns a list of
    dicts with q, v, collisions [(type, first, second, normal, time)] and polynomials
    [coefficients, highest degree first]."""
    if layout == "frames":
        return [{"q": q, "v": v, "collisions": [], "polynomials": []}
                for q, v in read_frames(path, num_particles, dim)]
    dofs = dim * num_particles
    with open(path, "rb") as f:
        data = f.read()
    records, at = [], 0
    frame = struct.Struct(f"<{2 * dofs}d")
    collision = struct.Struct(f"<iii{dim + 1}d")
    while at < len(data):
        values = frame.unpack_from(data, at)
        at += frame.size
        (count,) = struct.unpack_from("<i", data, at)
        at += 4
        collisions = []
        for _ in range(count):
            c = collision.unpack_from(data, at)
            at += collision.size
            collisions.append((c[0], c[1], c[2], c[3:3 + dim], c[3 + dim]))
        polynomials = []
        if layout == "polynomials":
            (count,) = struct.unpack_from("<i", data, at)
            at += 4
            for _ in range(count):
                (length,) = struct.unpack_from("<i", data, at)
                at += 4
                polynomials.append(struct.unpack_from(f"<{length}d", data, at))
                at += 8 * length
        records.append({"q": values[:dofs], "v": values[dofs:], "collisions": collisions,
                        "polynomials": polynomials})
    return records


def layout_of_scene(text):
    """The trajectory layout of a scene file's text, from its <collision type>."""
    for kind, layout in (('"simple"', "collisions"), ('"continuous-time"', "polynomials"),
                         ('"hybrid"', "polynomials")):
        if f"<collision type={kind}" in text:
            return layout
    return "frames"
