#!/usr/bin/env python3
"""Writes data/worlds/garage.world: a home garage with a workshop, 8 m x 7 m (the car parked in the
west half behind the closed garage door in the south wall, bicycles, the lawn mower and a gas can
along the west wall, shelving with storage bins in the north-west; the workshop on the east wall:
workbench with a vise and a pegboard, tool chest, drill press, table saw, air compressor, shop
vacuum; a utility corner in the north-east with the water heater and a chest freezer, the door
into the house in the north wall) for measuring the semantic stack on a world nobody tuned on.
Every model is inline (boxes, cylinders, spheres), so the world needs no model path. Model names
are what a world author would type; the class is the name less its _<number>. The primitives and
the SDF writing are the office generator's.
Run: python3 data/worlds/garage_models/make_garage.py > data/worlds/garage.world"""

import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
sys.path.insert(0, os.path.join(HERE, "..", "ward_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document)
from make_ward import turned, wheel, castors  # noqa: E402  (rotated visuals, wheels, castors)

W, D, H = 8.0, 7.0, 2.6    # room width (x), depth (y), wall height
T = 0.1                    # wall thickness
GX0, GX1, GH = 0.8, 3.8, 2.2   # the garage door's opening in the south wall
HX0, HX1 = 4.3, 5.2            # the house door's opening in the north wall

base.COL.update({
    "concrete": "0.58 0.58 0.56", "car_blue": "0.15 0.3 0.6", "tyre": "0.08 0.08 0.08",
    "chrome": "0.8 0.82 0.85", "headlight": "0.95 0.95 0.85", "bike_red": "0.75 0.12 0.1",
    "mower_green": "0.2 0.5 0.2", "fuel_red": "0.85 0.15 0.1", "hardboard": "0.7 0.55 0.38",
    "tool_red": "0.7 0.08 0.08", "steel": "0.72 0.74 0.76", "cast_iron": "0.25 0.3 0.32",
    "compressor_yellow": "0.92 0.75 0.1", "vac_yellow": "0.95 0.8 0.2", "tote_blue": "0.3 0.5 0.8",
    "tote_clear": "0.82 0.85 0.88", "ladder_alu": "0.78 0.8 0.82", "can_grey": "0.35 0.38 0.36",
    "door_panel": "0.92 0.92 0.9", "appliance": "0.95 0.95 0.94", "copper": "0.72 0.45 0.2",
    "yellow_handle": "0.9 0.75 0.15",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs


# ---- the things (local frames: x right, y forward, z up) ----
def car():
    # a small hatchback, nose at +y
    v = [box("body", "car_blue", 0, 0, 0.55, 1.75, 4.1, 0.6),
         box("cabin", "car_blue", 0, -0.35, 1.12, 1.55, 2.2, 0.55),
         box("windscreen", "glass", 0, 0.76, 1.12, 1.45, 0.02, 0.45),
         box("rear_window", "glass", 0, -1.46, 1.12, 1.45, 0.02, 0.45),
         box("side_windows_l", "glass", -0.78, -0.35, 1.14, 0.02, 2.0, 0.4),
         box("side_windows_r", "glass", 0.78, -0.35, 1.14, 0.02, 2.0, 0.4),
         box("bumper_front", "black", 0, 2.07, 0.38, 1.75, 0.06, 0.16),
         box("bumper_rear", "black", 0, -2.07, 0.38, 1.75, 0.06, 0.16),
         sph("headlight_l", "headlight", -0.6, 2.03, 0.62, 0.08),
         sph("headlight_r", "headlight", 0.6, 2.03, 0.62, 0.08)]
    return v + [wheel(f"wheel{i}", "tyre", sx * 0.8, sy * 1.3, 0.32, 0.32, 0.22)
                for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]


def bicycle():
    # standing on its wheels, length along y
    return [wheel("wheel_front", "tyre", 0, 0.52, 0.34, 0.34, 0.04),
            wheel("wheel_rear", "tyre", 0, -0.52, 0.34, 0.34, 0.04),
            turned(box("top_tube", "bike_red", 0, 0, 0.8, 0.04, 0.62, 0.04), "0.15 0 0"),
            turned(box("down_tube", "bike_red", 0, 0.15, 0.58, 0.04, 0.78, 0.04), "0.75 0 0"),
            box("seat_tube", "bike_red", 0, -0.22, 0.6, 0.04, 0.04, 0.55),
            box("chainstay", "bike_red", 0, -0.37, 0.34, 0.04, 0.32, 0.03),
            box("fork", "chrome", 0, 0.48, 0.6, 0.03, 0.04, 0.55),
            box("saddle", "black", 0, -0.24, 0.92, 0.12, 0.26, 0.05),
            box("handlebar", "black", 0, 0.42, 0.98, 0.55, 0.03, 0.03)]


def lawn_mower():
    # a push mower, the handle towards -y
    return [box("deck", "mower_green", 0, 0, 0.2, 0.5, 0.55, 0.14),
            cyl("engine", "black", 0, 0.05, 0.38, 0.13, 0.22),
            box("grass_bag", "dark_metal", 0, -0.45, 0.3, 0.4, 0.35, 0.3),
            turned(box("handle_l", "steel", -0.22, -0.55, 0.6, 0.025, 0.025, 0.9), "-0.7 0 0"),
            turned(box("handle_r", "steel", 0.22, -0.55, 0.6, 0.025, 0.025, 0.9), "-0.7 0 0"),
            box("handle_bar", "black", 0, -0.84, 0.95, 0.46, 0.03, 0.03)] + \
           [wheel(f"wheel{i}", "tyre", sx * 0.27, sy * 0.22, 0.1, 0.1, 0.05)
            for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]


def gas_can():
    return [box("body", "fuel_red", 0, 0, 0.17, 0.18, 0.34, 0.32),
            box("handle", "fuel_red", 0, 0.02, 0.36, 0.03, 0.18, 0.04),
            turned(cyl("spout", "black", 0, 0.16, 0.38, 0.018, 0.14), "-0.6 0 0")]


def shelving_unit(width=1.2, depth=0.45, height=1.8):
    v = [box(f"shelf{i}", "steel", 0, 0, 0.1 + 0.55 * i, width, depth, 0.03) for i in range(4)]
    return v + legs("dark_metal", width / 2 - 0.02, depth / 2 - 0.02, height, 0.035)


def storage_bin(c="tote_blue"):
    return [box("tub", c, 0, 0, 0.16, 0.55, 0.38, 0.3),
            box("lid", "black", 0, 0, 0.32, 0.57, 0.4, 0.03)]


def step_ladder():
    # an open aluminium step ladder: the front rails with steps lean back, the rear legs forward
    v = [turned(box(f"rail{i}", "ladder_alu", s * 0.22, 0.12, 0.72, 0.04, 0.06, 1.5), "-0.17 0 0")
         for i, s in enumerate((-1, 1))]
    v += [turned(box(f"leg{i}", "ladder_alu", s * 0.22, -0.2, 0.7, 0.03, 0.03, 1.45), "0.2 0 0")
          for i, s in enumerate((-1, 1))]
    v += [box(f"step{i}", "ladder_alu", 0, 0.22 - 0.085 * i, 0.3 + 0.35 * i, 0.44, 0.12, 0.03)
          for i in range(4)]
    return v + [box("top_cap", "black", 0, 0.0, 1.44, 0.5, 0.22, 0.05)]


def garbage_can():
    return [cyl("body", "can_grey", 0, 0, 0.46, 0.3, 0.92),
            cyl("lid", "can_grey", 0, 0, 0.95, 0.32, 0.05),
            box("lid_handle", "black", 0, 0, 1.0, 0.18, 0.04, 0.04)]


def water_heater():
    return [cyl("tank", "appliance", 0, 0, 0.78, 0.28, 1.5),
            cyl("top", "grey_plastic", 0, 0, 1.55, 0.26, 0.04),
            cyl("pipe_hot", "copper", -0.1, 0, 2.05, 0.02, 1.0),
            cyl("pipe_cold", "copper", 0.1, 0, 2.05, 0.02, 1.0),
            box("control", "black", 0, 0.28, 0.35, 0.12, 0.03, 0.1)]


def chest_freezer():
    return [box("body", "appliance", 0, 0, 0.42, 1.3, 0.7, 0.84),
            box("lid_seam", "grey_plastic", 0, 0, 0.78, 1.31, 0.71, 0.01),
            box("handle", "grey_plastic", 0, 0.36, 0.74, 0.3, 0.03, 0.04),
            box("plinth", "dark_metal", 0, 0, 0.02, 1.26, 0.66, 0.04)]


def workbench(length=2.0, depth=0.7):
    # a heavy wooden top on four legs, open underneath (the shop vacuum lives there); the front,
    # where one stands, is at -y
    return [box("top", "wood", 0, 0, 0.88, length, depth, 0.06),
            box("apron", "wood", 0, depth / 2 - 0.05, 0.8, length - 0.1, 0.03, 0.1)] + \
        legs("wood", length / 2 - 0.06, depth / 2 - 0.06, 0.85, 0.08)


def bench_vise():
    # sits on the bench top; the jaws open towards -y
    return [box("base", "cast_iron", 0, 0, 0.03, 0.16, 0.2, 0.06),
            box("rear_jaw", "cast_iron", 0, 0.04, 0.12, 0.16, 0.06, 0.12),
            box("front_jaw", "cast_iron", 0, -0.06, 0.12, 0.16, 0.06, 0.12),
            turned(cyl("screw", "steel", 0, -0.14, 0.1, 0.012, 0.12), "1.5708 0 0"),
            box("tommy_bar", "steel", 0, -0.2, 0.1, 0.2, 0.015, 0.015)]


def pegboard():
    # hung on the wall behind it (+y), tools hanging on it
    v = [box("board", "hardboard", 0, 0, 1.55, 2.0, 0.02, 1.0)]
    tools = [("hammer", "wood", -0.8, 0.04, 0.3), ("saw", "steel", -0.5, 0.3, 0.12),
             ("wrench1", "chrome", -0.15, 0.02, 0.22), ("wrench2", "chrome", -0.05, 0.02, 0.26),
             ("screwdriver1", "tool_red", 0.15, 0.02, 0.2), ("screwdriver2", "yellow_handle", 0.25, 0.02, 0.2),
             ("clamp", "cast_iron", 0.6, 0.15, 0.3)]
    v += [box(n, c, x, -0.02, 1.55, w, 0.02, h) for n, c, x, w, h in tools]
    return v


def tool_chest():
    v = [box("body", "tool_red", 0, 0, 0.55, 0.7, 0.46, 0.95),
         box("top", "black", 0, 0, 1.04, 0.72, 0.48, 0.03)]
    v += [box(f"drawer{i}", "chrome", 0, -0.232, 0.2 + 0.16 * i, 0.6, 0.005, 0.02) for i in range(6)]
    return v + castors(0.3, 0.18)


def drill_press():
    # floor-standing: base, column, table, head with the chuck over the table (-y is the front)
    return [box("base", "cast_iron", 0, 0.05, 0.03, 0.4, 0.5, 0.06),
            cyl("column", "steel", 0, 0.15, 0.85, 0.04, 1.6),
            box("table", "cast_iron", 0, -0.05, 0.95, 0.3, 0.3, 0.03),
            box("head", "cast_iron", 0, 0.0, 1.5, 0.25, 0.5, 0.3),
            box("belt_cover", "cast_iron", 0, 0.12, 1.7, 0.25, 0.35, 0.12),
            cyl("chuck", "steel", 0, -0.15, 1.29, 0.03, 0.12),
            box("feed_handle", "steel", 0.18, -0.05, 1.45, 0.2, 0.02, 0.02)]


def table_saw():
    return [box("cabinet", "dark_metal", 0, 0, 0.42, 0.6, 0.55, 0.84),
            box("table", "steel", 0, 0, 0.87, 0.8, 0.7, 0.04),
            turned(cyl("blade", "chrome", 0, 0, 0.9, 0.12, 0.01), "0 1.5708 0"),
            box("fence", "cast_iron", 0.25, 0, 0.92, 0.04, 0.7, 0.06),
            box("switch", "tool_red", 0, -0.29, 0.7, 0.1, 0.03, 0.06)]


def air_compressor():
    # a horizontal tank on wheels with the motor and gauge on top
    return [turned(cyl("tank", "compressor_yellow", 0, 0, 0.3, 0.2, 0.8), "0 1.5708 0"),
            box("motor", "black", 0.1, 0, 0.6, 0.3, 0.25, 0.2),
            cyl("gauge", "white", -0.15, 0, 0.56, 0.04, 0.03),
            box("handle", "black", -0.45, 0, 0.7, 0.03, 0.35, 0.03),
            wheel("wheel_l", "tyre", 0.3, -0.2, 0.1, 0.1, 0.05),
            wheel("wheel_r", "tyre", 0.3, 0.2, 0.1, 0.1, 0.05)]


def shop_vacuum():
    return [cyl("drum", "vac_yellow", 0, 0, 0.3, 0.2, 0.5),
            cyl("head", "black", 0, 0, 0.6, 0.21, 0.12),
            turned(cyl("hose", "black", 0, 0.22, 0.5, 0.025, 0.3), "0.6 0 0")] + castors(0.14, 0.14, 0.03)


def garage_door():
    # the sectional door, closed, filling its opening in the south wall
    w = GX1 - GX0
    v = [box(f"section{i}", "door_panel", 0, 0, 0.28 + 0.55 * i, w, 0.05, 0.54) for i in range(4)]
    return v + [box("handle", "black", 0, 0.04, 0.45, 0.2, 0.03, 0.03),
                box("track_l", "dark_metal", -w / 2 - 0.03, 0.1, GH / 2, 0.05, 0.05, GH),
                box("track_r", "dark_metal", w / 2 + 0.03, 0.1, GH / 2, 0.05, 0.05, GH)]


def walls():
    v, wall = base.wall_builder(H, T)
    # south wall around the garage door's opening; north wall around the house door's
    wall(0, 0, GX0, 0); wall(GX1, 0, W, 0); wall(GX0, 0, GX1, 0, GH, H)
    wall(0, D, HX0, D); wall(HX1, D, W, D); wall(HX0, D, HX1, D, 2.1, H)
    wall(0, 0, 0, D); wall(W, 0, W, D)
    return v


def main():
    out = base.shell(walls(), "floor_garage", "concrete", W, D, H)
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    add("garage_door", ((GX0 + GX1) / 2, T / 2 + 0.03, 0, 0), garage_door())
    # the parking side (west): the car nose-in, bikes, the mower and its fuel along the west wall
    add("car", (2.3, 3.0, 0, 0), car())
    add("bicycle_1", (0.35, 1.6, 0, 0), bicycle())
    add("bicycle_2", (0.7, 2.0, 0, 0), bicycle())
    add("lawn_mower", (0.45, 4.3, 0, 0), lawn_mower())
    add("gas_can", (0.3, 4.95, 0, 0), gas_can())
    add("window_1", (T / 2 + 0.02, 4.0, 1.5, 1.5708), base.window())
    # storage in the north-west: two shelving units with bins, one more bin on the floor, the ladder
    ys = D - T / 2 - 0.25
    for i, x in enumerate((0.75, 2.05), 1):
        add(f"shelving_unit_{i}", (x, ys, 0, 0), shelving_unit())
    bins = [(0.75, 0.115), (0.75, 0.665), (2.05, 0.115), (2.05, 1.215)]
    for i, (x, z) in enumerate(bins, 1):
        add(f"storage_bin_{i}", (x, ys, z, 0), storage_bin("tote_blue" if i % 2 else "tote_clear"))
    add("storage_bin_5", (2.05, ys - 0.55, 0, 0.3), storage_bin("tote_clear"))
    add("step_ladder", (3.05, D - 0.4, 0, 0), step_ladder())
    add("garbage_can", (3.85, D - 0.42, 0, 0), garbage_can())
    # the house door in the north wall, hinged at x 5.2, swung open into the garage
    add("door", (HX1 - 0.02, D - 0.47, 0, 1.5708), base.door())
    # utility corner (north-east)
    add("water_heater", (6.05, D - 0.4, 0, 0), water_heater())
    add("chest_freezer", (7.2, D - 0.45, 0, 0), chest_freezer())
    # the workshop on the east wall: front faces west (yaw -90 degrees turns local -y to -x)
    xe = W - T / 2
    add("workbench", (xe - 0.38, 3.2, 0, -1.5708), workbench())
    add("bench_vise", (xe - 0.62, 3.95, 0.91, -1.5708), bench_vise())
    add("pegboard", (xe - 0.02, 3.2, 0, -1.5708), pegboard())
    add("shop_vacuum", (xe - 0.4, 2.65, 0, 0), shop_vacuum())
    add("tool_chest", (xe - 0.3, 1.5, 0, -1.5708), tool_chest())
    add("drill_press", (xe - 0.35, 5.0, 0, -1.5708), drill_press())
    add("window_2", (xe - 0.02, 5.9, 1.5, 1.5708), base.window())
    add("table_saw", (5.5, 3.2, 0, 0), table_saw())
    add("air_compressor", (5.4, 0.45, 0, 0), air_compressor())
    lights = [base.point_light(name, x, y, 2.4, "0.75 0.75 0.72")
              for name, x, y in (("light_parking", 2.3, 3.0), ("light_storage", 1.5, 5.8),
                                 ("light_workshop", 6.3, 3.2), ("light_utility", 6.3, 6.0))]
    print(base.world_sdf("semsplat_garage", """The semsplat garage: a home garage with a workshop, 8 m x 7 m (the car behind the closed
     garage door, bikes, the mower and shelving in the west; the workbench, pegboard, tool chest,
     drill press, table saw and compressor on the east side; the water heater and a chest freezer
     by the door into the house) for measuring on a world nobody tuned on. Generated by
     garage_models/make_garage.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
