#!/usr/bin/env python3
"""Writes data/worlds/cafe.world: a coffee shop of 9 m x 8 m (the customer area in the south: two
booths under the west windows, four cafe tables with chairs, a lounge corner with two armchairs
and a coffee table in the south-east, a coat rack and a trash bin by the entrance in the south
wall; the service counter across the room at y 4.5-5.2 with bar stools in front of its west end,
the cash register and a pastry case on it and pendant lamps above it; behind it along the north
wall the kitchen side: sink, dishwasher, the back counter with the espresso machine, the coffee
grinder and a microwave on it, the menu board above, a drinks fridge and the staff door) for
measuring the semantic stack on a world nobody tuned on. Every model is inline (boxes,
cylinders, spheres), so the world needs no model path. Model names are what a world author would
type; the class is the name less its _<number>. The primitives, the walls, floor, ceiling and the
SDF writing are the office generator's.
Run: python3 data/worlds/cafe_models/make_cafe.py > data/worlds/cafe.world"""

import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
sys.path.insert(0, os.path.join(HERE, "..", "ward_models"))
import make_office as base  # noqa: E402  (primitives, walls, slabs, lights, the SDF document)
from make_ward import turned  # noqa: E402  (rotated visuals)

W, D, H = 9.0, 8.0, 3.0    # room width (x), depth (y), wall height
T = 0.1                    # wall thickness
EX0, EX1 = 4.0, 4.9        # the entrance's opening in the south wall
SX0, SX1 = 7.3, 8.2        # the staff door's opening in the north wall (to the stock room)
CY = 4.8                   # the service counter's centre line; its customer side faces -y
CX0 = 1.3                  # its west end (the staff pass is west of it), east end at the wall

