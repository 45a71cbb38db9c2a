#!/usr/bin/env python3
"""Writes data/worlds/warehouse.world: a small robot-operated warehouse (distribution centre) of
20 m x 14 m, 6 m high, in the style of the AWS RoboMaker small warehouse (the loading dock in the
south-east with two roll-up doors, staged pallets of cardboard boxes, a pallet jack and safety cones
in front of them and a personnel door beside them; the packing station in the south-west with two
packing tables, supply shelving and the conveyor belt that runs east toward the dock; three rows of
pallet racking in the middle and a fourth along the east wall, the forklift parked in the wide
aisle between them; a walled site office in the north-west corner with two desks, office chairs,
computers and a filing cabinet; the maintenance corner on the north wall with the workbench, a
ladder and a shelving unit; the break area in the north-east with a table and chairs, a vending
machine, a water cooler and a trash bin; fire extinguishers by the doors) for measuring the
semantic stack on a world nobody tuned on. Every model is inline (boxes, cylinders, spheres), so
the world needs no model path. Model names are what a world author would type; the class is the
name less its _<number>. The primitives and the SDF writing are the office generator's.
Run: python3 data/worlds/warehouse_models/make_warehouse.py > data/worlds/warehouse.world"""

import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
sys.path.insert(0, os.path.join(HERE, "..", "ward_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document, door, window, desk, chair)
from make_ward import turned, wheel, castors  # noqa: E402  (rotated visuals, wheels, castors)

W, D, H = 20.0, 14.0, 6.0  # warehouse width (x), depth (y), wall height
T = 0.1                    # wall thickness
PX0, PX1 = 11.0, 11.9      # the personnel door in the south wall
DOCK = ((13.0, 16.0), (16.6, 19.6))  # the two loading dock openings in the south wall
DOCK_H = 4.0               # their height
OX, OY, OH = 5.0, 10.0, 3.0  # the site office: x < OX, y > OY, its partitions OH high
ODX0, ODX1 = 3.8, 4.7      # the office doorway in its south partition

base.COL.update({
    "concrete": "0.6 0.6 0.58", "rack_blue": "0.12 0.3 0.6", "rack_orange": "0.9 0.45 0.1",
    "pallet_wood": "0.72 0.58 0.38", "cardboard": "0.7 0.52 0.32", "tape": "0.82 0.72 0.55",
    "forklift_yellow": "0.95 0.75 0.1", "rubber": "0.1 0.1 0.1", "steel": "0.7 0.72 0.74",
    "belt": "0.15 0.15 0.16", "roller": "0.78 0.8 0.82", "jack_red": "0.75 0.12 0.1",
    "cone_orange": "1.0 0.4 0.05", "door_grey": "0.66 0.68 0.7", "bench_top": "0.55 0.4 0.25",
    "ladder_alu": "0.8 0.82 0.84", "shelf_grey": "0.5 0.52 0.55", "screen": "0.1 0.12 0.15",
    "vending_red": "0.7 0.1 0.12", "extinguisher_red": "0.85 0.05 0.05", "bin_green": "0.2 0.4 0.25",
    "seat_grey": "0.4 0.42 0.45", "office_wall": "0.88 0.88 0.84", "safety_yellow": "0.95 0.85 0.1",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
BOX_SIZES = ((0.5, 0.4, 0.4), (0.6, 0.4, 0.35), (0.4, 0.4, 0.3))


# ---- the things (local frames: x right, y forward = the side a person faces, z up) ----
def storage_rack(length=2.7, depth=1.1, levels=(1.5, 3.0), top=4.4, loaded=(0, 1, 2, 3, 5)):
    """One bay of selective pallet racking: blue uprights, orange beams at each level, a pallet of
    boxes on the floor and on each beam level (the bays listed in loaded carry goods), open on
    both long sides (the aisle faces are +y and -y)."""
    v = []
    for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1))):
        v.append(box(f"upright{i}", "rack_blue", sx * (length / 2 - 0.04), sy * (depth / 2 - 0.04), top / 2,
                     0.08, 0.08, top))
    for s in (-1, 1):  # the braces between the front and back uprights
        v.append(box(f"brace{s + 1}", "rack_blue", s * (length / 2 - 0.04), 0, top / 2, 0.04, depth - 0.16, 0.04))
    for j, z in enumerate(levels + (top,)):
        for s in (-1, 1):
            v.append(box(f"beam{j}_{s + 1}", "rack_orange", 0, s * (depth / 2 - 0.04), z, length, 0.06, 0.12))
    slots = [(k, z) for z in (0.0,) + levels for k in (-1, 1)]
    for n, (k, z) in enumerate(slots):
        if n not in loaded:
            continue
        x = k * length / 4
        base_z = z + 0.06 if z else 0.0
        v.append(box(f"pallet{n}", "pallet_wood", x, 0, base_z + 0.072, 1.2, 1.0, 0.144))
        for m, (bx, by) in enumerate(((-0.28, -0.22), (0.28, -0.22), (-0.28, 0.22), (0.28, 0.22))):
            sx, sy, sz = BOX_SIZES[(n + m) % 3]
            v.append(box(f"goods{n}_{m}", "cardboard", x + bx, by, base_z + 0.144 + sz / 2, sx * 0.95, sy, sz))
    return v


def pallet():
    """A wooden pallet of 1.2 m x 1.0 m: top deck boards on three stringers and a bottom deck."""
    v = [box(f"deck{i}", "pallet_wood", -0.5 + 0.25 * i, 0, 0.134, 0.14, 1.0, 0.02) for i in range(5)]
    v += [box(f"block{i}", "pallet_wood", 0, -0.45 + 0.45 * i, 0.074, 1.2, 0.1, 0.1) for i in range(3)]
    return v + [box(f"foot{i}", "pallet_wood", -0.5 + 0.5 * i, 0, 0.012, 0.14, 1.0, 0.024) for i in range(3)]


def cardboard_box(size=(0.5, 0.4, 0.4)):
    """A taped shipping carton standing on whatever it was set on (its local z = 0)."""
    sx, sy, sz = size
    return [box("carton", "cardboard", 0, 0, sz / 2, sx, sy, sz),
            box("tape", "tape", 0, 0, sz + 0.001, 0.06, sy + 0.004, 0.002)]


def forklift():
    """A counterbalanced forklift: yellow body and counterweight, overhead guard, the mast and
    forks at +y, two big drive wheels at the front and two steering wheels at the back."""
    v = [box("chassis", "forklift_yellow", 0, -0.2, 0.45, 1.05, 1.7, 0.6),
         box("counterweight", "dark_metal", 0, -1.0, 0.6, 1.05, 0.35, 0.8),
         box("seat", "black", 0, -0.45, 0.95, 0.5, 0.45, 0.12),
         box("seat_back", "black", 0, -0.68, 1.2, 0.5, 0.08, 0.4),
         turned(cyl("steering", "black", 0, 0.05, 1.25, 0.17, 0.03), "-0.6 0 0"),
         cyl("column", "dark_metal", 0, 0.15, 1.0, 0.03, 0.5)]
    for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1))):
        v.append(box(f"guard_post{i}", "dark_metal", sx * 0.47, -0.75 + 0.8 * (sy + 1) / 2, 1.5, 0.06, 0.06, 1.5))
    v.append(box("guard_roof", "dark_metal", 0, -0.35, 2.22, 1.0, 0.9, 0.06))
    v += [box(f"mast{s + 1}", "dark_metal", s * 0.35, 0.75, 1.2, 0.1, 0.12, 2.3) for s in (-1, 1)]
    v += [box("carriage", "dark_metal", 0, 0.84, 0.45, 0.9, 0.06, 0.5),
          box("backrest", "dark_metal", 0, 0.84, 1.0, 0.9, 0.03, 0.6)]
    v += [box(f"fork{s + 1}", "steel", s * 0.3, 1.42, 0.06, 0.12, 1.1, 0.05) for s in (-1, 1)]
    v += [wheel(f"drive_wheel{s + 1}", "rubber", s * 0.46, 0.45, 0.3, 0.3, 0.22) for s in (-1, 1)]
    v += [wheel(f"steer_wheel{s + 1}", "rubber", s * 0.4, -0.85, 0.22, 0.22, 0.18) for s in (-1, 1)]
    return v + [sph("beacon", "cone_orange", 0, -0.7, 2.3, 0.06)]


