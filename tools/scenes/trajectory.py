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
