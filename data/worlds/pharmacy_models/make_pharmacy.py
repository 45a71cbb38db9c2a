#!/usr/bin/env python3
"""Writes data/worlds/pharmacy.world: a neighbourhood pharmacy, 10 m x 8 m (the shop floor in the
south with the entrance, security gates and baskets, health aisles of display shelves in the west,
beauty stands in the east and waiting chairs on the east wall; the dispensary in the north-west
behind the long pharmacy counter with its till, computer and label printer: medicine shelves on the
north wall, a step stool, the locked medicine cabinet over the safe, the pharmacy fridge; the
consultation room in the north-east behind a partition: desk, two chairs, blood pressure monitor,
sink and sharps bin) for measuring the semantic stack on a world nobody tuned on. Every model is
inline (boxes, cylinders, spheres), so the world needs no model path. Model names are what a world
author would type; the class is the name less its _<number>. The primitives and the SDF writing
are the office generator's.
Run: python3 data/worlds/pharmacy_models/make_pharmacy.py > data/worlds/pharmacy.world"""

import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
sys.path.insert(0, os.path.join(HERE, "..", "ward_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document)
from make_ward import turned, sink  # noqa: E402  (rotated visuals, the pedestal sink)

W, D, H = 10.0, 8.0, 2.8   # room width (x), depth (y), wall height
T = 0.1                    # wall thickness
EX0, EX1 = 4.0, 5.0        # the entrance's opening in the south wall
CX, CY = 7.0, 5.0          # the consultation room: x CX..W, y CY..D
CD0, CD1 = 8.0, 8.9        # its doorway in the partition y = CY

base.COL.update({
    "tile": "0.86 0.87 0.85", "melamine": "0.93 0.93 0.9", "pharmacy_green": "0.1 0.55 0.35",
    "till_grey": "0.3 0.32 0.34", "fridge_white": "0.96 0.96 0.97", "safe_grey": "0.4 0.42 0.43",
    "cabinet_white": "0.9 0.91 0.9", "shelf_white": "0.92 0.92 0.9", "box_blue": "0.25 0.45 0.75",
    "box_red": "0.8 0.2 0.2", "box_yellow": "0.92 0.8 0.25", "box_green": "0.35 0.65 0.4",
    "cosmetic_pink": "0.9 0.6 0.7", "mirror": "0.8 0.85 0.9", "lipstick": "0.7 0.1 0.2",
    "basket_red": "0.8 0.1 0.12", "gate_grey": "0.7 0.72 0.74", "sharps_yellow": "0.95 0.8 0.1",
    "lid_red": "0.8 0.1 0.1", "chair_blue": "0.2 0.35 0.6", "cuff_blue": "0.2 0.3 0.55",
    "step_grey": "0.55 0.57 0.6",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
PRODUCTS = ("box_blue", "box_red", "box_yellow", "box_green", "white")


# ---- the things (local frames: x right, y forward, z up; -y is the front unless said) ----
def pharmacy_counter(length=5.0):
    # the dispensary counter: a closed melamine front towards the shop (-y), a wooden top
    return [box("body", "melamine", 0, 0, 0.5, length, 0.6, 1.0),
            box("top", "light_wood", 0, 0, 1.02, length + 0.1, 0.7, 0.04),
            box("front_band", "pharmacy_green", 0, -0.305, 0.8, length, 0.01, 0.12),
            box("plinth", "dark_metal", 0, -0.02, 0.04, length - 0.04, 0.56, 0.08)]


def cash_register():
    # sits on the counter top; the customer display faces the shop (-y)
    return [box("base", "till_grey", 0, 0, 0.05, 0.38, 0.36, 0.1),
            box("drawer", "black", 0, -0.01, 0.02, 0.36, 0.34, 0.04),
            box("keypad", "black", 0, 0.06, 0.11, 0.26, 0.14, 0.02),
            box("screen", "black", 0, -0.08, 0.22, 0.24, 0.03, 0.16),
            box("customer_display", "till_grey", 0, -0.16, 0.17, 0.14, 0.02, 0.06)]


def label_printer():
    return [box("body", "white", 0, 0, 0.08, 0.18, 0.24, 0.16),
            box("slot", "black", 0, 0.121, 0.1, 0.1, 0.002, 0.01),
            box("lid", "grey_plastic", 0, -0.02, 0.165, 0.18, 0.18, 0.01)]


def medicine_shelf(width=1.2, depth=0.4, height=2.1):
    # tall dispensary shelving against the wall behind it (+y), packs of medicine on every shelf
    v = [box("back", "shelf_white", 0, depth / 2 - 0.01, height / 2, width, 0.02, height),
         box("side_l", "shelf_white", -width / 2 + 0.01, 0, height / 2, 0.02, depth, height),
         box("side_r", "shelf_white", width / 2 - 0.01, 0, height / 2, 0.02, depth, height)]
    for i in range(6):
        z = 0.1 + 0.38 * i
        v.append(box(f"shelf{i}", "shelf_white", 0, 0, z, width - 0.04, depth, 0.02))
        if i < 5:
            v += [box(f"pack{i}_{k}", PRODUCTS[(i + k) % 5], -0.45 + 0.18 * k, 0.0, z + 0.08,
                      0.12, 0.2, 0.14) for k in range(6)]
    return v


def medicine_cabinet():
    # a locked wall cabinet, the wall behind it (+y); hung by its pose's z
    return [box("body", "cabinet_white", 0, 0, 0, 0.9, 0.3, 0.8),
            box("door_l", "cabinet_white", -0.225, -0.155, 0, 0.44, 0.01, 0.78),
            box("door_r", "cabinet_white", 0.225, -0.155, 0, 0.44, 0.01, 0.78),
            box("cross", "pharmacy_green", 0, -0.162, 0.2, 0.16, 0.004, 0.05),
            box("cross_v", "pharmacy_green", 0, -0.162, 0.2, 0.05, 0.004, 0.16),
            box("lock", "metal", 0, -0.165, -0.1, 0.04, 0.02, 0.06)]


def pharmacy_fridge():
    # an upright glass-door fridge for vaccines and insulin
    return [box("body", "fridge_white", 0, 0, 0.9, 0.6, 0.6, 1.8),
            box("glass_door", "glass", 0, -0.305, 0.95, 0.5, 0.01, 1.5),
            box("handle", "metal", 0.22, -0.33, 1.0, 0.02, 0.03, 0.5),
            box("display", "black", 0, -0.305, 1.75, 0.2, 0.01, 0.06)]


def safe():
    return [box("body", "safe_grey", 0, 0, 0.27, 0.5, 0.5, 0.54),
            box("door", "safe_grey", 0, -0.255, 0.27, 0.44, 0.01, 0.48),
            turned(cyl("dial", "black", 0.1, -0.27, 0.32, 0.04, 0.02), "1.5708 0 0"),
            box("handle", "metal", -0.1, -0.27, 0.27, 0.03, 0.03, 0.12)]


def step_stool():
    # a two-step stool for the high shelves, the steps rising towards +y
    return [box("step_low", "step_grey", 0, -0.1, 0.22, 0.45, 0.2, 0.03),
            box("step_high", "step_grey", 0, 0.1, 0.45, 0.45, 0.2, 0.03),
            box("side_l", "step_grey", -0.21, 0, 0.22, 0.03, 0.4, 0.45),
            box("side_r", "step_grey", 0.21, 0, 0.22, 0.03, 0.4, 0.45)]


def display_shelf(length=2.4, depth=0.8, height=1.6):
    # a double-sided shop gondola along its local x, products on both faces
    v = [box("spine", "shelf_white", 0, 0, height / 2, length, 0.04, height),
         box("base", "dark_metal", 0, 0, 0.06, length, depth, 0.12),
         box("header", "pharmacy_green", 0, 0, height + 0.08, length, 0.06, 0.16)]
    for i in range(4):
        z = 0.3 + 0.35 * i
        for s in (-1, 1):
            v.append(box(f"shelf{i}_{s + 1}", "shelf_white", 0, s * depth / 4, z, length, depth / 2 - 0.04, 0.02))
            v += [box(f"item{i}_{s + 1}_{k}", PRODUCTS[(i + k + s) % 5], -1.0 + 0.25 * k,
                      s * depth / 4, z + 0.09, 0.16, 0.22, 0.16) for k in range(9)]
    return v


def cosmetics_stand():
    # a free-standing beauty display: tiered trays of lipsticks and bottles, a mirror on top
    v = [box("body", "white", 0, 0, 0.45, 1.0, 0.5, 0.9),
         box("tier1", "cosmetic_pink", 0, -0.05, 0.95, 0.95, 0.35, 0.08),
         box("tier2", "cosmetic_pink", 0, 0.08, 1.08, 0.95, 0.22, 0.08),
         box("mirror", "mirror", 0, 0.2, 1.45, 0.6, 0.02, 0.5),
         box("mirror_frame", "black", 0, 0.215, 1.45, 0.64, 0.01, 0.54)]
    v += [cyl(f"lipstick{k}", "lipstick", -0.4 + 0.1 * k, -0.1, 1.02, 0.012, 0.06) for k in range(9)]
    v += [cyl(f"bottle{k}", "glass", -0.4 + 0.1 * k, 0.08, 1.16, 0.02, 0.09) for k in range(9)]
    return v


def shopping_basket():
    # a stack of plastic hand baskets
    v = [box("tub", "basket_red", 0, 0, 0.13 + 0.07 * k, 0.45, 0.32, 0.24) for k in range(3)]
    return v + [box("handle", "black", 0, 0, 0.42, 0.03, 0.3, 0.03)]


def security_gate():
    # an anti-theft pedestal at the entrance, its panel along local y
    return [box("base", "gate_grey", 0, 0, 0.025, 0.12, 0.45, 0.05),
            box("panel", "gate_grey", 0, 0, 0.8, 0.04, 0.4, 1.5),
            box("light_strip", "white", 0, 0, 1.52, 0.05, 0.4, 0.04)]


def trash_can():
    return [cyl("body", "dark_metal", 0, 0, 0.35, 0.18, 0.7),
            cyl("rim", "black", 0, 0, 0.71, 0.19, 0.02)]


def chair():
    # a plain four-legged chair, the back at +y: whoever sits faces -y
    return [box("seat", "chair_blue", 0, 0, 0.46, 0.46, 0.44, 0.05),
            box("back", "chair_blue", 0, 0.2, 0.78, 0.44, 0.04, 0.6)] + legs("metal", 0.2, 0.19, 0.44, 0.03)


def blood_pressure_monitor():
    # sits on the desk: the unit with its screen and the cuff beside it
    return [box("unit", "white", 0, 0, 0.04, 0.16, 0.12, 0.08),
            box("screen", "black", 0, -0.061, 0.05, 0.1, 0.002, 0.05),
            box("cuff", "cuff_blue", 0.16, 0, 0.02, 0.14, 0.22, 0.04),
            turned(cyl("tube", "black", 0.08, 0.02, 0.05, 0.005, 0.08), "0 1.5708 0")]


def sharps_bin():
    # a yellow box with a red lid on a wall bracket, the wall behind it (+y); hung by its pose's z
    return [box("body", "sharps_yellow", 0, 0, 0, 0.22, 0.16, 0.28),
            box("lid", "lid_red", 0, 0, 0.15, 0.23, 0.17, 0.03),
            box("bracket", "dark_metal", 0, 0.085, -0.05, 0.18, 0.01, 0.2)]


def walls():
    v, wall = base.wall_builder(H, T)
    # outer walls; the entrance in the south wall
    wall(0, 0, EX0, 0); wall(EX1, 0, W, 0); wall(EX0, 0, EX1, 0, 2.2, H)
    wall(0, D, W, D); wall(0, 0, 0, D); wall(W, 0, W, D)
    # the consultation room's partitions with its doorway
    wall(CX, CY, CX, D, c="partition")
    wall(CX, CY, CD0, CY, c="partition"); wall(CD1, CY, W, CY, c="partition")
    wall(CD0, CY, CD1, CY, 2.1, H, c="partition")
    return v


def main():
    out = base.shell(walls(), "floor_tiles", "tile", W, D, H)
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    # the entrance: the door swung open inside against the wall, gates either side, baskets, a bin
    add("door_1", (EX1 - 0.02, T / 2 + 0.47, 0, 1.5708), base.door())
    add("security_gate_1", (EX0 - 0.15, 1.2, 0, 0), security_gate())
    add("security_gate_2", (EX1 + 0.25, 1.2, 0, 0), security_gate())
    add("shopping_basket", (EX0 - 0.6, 0.4, 0, 0), shopping_basket())
    add("trash_can", (EX1 + 0.75, 0.35, 0, 0), trash_can())
    add("window_1", (2.0, T / 2 + 0.02, 1.5, 0), base.window())
    add("window_2", (7.6, T / 2 + 0.02, 1.5, 0), base.window())
    # the health aisles in the west: three gondolas running north-south
    for i, x in enumerate((0.75, 2.0, 3.25), 1):
        add(f"display_shelf_{i}", (x, 2.9, 0, 1.5708), display_shelf())
    # the beauty stands in the east half of the shop floor, the waiting chairs on the east wall
    add("cosmetics_stand_1", (6.2, 2.6, 0, 0), cosmetics_stand())
    add("cosmetics_stand_2", (7.6, 0.9, 0, 3.1416), cosmetics_stand())
    for i, y in enumerate((1.6, 2.3, 3.0), 1):
        add(f"chair_{i}", (W - T / 2 - 0.3, y, 0, -1.5708), chair())
    # the dispensary: the counter, things on it, the shelving and the locked stores behind it
    add("pharmacy_counter", (3.5, 5.3, 0, 0), pharmacy_counter())
    top = 1.04
    add("computer_monitor", (2.0, 5.4, top, 3.1416), base.monitor())  # faces the staff (+y)
    add("label_printer", (2.6, 5.4, top, 0), label_printer())
    add("cash_register", (4.8, 5.3, top, 0), cash_register())
    ys = D - T / 2 - 0.2
    for i, x in enumerate((1.0, 2.3, 3.6), 1):
        add(f"medicine_shelf_{i}", (x, ys, 0, 0), medicine_shelf())
    add("step_stool", (2.95, 7.1, 0, 0), step_stool())
    add("medicine_cabinet", (5.0, D - T / 2 - 0.15, 1.6, 0), medicine_cabinet())
    add("safe", (5.0, D - T / 2 - 0.27, 0, 0), safe())
    add("pharmacy_fridge", (6.3, D - T / 2 - 0.32, 0, 0), pharmacy_fridge())
    # the consultation room: its door swung in, desk against the north wall, sink on the east wall
    add("door_2", (CD1 - 0.02, CY + T / 2 + 0.47, 0, 1.5708), base.door())
    add("desk", (8.4, D - T / 2 - 0.37, 0, 0), base.desk())
    add("blood_pressure_monitor", (8.0, D - T / 2 - 0.37, 0.75, 0), blood_pressure_monitor())
    add("chair_4", (8.4, 6.85, 0, 3.1416), chair())
    add("chair_5", (7.5, 6.0, 0, 2.3), chair())
    add("sink", (W - T / 2 - 0.22, 5.75, 0, 1.5708), sink())
    add("sharps_bin", (W - T / 2 - 0.09, 6.35, 1.1, -1.5708), sharps_bin())
    add("window_3", (W - T / 2 - 0.02, 7.0, 1.5, 1.5708), base.window())
    lights = [base.point_light(name, x, y, 2.6, "0.8 0.8 0.78")
              for name, x, y in (("light_aisles", 2.0, 2.8), ("light_beauty", 7.0, 2.2),
                                 ("light_dispensary", 3.5, 6.6), ("light_consultation", 8.5, 6.5))]
    print(base.world_sdf("semsplat_pharmacy", """The semsplat pharmacy: a neighbourhood pharmacy, 10 m x 8 m (the shop floor with the
     health aisles, beauty stands and waiting chairs; the dispensary behind the pharmacy counter
     with medicine shelves, the medicine cabinet, safe and pharmacy fridge; the consultation room
     in the north-east) for measuring on a world nobody tuned on. Generated by
     pharmacy_models/make_pharmacy.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
