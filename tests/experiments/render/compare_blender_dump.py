# The vertex positions Blender shows (blender_import.py --dump) against the run's own render
# meshes of those frames (frames/frame_NNNN.ply, written by the run with [effects]
# render_meshes): every vertex equal to float32 precision.
# Usage: compare_blender_dump.py DUMP.csv RUN
import csv
import struct
import sys
from pathlib import Path


def read_ply_vertices(path):
    """The vertices of a binary little-endian PLY whose vertex properties are x y z doubles."""
    data = path.read_bytes()
    header_end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:header_end].decode().splitlines()
    if "format binary_little_endian 1.0" not in header:
        sys.exit(f"{path}: not a binary little-endian PLY")
    count = next(int(line.split()[2]) for line in header if line.startswith("element vertex"))
    return list(struct.iter_unpack("<3d", data[header_end:header_end + 24 * count]))


def main(dump, run):
    shown = {}
    with open(dump) as f:
        for row in csv.DictReader(f):
            shown.setdefault(int(row["frame"]), []).append((float(row["x"]), float(row["y"]), float(row["z"])))
    if len(shown) < 3:
        sys.exit(f"{dump}: {len(shown)} frames, not 3")
    for frame, positions in sorted(shown.items()):
        ours = read_ply_vertices(Path(run) / "frames" / f"frame_{frame:04d}.ply")
        if len(ours) != len(positions):
            sys.exit(f"frame {frame}: Blender shows {len(positions)} vertices, the run has {len(ours)}")
        worst = 0.0
        for a, b in zip(positions, ours):
            for u, v in zip(a, b):
                f32 = struct.unpack("<f", struct.pack("<f", v))[0]
                worst = max(worst, abs(u - f32) / max(abs(v), 1e-30))
        if worst > 1.2e-7:  # a float32's rounding: 2^-24 relative, with room for one step
            sys.exit(f"frame {frame}: a vertex is {worst:.2e} (relative) from the run's")
        print(f"frame {frame}: {len(ours)} vertices equal to float precision (worst {worst:.1e})")


main(sys.argv[1], sys.argv[2])