def pallet_jack():
    """A manual pallet jack: two forks toward +y, the hydraulic unit and the tiller handle at -y."""
    v = [box(f"fork{s + 1}", "jack_red", s * 0.2, 0.25, 0.05, 0.16, 1.15, 0.07) for s in (-1, 1)]
    v += [box("yoke", "jack_red", 0, -0.35, 0.12, 0.55, 0.12, 0.2),
          cyl("pump", "jack_red", 0, -0.45, 0.35, 0.07, 0.4),
          turned(cyl("tiller", "dark_metal", 0, -0.6, 0.75, 0.02, 0.8), "-0.35 0 0"),
          box("grip", "black", 0, -0.74, 1.12, 0.32, 0.04, 0.05),
          wheel("steer_wheel", "rubber", 0, -0.45, 0.09, 0.09, 0.08)]
    return v + [wheel(f"load_roller{s + 1}", "rubber", s * 0.2, 0.75, 0.04, 0.035, 0.08) for s in (-1, 1)]


def roll_up_door(width=3.0, height=DOCK_H, opened=0.0):
    """A dock's roll-up door on the inside face of the wall (its back at -y): the drum housing over
    the opening, guides on both sides and the curtain of slats down to height * opened from the
    floor (0 closed, 1 all the way up: then only the drum and the bottom bar show)."""
    z0 = height * opened
    v = [turned(cyl("drum", "door_grey", 0, 0.27, height + 0.3, 0.25, width + 0.2), "0 1.5708 0"),
         box("guide_l", "dark_metal", -width / 2 - 0.06, 0.04, height / 2, 0.1, 0.08, height),
         box("guide_r", "dark_metal", width / 2 + 0.06, 0.04, height / 2, 0.1, 0.08, height),
         box("bottom_bar", "rubber", 0, 0.04, z0 + 0.03, width, 0.06, 0.06)]
    n = int(round((height - z0) / 0.25))
    v += [box(f"slat{i}", "door_grey", 0, 0.03, z0 + 0.06 + 0.25 * i + 0.12, width, 0.04, 0.23) for i in range(n)]
    return v + [box("stripe", "safety_yellow", 0, 0.075, z0 + 0.09, width, 0.004, 0.06)]


