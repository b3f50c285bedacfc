# A run's ParaView output ([effects] paraview) is what ParaView reads and says what the run
# did: grains.pvd lists every frame at its time, each frame_NNNN.vtp is VTK XML poly data with
# one point per grain and every array that long, its awake grains are stats.csv's, a grain's
# bonds pair up (each bond counts at both grains), the sticky pile ends bonded, and the grains
# falling in the first frames move down.
# Usage: check_paraview.py RUN FRAMES FPS
import csv
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

run, frames, fps = Path(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3])


def fail(why):
    sys.exit(f"{run}: {why}")


collection = ET.parse(run / "grains.pvd").getroot()
if collection.get("type") != "Collection":
    fail("grains.pvd is not a VTK collection")
datasets = collection.findall("./Collection/DataSet")
if len(datasets) != frames:
    fail(f"grains.pvd lists {len(datasets)} frames, not {frames}")
with open(run / "stats.csv") as f:
    awake_by_frame = {int(row["frame"]): int(row["awake"]) for row in csv.DictReader(f)}

falling, bonded_at_end = 0, 0
for k, dataset in enumerate(datasets, start=1):
    if abs(float(dataset.get("timestep")) - k / fps) > 1e-9:
        fail(f"frame {k} is at {dataset.get('timestep')} s, not {k / fps}")
    piece = ET.parse(run / dataset.get("file")).getroot().find("./PolyData/Piece")
    n = int(piece.get("NumberOfPoints"))
    arrays = {a.get("Name"): [float(x) for x in a.text.split()] for a in piece.iter("DataArray")}
    for name, components in (("centre", 3), ("velocity", 3), ("awake", 1), ("bonds", 1), ("grain", 1),
                             ("in_scene", 1), ("connectivity", 1), ("offsets", 1)):
        if len(arrays.get(name, [])) != components * n:
            fail(f"frame {k}: {name} has {len(arrays.get(name, []))} values for {n} grains")
    if sum(arrays["awake"]) != awake_by_frame[k]:
        fail(f"frame {k}: {sum(arrays['awake'])} grains awake, stats.csv says {awake_by_frame[k]}")
    if sum(arrays["bonds"]) % 2:
        fail(f"frame {k}: the grains' bond counts do not pair up")
    if k <= 3:
        falling += sum(1 for g in range(n) if arrays["in_scene"][g] and arrays["velocity"][3 * g + 2] < -0.1)
    bonded_at_end = sum(1 for b in arrays["bonds"] if b > 0)
if falling == 0:
    fail("no grain in the scene falls in the first three frames")
if bonded_at_end == 0:
    fail("no grain is bonded at the end of a sticky pour")
print(f"{run}: {frames} frames for ParaView; {bonded_at_end} grains bonded at the end")
