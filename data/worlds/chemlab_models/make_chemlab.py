#!/usr/bin/env python3
"""Writes data/worlds/chemlab.world: a university chemistry teaching laboratory of 12 m x 9 m (four
island lab benches with stools and bunsen burners in the middle, three fume cupboards along the
north wall, two sinks under the west windows, the safety corner in the north-west with the safety
shower and the eyewash station, the fire extinguisher, fire blanket and first aid kit by the
entrance in the south-west, the demonstration bench in front of the whiteboard on the east
wall; a prep room in the north-east behind a partition, with a bench carrying the analytical
balance, the centrifuge and the drying oven, the chemical cabinet, glassware cabinet, fridge, a
sink and the gas cylinders) for measuring the semantic stack on a world nobody tuned on. Every
model is inline (boxes, cylinders, spheres), so the world needs no model path. Model names are
what a world author would type; the class is the name less its _<number>. The primitives and the
SDF writing are the office generator's.
Run: python3 data/worlds/chemlab_models/make_chemlab.py > data/worlds/chemlab.world"""

import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
sys.path.insert(0, os.path.join(HERE, "..", "ward_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document)
from make_ward import turned  # noqa: E402  (rotated visuals)

W, D, H = 12.0, 9.0, 3.0   # room width (x), depth (y), wall height
T = 0.1                    # wall thickness
PX, PY = 8.5, 5.5          # the prep room: x PX..W, y PY..D
EX0, EX1 = 1.0, 1.9        # the entrance in the south wall
PD0, PD1 = 6.2, 7.1        # the prep room's doorway in its west partition (x = PX)

base.COL.update({
    "lab_floor": "0.55 0.6 0.58", "resin": "0.12 0.13 0.14", "bench_grey": "0.7 0.72 0.74",
    "steel": "0.76 0.78 0.8", "stool_blue": "0.2 0.3 0.55", "fume_white": "0.9 0.9 0.88",
    "sash": "0.7 0.82 0.88", "brass": "0.75 0.6 0.3", "safety_green": "0.1 0.6 0.3",
    "safety_yellow": "0.95 0.8 0.1", "fire_red": "0.8 0.1 0.08", "ceramic": "0.96 0.96 0.97",
    "flammable_yellow": "0.95 0.75 0.1", "gas_grey": "0.45 0.48 0.5", "gas_black": "0.1 0.1 0.1",
    "poster": "0.85 0.88 0.8", "appliance": "0.95 0.95 0.94", "flame_blue": "0.3 0.45 0.9",
    "bin_grey": "0.4 0.42 0.42",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs


# ---- the things (local frames: x right, y forward, z up) ----
def lab_bench(length=2.4, depth=1.2):
    # an island bench: a black resin top on grey cupboards, a reagent shelf along its middle
    return [box("top", "resin", 0, 0, 0.9, length, depth, 0.04),
            box("cupboards", "bench_grey", 0, 0, 0.44, length - 0.1, depth - 0.1, 0.84),
            box("plinth", "dark_metal", 0, 0, 0.03, length - 0.14, depth - 0.14, 0.06),
            box("reagent_shelf", "light_wood", 0, 0, 1.25, length - 0.3, 0.22, 0.03),
            box("shelf_post_l", "steel", -(length / 2 - 0.2), 0, 1.08, 0.04, 0.04, 0.32),
            box("shelf_post_r", "steel", length / 2 - 0.2, 0, 1.08, 0.04, 0.04, 0.32)]


def wall_bench(length=2.4, depth=0.7):
    # the same bench against a wall (the prep room's), no shelf
    return [box("top", "resin", 0, 0, 0.9, length, depth, 0.04),
            box("cupboards", "bench_grey", 0, 0, 0.44, length - 0.05, depth - 0.05, 0.84)]


def lab_stool():
    return [cyl("seat", "stool_blue", 0, 0, 0.66, 0.17, 0.05),
            cyl("column", "steel", 0, 0, 0.35, 0.025, 0.6),
            cyl("ring", "steel", 0, 0, 0.25, 0.16, 0.02),
            cyl("base", "dark_metal", 0, 0, 0.02, 0.22, 0.03)]


def bunsen_burner():
    # sits on the bench top; the gas hose runs to the tap towards +y
    return [cyl("base", "dark_metal", 0, 0, 0.01, 0.045, 0.02),
            cyl("barrel", "brass", 0, 0, 0.08, 0.01, 0.13),
            cyl("collar", "brass", 0, 0, 0.04, 0.014, 0.02),
            turned(cyl("hose", "fire_red", 0, 0.08, 0.02, 0.006, 0.16), "1.5708 0 0")]


def fume_cupboard():
    # a cupboard-sized hood standing on the floor: base cabinet, work chamber behind the glass
    # sash (the open front is at -y), the extract duct up to the ceiling
    return [box("base_cabinet", "bench_grey", 0, 0, 0.42, 1.5, 0.85, 0.84),
            box("work_top", "resin", 0, 0, 0.86, 1.5, 0.85, 0.04),
            box("back", "fume_white", 0, 0.4, 1.55, 1.5, 0.05, 1.35),
            box("side_l", "fume_white", -0.72, 0, 1.55, 0.06, 0.85, 1.35),
            box("side_r", "fume_white", 0.72, 0, 1.55, 0.06, 0.85, 1.35),
            box("hood", "fume_white", 0, 0, 2.3, 1.5, 0.85, 0.2),
            box("sash", "sash", 0, -0.4, 1.55, 1.38, 0.02, 0.7),
            box("sash_handle", "steel", 0, -0.42, 1.2, 1.2, 0.03, 0.03),
            box("airflow_gauge", "safety_green", 0.6, -0.42, 2.0, 0.1, 0.02, 0.1),
            cyl("duct", "steel", 0, 0.1, 2.7, 0.15, 0.6)]


def sink():
    # a lab sink on its own cupboard, the tap goose-neck high for filling flasks
    return [box("cupboard", "bench_grey", 0, 0, 0.44, 0.8, 0.6, 0.84),
            box("top", "resin", 0, 0, 0.88, 0.8, 0.6, 0.04),
            box("bowl", "ceramic", 0, 0.02, 0.86, 0.5, 0.4, 0.05),
            cyl("tap", "steel", 0, 0.24, 1.05, 0.015, 0.32),
            turned(cyl("spout", "steel", 0, 0.16, 1.2, 0.012, 0.16), "1.5708 0 0")]


def safety_shower():
    # a drench shower: a green pipe up to the shower head, a pull handle hanging down
    return [box("floor_plate", "dark_metal", 0, 0, 0.01, 0.6, 0.6, 0.02),
            cyl("riser", "safety_green", 0, -0.25, 1.15, 0.03, 2.3),
            box("arm", "safety_green", 0, -0.05, 2.3, 0.05, 0.45, 0.05),
            cyl("head", "safety_yellow", 0, 0.15, 2.22, 0.15, 0.08),
            cyl("pull_rod", "steel", 0.12, 0.05, 1.85, 0.008, 0.8),
            box("pull_handle", "safety_yellow", 0.12, 0.05, 1.42, 0.12, 0.02, 0.08),
            box("sign", "safety_green", 0, -0.28, 2.6, 0.3, 0.01, 0.2)]


def eyewash_station():
    # wall-mounted (the wall behind, -y): a bowl with two yellow nozzles and a push flag
    return [box("bracket", "steel", 0, -0.05, 1.0, 0.15, 0.05, 0.25),
            cyl("bowl", "safety_yellow", 0, 0.12, 1.0, 0.16, 0.08),
            cyl("nozzle_l", "safety_green", -0.05, 0.12, 1.08, 0.015, 0.06),
            cyl("nozzle_r", "safety_green", 0.05, 0.12, 1.08, 0.015, 0.06),
            box("push_flag", "safety_yellow", 0.2, 0.12, 1.0, 0.08, 0.02, 0.12),
            cyl("drain", "steel", 0, 0.12, 0.6, 0.02, 0.7),
            box("sign", "safety_green", 0, -0.06, 1.55, 0.3, 0.01, 0.3)]


def fire_extinguisher():
    # hung on a wall bracket (wall behind, -y)
    return [cyl("body", "fire_red", 0, 0.1, 0.7, 0.08, 0.55),
            cyl("valve", "black", 0, 0.1, 1.02, 0.025, 0.1),
            box("lever", "black", 0, 0.1, 1.08, 0.03, 0.12, 0.02),
            turned(cyl("hose", "black", 0.07, 0.1, 0.85, 0.01, 0.3), "0 0.2 0"),
            box("bracket", "steel", 0, 0.01, 0.75, 0.1, 0.02, 0.3)]


def fire_blanket():
    # a red wall pouch with two pull tapes hanging below it
    return [box("pouch", "fire_red", 0, 0.03, 1.5, 0.3, 0.06, 0.3),
            box("tape_l", "white", -0.06, 0.065, 1.3, 0.03, 0.005, 0.12),
            box("tape_r", "white", 0.06, 0.065, 1.3, 0.03, 0.005, 0.12)]


def first_aid_kit():
    # a green wall box with a white cross on its door
    return [box("box", "safety_green", 0, 0.06, 1.45, 0.4, 0.12, 0.3),
            box("cross_v", "white", 0, 0.121, 1.45, 0.05, 0.004, 0.18),
            box("cross_h", "white", 0, 0.121, 1.45, 0.18, 0.004, 0.05)]


def waste_bin():
    return [cyl("body", "bin_grey", 0, 0, 0.35, 0.2, 0.7),
            cyl("lid", "black", 0, 0, 0.71, 0.205, 0.03)]


def whiteboard():
    # wall-mounted: its face looks along -y
    return [box("frame", "metal", 0, 0, 1.5, 2.4, 0.03, 1.2),
            box("board", "white", 0, -0.016, 1.5, 2.32, 0.004, 1.12),
            box("tray", "metal", 0, -0.04, 0.88, 2.2, 0.06, 0.02)]


def periodic_table():
    # the wall chart of the elements: a poster with rows of coloured blocks (face along -y)
    v = [box("poster", "poster", 0, 0, 1.6, 1.6, 0.01, 1.0)]
    rows = ((0.35, 18), (0.2, 18), (0.05, 18), (-0.1, 18), (-0.25, 14))
    cols = ("safety_yellow", "sash", "flame_blue", "safety_green", "fire_red")
    for r, (z, n) in enumerate(rows):
        v.append(box(f"row{r}", cols[r], 0, -0.008, 1.6 + z, 0.08 * n, 0.004, 0.11))
    return v


def demonstration_bench(length=3.0, depth=0.9):
    # the lecturer's bench at the front: a long top on a solid front panel, a sink at one end,
    # the lecturer stands behind it (+y, the whiteboard side)
    return [box("top", "resin", 0, 0, 0.92, length, depth, 0.05),
            box("front_panel", "light_wood", 0, -depth / 2 + 0.03, 0.45, length, 0.05, 0.9),
            box("cupboards", "bench_grey", 0, 0.05, 0.45, length - 0.1, depth - 0.15, 0.86),
            box("basin", "ceramic", length / 2 - 0.35, 0.1, 0.93, 0.4, 0.35, 0.02),
            cyl("tap", "steel", length / 2 - 0.35, 0.35, 1.1, 0.012, 0.3)]


def chemical_cabinet():
    # a yellow flammables safety cabinet, two doors (front at -y)
    return [box("body", "flammable_yellow", 0, 0, 0.9, 1.1, 0.5, 1.8),
            box("seam", "black", 0, -0.252, 0.9, 0.01, 0.005, 1.75),
            box("handle_l", "black", -0.08, -0.26, 1.0, 0.02, 0.02, 0.2),
            box("handle_r", "black", 0.08, -0.26, 1.0, 0.02, 0.02, 0.2),
            box("label", "fire_red", 0, -0.253, 1.55, 0.5, 0.005, 0.15),
            box("sump", "dark_metal", 0, 0, 0.04, 1.08, 0.48, 0.08)]


def glassware_cabinet():
    # tall, with glass doors and shelves of flasks behind them (front at -y)
    v = [box("back", "bench_grey", 0, 0.2, 1.0, 1.0, 0.04, 2.0),
         box("side_l", "bench_grey", -0.48, 0, 1.0, 0.04, 0.42, 2.0),
         box("side_r", "bench_grey", 0.48, 0, 1.0, 0.04, 0.42, 2.0),
         box("top", "bench_grey", 0, 0, 1.99, 1.0, 0.42, 0.03),
         box("doors", "glass", 0, -0.2, 1.0, 0.92, 0.01, 1.95)]
    for i in range(4):
        z = 0.1 + 0.48 * i
        v.append(box(f"shelf{i}", "bench_grey", 0, 0, z, 0.92, 0.38, 0.02))
        v += [cyl(f"flask{i}_{k}", "sash", -0.3 + 0.2 * k, 0, z + 0.09, 0.05, 0.16) for k in range(4)]
    return v


def fridge():
    # a tall white lab fridge with a "no food" sign (front at -y)
    return [box("body", "appliance", 0, 0, 0.9, 0.6, 0.65, 1.8),
            box("door_seam", "grey_plastic", 0, -0.326, 1.2, 0.58, 0.005, 0.01),
            box("handle", "steel", 0.24, -0.34, 1.1, 0.03, 0.03, 0.5),
            box("sign", "fire_red", 0, -0.327, 1.5, 0.25, 0.004, 0.15)]


def gas_cylinder(c="gas_grey"):
    return [cyl("body", c, 0, 0, 0.7, 0.11, 1.4),
            sph("shoulder", c, 0, 0, 1.4, 0.11),
            cyl("valve", "brass", 0, 0, 1.55, 0.03, 0.12),
            box("regulator", "steel", 0.05, 0, 1.6, 0.08, 0.05, 0.08)]


def analytical_balance():
    # on the bench: a weighing chamber with glass draft shield, display at the front (-y)
    return [box("base", "white", 0, 0, 0.04, 0.25, 0.38, 0.08),
            box("chamber", "glass", 0, 0.03, 0.2, 0.22, 0.24, 0.24),
            box("display", "black", 0, -0.16, 0.06, 0.16, 0.02, 0.05),
            cyl("pan", "steel", 0, 0.03, 0.1, 0.045, 0.005)]


def centrifuge():
    # a benchtop centrifuge: a round drum with a lid and a control panel at the front (-y)
    return [box("body", "white", 0, 0, 0.15, 0.45, 0.55, 0.3),
            cyl("lid", "grey_plastic", 0, 0.03, 0.31, 0.19, 0.02),
            box("panel", "dark_metal", 0, -0.26, 0.15, 0.35, 0.02, 0.12)]


def drying_oven():
    # a benchtop oven with a steel door and a dial (front at -y)
    return [box("body", "appliance", 0, 0, 0.3, 0.65, 0.55, 0.6),
            box("door", "steel", -0.05, -0.28, 0.3, 0.5, 0.02, 0.5),
            cyl("dial", "black", 0.26, -0.28, 0.45, 0.03, 0.02),
            box("vent", "dark_metal", 0, 0, 0.61, 0.2, 0.2, 0.02)]


def walls():
    v, wall = base.wall_builder(H, T)
    # outer walls; the entrance in the south wall
    wall(0, 0, EX0, 0); wall(EX1, 0, W, 0); wall(EX0, 0, EX1, 0, 2.1, H)
    wall(0, D, W, D); wall(0, 0, 0, D); wall(W, 0, W, D)
    # the prep room's partitions: its doorway in the west one
    wall(PX, PY, PX, PD0, c="partition"); wall(PX, PD1, PX, D, c="partition")
    wall(PX, PD0, PX, PD1, 2.1, H, c="partition")
    wall(PX, PY, W, PY, c="partition")
    return v


def teaching_lab(add):
    # four island benches in two rows, each with two stools along both long sides and two burners
    benches = [(2.4, 2.6), (5.6, 2.6), (2.4, 5.0), (5.6, 5.0)]
    s = 0
    for i, (x, y) in enumerate(benches, 1):
        add(f"lab_bench_{i}", (x, y, 0, 0), lab_bench())
        add(f"bunsen_burner_{2 * i - 1}", (x - 0.6, y - 0.3, 0.92, 0), bunsen_burner())
        add(f"bunsen_burner_{2 * i}", (x + 0.6, y + 0.3, 0.92, 3.1416), bunsen_burner())
        for dx, dy in ((-0.6, -0.85), (0.6, -0.85), (-0.6, 0.85), (0.6, 0.85)):
            s += 1
            add(f"lab_stool_{s}", (x + dx, y + dy, 0, 0), lab_stool())
    # three fume cupboards along the north wall, fronts facing south
    for i, x in enumerate((1.8, 3.9, 6.0), 1):
        add(f"fume_cupboard_{i}", (x, D - T / 2 - 0.45, 0, 0), fume_cupboard())
    # sinks under the two west windows (fronts facing east), a bin between them
    for i, y in enumerate((3.0, 5.4), 1):
        add(f"sink_{i}", (T / 2 + 0.32, y, 0, 1.5708), sink())
        add(f"window_{i}", (T / 2 + 0.02, y, 1.7, 1.5708), base.window())
    add("waste_bin_1", (0.3, 4.2, 0, 0), waste_bin())
    # the safety corner (north-west): the drench shower and the eyewash on the west wall beside it
    add("safety_shower", (0.45, D - 0.45, 0, -1.5708), safety_shower())
    add("eyewash_station", (T / 2, 7.2, 0, -1.5708), eyewash_station())
    # by the entrance (south-west): first aid, fire extinguisher and blanket
    add("door_1", (EX0 + 0.04, 0.47, 0, 1.5708), base.door())  # hinged at x 1.0, swung open
    add("first_aid_kit", (T / 2, 1.6, 0, -1.5708), first_aid_kit())
    add("fire_extinguisher", (2.3, T / 2, 0, 0), fire_extinguisher())
    add("fire_blanket", (2.8, T / 2, 0, 0), fire_blanket())
    add("waste_bin_2", (3.4, 0.3, 0, 0), waste_bin())
    add("periodic_table", (5.8, T / 2 + 0.02, 0, 3.1416), periodic_table())
    add("window_3", (8.8, T / 2 + 0.02, 1.7, 0), base.window())
    # the front (east wall, south of the prep room): whiteboard and the demonstration bench
    add("whiteboard", (W - T / 2 - 0.02, 2.8, 0, -1.5708), whiteboard())
    add("demonstration_bench", (10.4, 2.8, 0, -1.5708), demonstration_bench())


def prep_room(add):
    # the bench along the north wall carries the balance, the centrifuge and the oven
    yb = D - T / 2 - 0.36
    add("lab_bench_5", (10.3, yb, 0, 3.1416), wall_bench())
    add("analytical_balance", (9.5, yb, 0.92, 3.1416), analytical_balance())
    add("centrifuge", (10.3, yb, 0.92, 3.1416), centrifuge())
    add("drying_oven", (11.15, yb, 0.92, 3.1416), drying_oven())
    # east wall: the chemical cabinet and the fridge (fronts facing west)
    add("chemical_cabinet", (W - T / 2 - 0.26, 7.4, 0, -1.5708), chemical_cabinet())
    add("fridge", (W - T / 2 - 0.34, 6.5, 0, -1.5708), fridge())
    # beside the doorway, against the partition: the glassware cabinet (front facing east)
    add("glassware_cabinet", (PX + T / 2 + 0.22, 7.9, 0, 1.5708), glassware_cabinet())
    # along the south partition: the prep room's sink and the gas cylinders chained by the wall
    add("sink_3", (9.4, PY + T / 2 + 0.31, 0, 3.1416), sink())
    add("waste_bin_3", (10.15, PY + 0.3, 0, 0), waste_bin())
    add("gas_cylinder_1", (W - 0.4, PY + 0.2, 0, 0), gas_cylinder("gas_grey"))
    add("gas_cylinder_2", (W - 0.4, PY + 0.5, 0, 0), gas_cylinder("gas_black"))
    add("door_2", (PX + 0.47, PD1 - 0.04, 0, 0), base.door())  # hinged at y 7.1, swung in


def main():
    out = base.shell(walls(), "floor_lab", "lab_floor", W, D, H)
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    teaching_lab(add)
    prep_room(add)
    lights = [base.point_light(name, x, y, 2.8, "0.78 0.78 0.76")
              for name, x, y in (("light_benches_s", 4.0, 2.6), ("light_benches_n", 4.0, 5.6),
                                 ("light_front", 10.2, 2.8), ("light_prep", 10.2, 7.2))]
    print(base.world_sdf("semsplat_chemlab", """The semsplat chemistry lab: a university chemistry teaching laboratory of 12 m x 9 m
     (four island lab benches with stools and bunsen burners, three fume cupboards on the north
     wall, sinks under the west windows, the safety shower and eyewash in the north-west, fire and
     first aid by the entrance, the demonstration bench and whiteboard on the east wall; a prep
     room in the north-east with the balance, centrifuge, drying oven, chemical and glassware
     cabinets, a fridge, a sink and the gas cylinders) for measuring on a world nobody tuned on.
     Generated by chemlab_models/make_chemlab.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