def conveyor_belt(length=6.0, width=0.7, height=0.85):
    """A belt conveyor running along x on steel legs: side frames flush with the belt, end rollers."""
    v = [box("belt", "belt", 0, 0, height, length, width - 0.08, 0.04),
         box("rail_l", "steel", 0, -width / 2 + 0.02, height - 0.04, length, 0.04, 0.12),
         box("rail_r", "steel", 0, width / 2 - 0.02, height - 0.04, length, 0.04, 0.12)]
    v += [turned(cyl(f"roller{s + 1}", "roller", s * length / 2, 0, height - 0.08, 0.06, width - 0.08), "1.5708 0 0")
          for s in (-1, 1)]
    for i in range(4):
        x = -length / 2 + 0.2 + i * (length - 0.4) / 3
        v += [box(f"leg{i}_{s + 1}", "steel", x, s * (width / 2 - 0.04), (height - 0.02) / 2, 0.06, 0.06, height - 0.02)
              for s in (-1, 1)]
    return v + [box("motor", "dark_metal", length / 2 - 0.3, -width / 2 - 0.12, height - 0.2, 0.3, 0.2, 0.2)]


def packing_table(length=1.8, depth=0.9):
    """A packing bench: a wide top with a cutting mat, and on the lower shelf flattened cartons,
    a roll of bubble wrap, the tape dispenser and the label printer."""
    v = [box("top", "bench_top", 0, 0, 0.88, length, depth, 0.04),
         box("mat", "bin_green", -0.2, 0.05, 0.901, 0.9, 0.6, 0.002),
         box("shelf", "light_wood", 0, 0, 0.25, length - 0.1, depth - 0.1, 0.03),
         box("flat_cartons", "cardboard", 0.35, 0, 0.3, 0.8, 0.6, 0.08),
         turned(cyl("wrap_roll", "white", -0.5, 0, 0.39, 0.12, 0.6), "0 1.5708 0"),
         box("tape_dispenser", "jack_red", 0.55, 0.15, 0.39, 0.1, 0.3, 0.1),
         box("label_printer", "grey_plastic", 0.2, -0.15, 0.42, 0.2, 0.25, 0.16)]
    return v + legs("steel", length / 2 - 0.05, depth / 2 - 0.05, 0.86, 0.05)