base.COL.update({
    "tile": "0.55 0.45 0.38", "walnut": "0.4 0.26 0.15", "oak": "0.72 0.55 0.35",
    "bench_leather": "0.45 0.15 0.12", "velvet": "0.2 0.35 0.3", "marble": "0.9 0.89 0.86",
    "counter_front": "0.3 0.22 0.18", "steel": "0.78 0.8 0.82", "chrome": "0.85 0.86 0.88",
    "espresso_red": "0.7 0.1 0.08", "pastry": "0.8 0.55 0.25", "cream": "0.95 0.9 0.8",
    "chalkboard": "0.12 0.14 0.13", "chalk": "0.92 0.92 0.9", "brass": "0.78 0.62 0.3",
    "appliance": "0.95 0.95 0.94", "bean_brown": "0.3 0.18 0.1", "bottle_green": "0.2 0.5 0.3",
    "bottle_orange": "0.9 0.5 0.1", "bulb": "1 0.95 0.8",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs


# ---- the customer side (local frames: x right, y forward, z up; a seat faces +y) ----
def cafe_table():
    # a small round bistro table on one pedestal
    return [cyl("top", "marble", 0, 0, 0.74, 0.35, 0.03),
            cyl("pedestal", "dark_metal", 0, 0, 0.37, 0.035, 0.72),
            cyl("foot", "dark_metal", 0, 0, 0.015, 0.25, 0.03)]


def chair():
    # a wooden bistro chair, the back at -y
    return [box("seat", "oak", 0, 0, 0.45, 0.42, 0.42, 0.04),
            box("back", "oak", 0, -0.19, 0.72, 0.4, 0.03, 0.45)] + legs("oak", 0.18, 0.18, 0.44, 0.035)


def booth():
    # a table against the wall (its long side along x, the wall at -x) between two high-backed
    # benches facing each other
    v = [box("table_top", "walnut", 0.05, 0, 0.74, 1.1, 0.7, 0.04),
         box("table_leg", "dark_metal", 0.3, 0, 0.36, 0.06, 0.06, 0.72),
         box("table_foot", "dark_metal", 0.3, 0, 0.015, 0.4, 0.4, 0.03)]
    for i, s in enumerate((-1, 1)):
        v += [box(f"bench_base{i}", "walnut", 0, s * 0.6, 0.2, 1.3, 0.45, 0.4),
              box(f"bench_seat{i}", "bench_leather", 0, s * 0.6, 0.45, 1.3, 0.47, 0.1),
              box(f"bench_back{i}", "bench_leather", 0, s * 0.8, 0.85, 1.3, 0.1, 0.7)]
    return v


def bar_stool():
    return [cyl("seat", "bench_leather", 0, 0, 0.76, 0.18, 0.06),
            cyl("pole", "chrome", 0, 0, 0.38, 0.025, 0.72),
            cyl("footrest", "chrome", 0, 0, 0.3, 0.16, 0.02),
            cyl("base", "chrome", 0, 0, 0.015, 0.22, 0.03)]


def armchair():
    # an upholstered lounge chair, the back at -y
    return [box("seat", "velvet", 0, 0.03, 0.24, 0.85, 0.75, 0.36),
            box("back", "velvet", 0, -0.32, 0.62, 0.85, 0.16, 0.5),
            box("arm_l", "velvet", -0.36, 0.03, 0.53, 0.13, 0.75, 0.22),
            box("arm_r", "velvet", 0.36, 0.03, 0.53, 0.13, 0.75, 0.22),
            box("cushion", "cream", 0, -0.2, 0.55, 0.4, 0.1, 0.3)]


def coffee_table():
    # low, between the armchairs
    return [box("top", "walnut", 0, 0, 0.42, 0.9, 0.55, 0.04),
            box("shelf", "walnut", 0, 0, 0.12, 0.82, 0.48, 0.02)] + legs("walnut", 0.4, 0.23, 0.4, 0.04)


def coat_rack():
    v = [cyl("base", "dark_metal", 0, 0, 0.02, 0.22, 0.04),
         cyl("pole", "walnut", 0, 0, 0.9, 0.025, 1.75)]
    v += [box(f"hook{i}", "brass", 0.09 * dx, 0.09 * dy, 1.68, 0.16 if dx else 0.02,
              0.16 if dy else 0.02, 0.02) for i, (dx, dy) in enumerate(((1, 0), (-1, 0), (0, 1), (0, -1)))]
    return v + [box("coat", "bench_leather", 0.12, 0, 1.35, 0.08, 0.35, 0.6)]


def trash_bin():
    return [cyl("body", "dark_metal", 0, 0, 0.38, 0.2, 0.76),
            cyl("lid", "black", 0, 0, 0.78, 0.21, 0.04),
            box("flap", "steel", 0, 0.15, 0.7, 0.2, 0.02, 0.12)]


# ---- the counter and behind it (the customer side of the counter is -y) ----
def service_counter(length):
    return [box("body", "counter_front", 0, 0, 0.5, length, 0.62, 1.0),
            box("top", "oak", 0, 0, 1.02, length + 0.04, 0.7, 0.04),
            box("kick", "black", 0, -0.3, 0.05, length, 0.04, 0.1),
            box("foot_rail", "brass", 0, -0.4, 0.22, length, 0.04, 0.04)]


def cash_register():
    # sits on the counter; the screen faces the cashier (+y)
    return [box("base", "black", 0, 0, 0.05, 0.4, 0.4, 0.1),
            box("drawer", "dark_metal", 0, -0.05, 0.02, 0.38, 0.3, 0.04),
            box("neck", "dark_metal", 0, 0.05, 0.15, 0.05, 0.05, 0.12),
            turned(box("screen", "black", 0, 0.05, 0.28, 0.3, 0.02, 0.22), "-0.3 0 0"),
            box("card_reader", "grey_plastic", 0.25, -0.05, 0.04, 0.08, 0.14, 0.08)]


def pastry_case():
    # a glass display case on the counter with two trays of pastries
    v = [box("base", "steel", 0, 0, 0.03, 1.2, 0.6, 0.06),
         box("glass_front", "glass", 0, -0.29, 0.3, 1.2, 0.02, 0.5),
         box("glass_top", "glass", 0, 0, 0.56, 1.2, 0.6, 0.02),
         box("glass_side_l", "glass", -0.59, 0, 0.3, 0.02, 0.6, 0.5),
         box("glass_side_r", "glass", 0.59, 0, 0.3, 0.02, 0.6, 0.5),
         box("shelf", "steel", 0, 0, 0.3, 1.16, 0.56, 0.02)]
    v += [sph(f"pastry{i}", "pastry", -0.45 + 0.18 * (i % 6), -0.08 + 0.16 * (i // 12),
              0.1 + 0.24 * ((i // 6) % 2), 0.06) for i in range(12)]
    return v


def back_counter(length):
    return [box("cabinet", "white", 0, 0, 0.45, length, 0.6, 0.9),
            box("top", "steel", 0, 0, 0.92, length, 0.65, 0.04),
            box("plinth", "black", 0, -0.28, 0.05, length, 0.04, 0.1)]


def espresso_machine():
    # a two-group machine on the back counter, the group heads towards -y (the barista)
    v = [box("body", "espresso_red", 0, 0, 0.24, 0.75, 0.5, 0.48),
         box("front", "chrome", 0, -0.25, 0.3, 0.72, 0.01, 0.25),
         box("cup_tray", "chrome", 0, 0, 0.49, 0.7, 0.45, 0.02),
         box("drip_tray", "chrome", 0, -0.3, 0.06, 0.65, 0.15, 0.03)]
    for i, x in enumerate((-0.18, 0.18)):
        v += [cyl(f"group{i}", "chrome", x, -0.3, 0.3, 0.04, 0.06),
              turned(cyl(f"portafilter{i}", "black", x, -0.38, 0.26, 0.015, 0.14), "1.5708 0 0")]
    v += [cyl("steam_wand", "chrome", 0.33, -0.3, 0.2, 0.008, 0.2),
          cyl("cup1", "white", -0.15, 0.05, 0.54, 0.04, 0.07), cyl("cup2", "white", 0.1, 0.05, 0.54, 0.04, 0.07)]
    return v


def coffee_grinder():
    return [box("base", "black", 0, 0, 0.12, 0.2, 0.28, 0.24),
            box("spout", "chrome", 0, -0.14, 0.16, 0.05, 0.04, 0.04),
            cyl("motor", "black", 0, 0.02, 0.3, 0.08, 0.14),
            cyl("hopper", "glass", 0, 0.02, 0.47, 0.1, 0.2),
            cyl("beans", "bean_brown", 0, 0.02, 0.44, 0.095, 0.12),
            cyl("hopper_lid", "black", 0, 0.02, 0.58, 0.1, 0.02)]


def microwave():
    return [box("body", "appliance", 0, 0, 0.15, 0.5, 0.38, 0.3),
            box("window", "black", -0.06, -0.191, 0.15, 0.3, 0.005, 0.2),
            box("panel", "grey_plastic", 0.18, -0.191, 0.15, 0.1, 0.005, 0.24)]


def drinks_fridge():
    # a tall glass-door fridge of bottled drinks
    v = [box("cabinet", "white", 0, 0, 0.98, 0.7, 0.65, 1.95),
         box("door_glass", "glass", 0, -0.33, 1.02, 0.62, 0.01, 1.65),
         box("handle", "chrome", 0.27, -0.35, 1.05, 0.03, 0.03, 0.6),
         box("header", "espresso_red", 0, -0.33, 1.9, 0.7, 0.01, 0.12)]
    for s in range(4):
        v += [box(f"shelf{s}", "steel", 0, -0.05, 0.35 + 0.4 * s, 0.6, 0.5, 0.015)]
        v += [cyl(f"bottle{s}_{j}", "bottle_green" if (s + j) % 2 else "bottle_orange",
                  -0.22 + 0.11 * j, -0.15, 0.46 + 0.4 * s, 0.03, 0.2) for j in range(5)]
    return v


def dishwasher():
    return [box("body", "steel", 0, 0, 0.43, 0.6, 0.6, 0.86),
            box("panel", "black", 0, -0.301, 0.8, 0.56, 0.005, 0.08),
            box("handle", "chrome", 0, -0.32, 0.7, 0.4, 0.03, 0.02)]


def sink():
    # a sink cabinet with a steel basin and a tall faucet at the back (+y)
    return [box("cabinet", "white", 0, 0, 0.44, 0.8, 0.6, 0.88),
            box("rim", "steel", 0, 0, 0.9, 0.8, 0.62, 0.04),
            box("basin", "dark_metal", 0, -0.02, 0.89, 0.55, 0.4, 0.03),
            cyl("faucet", "chrome", 0, 0.24, 1.08, 0.015, 0.34),
            box("spout", "chrome", 0, 0.16, 1.24, 0.03, 0.18, 0.03)]


def menu_board():
    # a chalkboard on the wall behind it (+y), lines of chalk writing in three columns
    v = [box("frame", "walnut", 0, 0, 0, 2.2, 0.04, 1.0),
         box("board", "chalkboard", 0, -0.021, 0, 2.1, 0.004, 0.9)]
    v += [box(f"line{c}_{r}", "chalk", -0.7 + 0.7 * c, -0.024, 0.3 - 0.15 * r, 0.5, 0.003, 0.04)
          for c in range(3) for r in range(5)]
    return v


def pendant_lamp(drop):
    # hangs from the ceiling: the model stands on the floor, its shade drop metres below the ceiling
    zs = H - drop
    return [cyl("cord", "black", 0, 0, (H + zs) / 2, 0.005, drop),
            cyl("shade", "brass", 0, 0, zs, 0.16, 0.18),
            sph("bulb", "bulb", 0, 0, zs - 0.09, 0.05)]


def walls():
    v, wall = base.wall_builder(H, T)
    # the entrance in the south wall, the staff door in the north wall
    wall(0, 0, EX0, 0); wall(EX1, 0, W, 0); wall(EX0, 0, EX1, 0, 2.1, H)
    wall(0, D, SX0, D); wall(SX1, D, W, D); wall(SX0, D, SX1, D, 2.1, H)
    wall(0, 0, 0, D); wall(W, 0, W, D)
    return v


def main():
    out = base.shell(walls(), "floor_cafe", "tile", W, D, H)
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    # the entrance (hinged at x 4.0, swung open against the wall), the coat rack and bin beside it
    add("door_1", (EX0 + 0.04, 0.47, 0, 1.5708), base.door())
    add("coat_rack", (3.55, 0.35, 0, 0), coat_rack())
    add("trash_bin", (5.25, 0.3, 0, 0), trash_bin())
    add("window_1", (2.2, T / 2 + 0.02, 1.5, 0), base.window())
    add("window_2", (6.8, T / 2 + 0.02, 1.5, 0), base.window())
    # two booths against the west wall, a window above each
    for i, y in enumerate((1.45, 3.25), 1):
        add(f"booth_{i}", (0.75, y, 0, 0), booth())
        add(f"window_{i + 2}", (T / 2 + 0.02, y, 1.6, 1.5708), base.window())
    # four cafe tables with two chairs each, facing across the table (yaw -90: a seat faces +x)
    tables = [(2.6, 1.2), (2.6, 2.9), (5.5, 1.6), (5.5, 3.0)]
    for i, (x, y) in enumerate(tables, 1):
        add(f"cafe_table_{i}", (x, y, 0, 0), cafe_table())
        add(f"chair_{2 * i - 1}", (x - 0.6, y, 0, -1.5708), chair())
        add(f"chair_{2 * i}", (x + 0.6, y, 0, 1.5708), chair())
    # the lounge corner (south-east): two armchairs facing each other over the coffee table
    add("armchair_1", (7.0, 1.4, 0, -1.5708), armchair())
    add("armchair_2", (8.5, 1.4, 0, 1.5708), armchair())
    add("coffee_table", (7.75, 1.4, 0, 0), coffee_table())
    add("potted_plant_1", (1.85, 0.45, 0, 0), base.plant())
    add("potted_plant_2", (8.55, 3.75, 0, 0), base.plant())
    # the service counter, bar stools at its west end, the register and the pastry case on it
    add("service_counter", ((CX0 + W - T / 2) / 2, CY, 0, 0), service_counter(W - T / 2 - CX0))
    for i, x in enumerate((2.2, 2.9, 3.6), 1):
        add(f"bar_stool_{i}", (x, CY - 0.8, 0, 0), bar_stool())
    add("cash_register", (4.7, CY, 1.04, 0), cash_register())
    add("pastry_case", (6.5, CY, 1.04, 0), pastry_case())
    for i, x in enumerate((2.9, 4.7, 6.5), 1):
        add(f"pendant_lamp_{i}", (x, CY, 0, 0), pendant_lamp(0.85))
    # behind the counter, along the north wall (fronts face -y: yaw 0 already)
    yb = D - T / 2 - 0.32
    add("sink", (1.8, yb, 0, 0), sink())
    add("dishwasher", (2.62, yb, 0, 0), dishwasher())
    add("back_counter", (4.2, yb, 0, 0), back_counter(2.5))
    add("espresso_machine", (3.6, yb - 0.03, 0.94, 0), espresso_machine())
    add("coffee_grinder", (4.3, yb, 0.94, 0), coffee_grinder())
    add("microwave", (5.05, yb + 0.05, 0.94, 0), microwave())
    add("menu_board", (4.2, D - T / 2 - 0.02, 2.2, 0), menu_board())
    add("drinks_fridge", (6.1, yb - 0.02, 0, 0), drinks_fridge())
    add("door_2", (SX1 - 0.04, D - 0.47, 0, 1.5708), base.door())  # the staff door, hinged at x 8.2
    lights = [base.point_light(name, x, y, 2.8, "0.78 0.74 0.66")
              for name, x, y in (("light_booths", 1.5, 2.3), ("light_tables", 4.0, 2.2),
                                 ("light_lounge", 7.7, 1.6), ("light_counter", 4.5, 4.4),
                                 ("light_kitchen", 4.5, 6.8))]
    print(base.world_sdf("semsplat_cafe", """The semsplat cafe: a coffee shop of 9 m x 8 m (booths, cafe tables and a lounge corner
     in the south; the service counter with bar stools, the register and a pastry case across the
     middle; sink, dishwasher, the back counter with the espresso machine, grinder and microwave,
     the menu board and a drinks fridge behind it) for measuring on a world nobody tuned on.
     Generated by cafe_models/make_cafe.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