def workbench(length=2.0, depth=0.8):
    """A heavy maintenance workbench against a wall (at -y): a thick top, a pegboard of tools behind
    it, a vice on the front edge and a drawer unit underneath."""
    v = [box("top", "bench_top", 0, 0, 0.9, length, depth, 0.06),
         box("drawers", "shelf_grey", 0.6, 0, 0.45, 0.6, depth - 0.1, 0.8),
         box("pegboard", "light_wood", 0, -depth / 2 + 0.02, 1.5, length, 0.02, 1.0),
         box("vice", "rack_blue", -0.7, depth / 2 - 0.1, 1.0, 0.2, 0.2, 0.14)]
    v += [box(f"tool{i}", "dark_metal", -0.7 + 0.35 * i, -depth / 2 + 0.05, 1.5, 0.04, 0.02, 0.3) for i in range(5)]
    v += [box(f"drawer{i}", "dark_metal", 0.6, depth / 2 - 0.04, 0.2 + 0.22 * i, 0.2, 0.02, 0.02) for i in range(3)]
    return v + legs("dark_metal", length / 2 - 0.04, depth / 2 - 0.04, 0.87, 0.06)


def shelving_unit(length=1.2, depth=0.5, height=2.0):
    """A grey steel shelving unit of five shelves with totes and rolls of stretch film, against a
    wall behind it (-y)."""
    v = [box(f"post{i}", "shelf_grey", sx * (length / 2 - 0.02), sy * (depth / 2 - 0.02), height / 2, 0.04, 0.04, height)
         for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    for i in range(5):
        z = 0.1 + 0.45 * i
        v.append(box(f"shelf{i}", "shelf_grey", 0, 0, z, length, depth, 0.02))
        if i < 4:
            v += [box(f"tote{i}_{k}", ("rack_blue", "cardboard", "grey_plastic")[(i + k) % 3], -0.38 + 0.38 * k, 0,
                      z + 0.13, 0.32, 0.4, 0.24) for k in range(3)]
    return v


def ladder(height=2.6, lean=0.3):
    """An aluminium straight ladder leaning on the wall behind it (-y): two rails and the rungs,
    tilted back by lean radians, its feet on rubber pads."""
    dy = height / 2 * lean  # how far the middle of the ladder leans back
    v = [turned(box(f"rail{s + 1}", "ladder_alu", s * 0.22, -dy, height / 2, 0.04, 0.08, height), f"{lean} 0 0")
         for s in (-1, 1)]
    for i in range(8):
        h = 0.3 + 0.3 * i
        v.append(box(f"rung{i}", "ladder_alu", 0, -h * lean, h, 0.44, 0.03, 0.03))
    return v + [box(f"pad{s + 1}", "rubber", s * 0.22, 0, 0.02, 0.08, 0.12, 0.04) for s in (-1, 1)]


def computer():
    """A desktop computer set on a desk (its local z = the desk top): monitor, keyboard, mouse and
    the tower beside the monitor."""
    return [box("monitor", "black", 0, 0.15, 0.28, 0.55, 0.04, 0.34),
            box("picture", "screen", 0, 0.128, 0.28, 0.51, 0.004, 0.3),
            box("monitor_stand", "dark_metal", 0, 0.18, 0.06, 0.15, 0.15, 0.12),
            box("keyboard", "black", 0, -0.12, 0.015, 0.44, 0.14, 0.03),
            box("mouse", "grey_plastic", 0.32, -0.12, 0.015, 0.06, 0.1, 0.03),
            box("tower", "black", -0.45, 0.1, 0.22, 0.2, 0.42, 0.44)]


def office_chair():
    """A swivel office chair on five castors (the office generator's shape, a bit taller)."""
    v = [cyl("base", "dark_metal", 0, 0, 0.06, 0.3, 0.03), cyl("column", "dark_metal", 0, 0, 0.27, 0.03, 0.4),
         box("seat", "fabric", 0, 0, 0.48, 0.48, 0.46, 0.08),
         box("back", "fabric", 0, -0.23, 0.8, 0.46, 0.06, 0.56)]
    return v + castors(0.22, 0.22, 0.03)


def filing_cabinet():
    """A four-drawer steel filing cabinet, the drawers at +y."""
    v = [box("body", "metal", 0, 0, 0.66, 0.47, 0.62, 1.32)]
    return v + [box(f"handle{i}", "dark_metal", 0, 0.32, 0.2 + 0.32 * i, 0.12, 0.02, 0.02) for i in range(4)]


def table(length=1.6, depth=0.8):
    """A plain break-room table on steel legs."""
    return [box("top", "white", 0, 0, 0.74, length, depth, 0.03)] + \
        legs("steel", length / 2 - 0.06, depth / 2 - 0.06, 0.73, 0.04)


def chair():
    """A stacking chair: plastic seat and back on a steel frame, the seat's front at +y."""
    v = [box("seat", "seat_grey", 0, 0, 0.45, 0.44, 0.42, 0.04),
         box("back", "seat_grey", 0, -0.2, 0.7, 0.42, 0.03, 0.34)]
    return v + legs("steel", 0.19, 0.18, 0.44, 0.025)


def vending_machine():
    """A snack vending machine, the glass front and the keypad at +y."""
    return [box("body", "vending_red", 0, 0, 0.9, 0.9, 0.8, 1.8),
            box("window", "glass", -0.1, 0.401, 1.05, 0.6, 0.004, 1.2),
            box("keypad", "black", 0.33, 0.401, 1.1, 0.14, 0.004, 0.3),
            box("chute", "black", -0.1, 0.401, 0.25, 0.55, 0.004, 0.18)]


def water_cooler():
    """A bottled water cooler: the white cabinet, taps at +y and the blue bottle on top."""
    return [box("body", "white", 0, 0, 0.5, 0.32, 0.32, 1.0),
            box("tap_panel", "grey_plastic", 0, 0.165, 0.85, 0.2, 0.01, 0.12),
            cyl("bottle", "blue_water", 0, 0, 1.2, 0.13, 0.4)]


def fire_extinguisher():
    """A red extinguisher on its wall bracket (the wall at -y), under a sign."""
    return [cyl("cylinder", "extinguisher_red", 0, 0, 0.85, 0.08, 0.5),
            cyl("valve", "black", 0, 0, 1.14, 0.025, 0.08),
            box("hose", "black", 0.07, 0.02, 0.95, 0.02, 0.02, 0.3),
            box("bracket", "dark_metal", 0, -0.08, 0.8, 0.12, 0.04, 0.12),
            box("sign", "extinguisher_red", 0, -0.095, 1.5, 0.25, 0.01, 0.3)]


def trash_bin():
    """A wheeled plastic trash bin with its lid."""
    return [cyl("body", "bin_green", 0, 0, 0.45, 0.28, 0.9), cyl("lid", "bin_green", 0, 0, 0.92, 0.3, 0.04)]


def safety_cone():
    """An orange traffic cone of 0.7 m: a square foot and a stack of shrinking discs."""
    v = [box("foot", "cone_orange", 0, 0, 0.015, 0.38, 0.38, 0.03)]
    for i in range(6):
        c = "white" if i in (3, 4) else "cone_orange"
        v.append(cyl(f"band{i}", c, 0, 0, 0.08 + 0.11 * i, 0.15 - 0.022 * i, 0.11))
    return v


def walls():
    """The outer walls with the personnel door and the two dock openings in the south, and the
    site office's partitions (OH high) in the north-west corner with its doorway."""
    v, wall = base.wall_builder(H, T)
    (a0, a1), (b0, b1) = DOCK
    wall(0, 0, PX0, 0); wall(PX0, 0, PX1, 0, 2.1, H); wall(PX1, 0, a0, 0)
    wall(a0, 0, a1, 0, DOCK_H, H); wall(a1, 0, b0, 0); wall(b0, 0, b1, 0, DOCK_H, H); wall(b1, 0, W, 0)
    wall(0, D, W, D); wall(0, 0, 0, D); wall(W, 0, W, D)
    wall(0, OY, ODX0, OY, 0, OH, "office_wall"); wall(ODX1, OY, OX, OY, 0, OH, "office_wall")
    wall(ODX0, OY, ODX1, OY, 2.1, OH, "office_wall"); wall(OX, OY, OX, D, 0, OH, "office_wall")
    return v


def dock(out):
    """The loading dock (south-east): the roll-up doors, staged pallets, the pallet jack, cones."""
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    (a0, a1), (b0, b1) = DOCK
    add("roll_up_door_1", ((a0 + a1) / 2, T / 2, 0, 0), roll_up_door(a1 - a0, opened=0.0))
    add("roll_up_door_2", ((b0 + b1) / 2, T / 2, 0, 0), roll_up_door(b1 - b0, opened=1.0))
    add("door_1", (PX0 + 0.04, 0.47, 0, 1.5708), base.door())  # the personnel door, swung open inward
    add("fire_extinguisher_1", (10.55, T / 2 + 0.1, 0, 0), fire_extinguisher())
    # staged outbound pallets in front of the doors, boxes stacked on two of them
    add("pallet_1", (14.0, 2.0, 0, 0), pallet())
    add("pallet_2", (15.5, 2.0, 0, 0), pallet())
    add("pallet_3", (18.1, 2.4, 0, 0), pallet())
    n = [0]

    def carton(x, y, z, size, yaw=0.0):
        n[0] += 1
        add(f"cardboard_box_{n[0]}", (x, y, z, yaw), cardboard_box(size))
    for dx, dy in ((-0.28, -0.25), (0.28, -0.25), (-0.28, 0.25), (0.28, 0.25)):
        carton(14.0 + dx, 2.0 + dy, 0.144, (0.5, 0.45, 0.4))
    carton(14.0, 2.0, 0.544, (0.6, 0.45, 0.35))
    carton(18.1 - 0.25, 2.4, 0.144, (0.5, 0.9, 0.5))
    carton(18.1 + 0.3, 2.4, 0.144, (0.4, 0.5, 0.3))
    # an empty stack of three pallets behind the staged ones
    for k in range(3):
        add(f"pallet_{4 + k}", (15.6, 3.5, 0.144 * k, 0), pallet())
    add("pallet_jack", (12.0, 3.8, 0, 3.1416), pallet_jack())  # forks pointing south, to the dock
    add("safety_cone_1", (16.85, 0.9, 0, 0), safety_cone())  # flanking the open dock door
    add("safety_cone_2", (19.35, 0.9, 0, 0), safety_cone())
    add("safety_cone_3", (14.6, 4.0, 0, 0), safety_cone())  # at the end of the forklift aisle
    return n[0]


def packing(out, boxes):
    """The packing station (south-west): packing tables, supply shelving, the conveyor to the dock."""
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    add("packing_table_1", (2.9, 2.4, 0, 3.1416), packing_table())  # packers stand on its south side
    add("packing_table_2", (2.9, 4.6, 0, 3.1416), packing_table())
    add("shelving_unit_1", (T / 2 + 0.27, 2.4, 0, -1.5708), shelving_unit())
    add("shelving_unit_2", (T / 2 + 0.27, 4.6, 0, -1.5708), shelving_unit())
    add("conveyor_belt", (7.2, 2.4, 0, 0), conveyor_belt())
    add("trash_bin_1", (4.35, 3.6, 0, 0), trash_bin())
    n = boxes
    for x, y, z, size in ((2.6, 2.45, 0.9, (0.4, 0.4, 0.3)), (3.1, 4.55, 0.9, (0.5, 0.4, 0.4)),
                          (5.4, 2.4, 0.87, (0.4, 0.4, 0.3)), (8.1, 2.4, 0.87, (0.5, 0.4, 0.35))):
        n += 1
        add(f"cardboard_box_{n}", (x, y, z, 0), cardboard_box(size))


def storage(out):
    """Pallet racking: three free-standing rows of two bays in the middle (their long sides
    along y), a fourth row against the east wall, the forklift in the wide aisle between."""
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    k = 0
    for x in (6.0, 9.6, 13.2, W - T / 2 - 0.56):
        for y, loaded in ((5.55, (0, 1, 2, 3, 5)), (8.25, (0, 2, 3, 4, 5))):
            k += 1
            add(f"storage_rack_{k}", (x, y, 0, 1.5708), storage_rack(loaded=loaded))
    add("forklift", (16.4, 6.8, 0, 3.1416), forklift())  # forks toward the dock (south)


def office(out):
    """The site office (north-west): two desks with computers and chairs, a filing cabinet."""
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    add("door_2", (ODX0 + 0.04, OY + 0.47, 0, 1.5708), base.door())
    add("window_1", (T / 2 + 0.02, 12.2, 1.5, 1.5708), base.window())  # in the west wall
    add("window_2", (1.9, OY + T / 2 + 0.02, 1.5, 0), base.window())  # looking out over the floor
    for i, x in enumerate((1.6, 3.4), 1):
        add(f"desk_{i}", (x, 12.95, 0, 0), base.desk())
        add(f"computer_{i}", (x, 12.95, 0.75, 0), computer())
        add(f"office_chair_{i}", (x, 12.3, 0, 0), office_chair())  # facing the desk (north)
    add("filing_cabinet", (OX - T / 2 - 0.32, 13.3, 0, 1.5708), filing_cabinet())
    add("fire_extinguisher_2", (3.25, OY - T / 2 - 0.1, 0, 3.1416), fire_extinguisher())  # outside, by the door


def maintenance(out):
    """The maintenance corner on the north wall: the workbench, a ladder, a shelving unit."""
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    add("workbench", (8.0, D - T / 2 - 0.41, 0, 3.1416), workbench())
    add("ladder", (10.3, D - T / 2 - 0.82, 0, 3.1416), ladder())  # its top against the wall
    add("shelving_unit_3", (12.0, D - T / 2 - 0.27, 0, 3.1416), shelving_unit())


def break_area(out):
    """The break area (north-east): a table with four chairs, the vending machine, the water
    cooler, a trash bin, a fire extinguisher and a window."""
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    add("table", (16.8, 12.0, 0, 0), table())
    for i, (x, y, yaw) in enumerate(((16.4, 11.35, 0), (17.2, 11.35, 0), (16.4, 12.65, 3.1416),
                                     (17.2, 12.65, 3.1416)), 1):
        add(f"chair_{i}", (x, y, 0, yaw), chair())
    add("vending_machine", (W - T / 2 - 0.41, 11.0, 0, 1.5708), vending_machine())  # facing west
    add("water_cooler", (W - T / 2 - 0.17, 12.7, 0, 1.5708), water_cooler())
    add("trash_bin_2", (15.1, D - T / 2 - 0.35, 0, 0), trash_bin())
    add("fire_extinguisher_3", (14.4, D - T / 2 - 0.1, 0, 3.1416), fire_extinguisher())
    add("window_3", (17.4, D - T / 2 - 0.02, 2.0, 0), base.window())


def main():
    office_roof = base.box("office_ceiling", "white", OX / 2, (OY + D) / 2, OH + 0.01, OX, D - OY, 0.02)
    out = [base.model("walls", (0, 0, 0, 0), walls()),
           base.model("floor", (0, 0, 0, 0), base.floor_slab("floor_warehouse", "concrete", W, D)),
           base.model("ceiling", (0, 0, 0, 0), base.ceiling_slab(W, D, H) + [office_roof])]
    boxes = dock(out)
    packing(out, boxes)
    storage(out)
    office(out)
    maintenance(out)
    break_area(out)
    lights = [base.point_light(name, x, y, z, "0.85 0.85 0.82")
              for name, x, y, z in (("light_dock", 16.0, 2.5, 5.6), ("light_packing", 3.5, 3.5, 5.6),
                                    ("light_racks_w", 7.8, 7.0, 5.6), ("light_racks_e", 14.8, 7.0, 5.6),
                                    ("light_north", 10.0, 12.0, 5.6), ("light_break", 17.0, 12.0, 5.6),
                                    ("light_office", 2.5, 12.0, 2.8))]
    print(base.world_sdf("semsplat_warehouse", """The semsplat warehouse: a small distribution centre of 20 m x 14 m
     after the AWS RoboMaker small warehouse (the loading dock with two roll-up doors, staged
     pallets, a pallet jack and cones in the south-east, the packing station and the conveyor in
     the south-west, four rows of pallet racking with the forklift in the middle, the site office
     in the north-west, the maintenance corner on the north wall, the break area in the
     north-east) for measuring on a world nobody tuned on. Generated by
     warehouse_models/make_warehouse.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
