#!/usr/bin/env python3
"""Writes data/worlds/basement.world: a house basement of 11 m x 8 m with a laundry room and a
home gym (the laundry room walled off in the south-west: washing machine, dryer with the laundry
basket on it and the utility sink under a small window, the ironing board and a drying rack; the
utility and storage corner in the north-west: furnace, water heater, dehumidifier, storage shelves
with cardboard boxes, more boxes under the wooden staircase that climbs along the north wall; the
home gym in the east: treadmill, exercise bike, weight bench beside the dumbbell rack, a yoga mat
in front of the wall mirror, a punching bag hanging from a joist, the walk-out door in the east
wall) for measuring the semantic stack on a world nobody tuned on. Every model is inline (boxes,
cylinders, spheres), so the world needs no model path. Model names are what a world author would
type; the class is the name less its _<number>. The primitives, walls, slabs and the SDF writing
are the office generator's.
Run: python3 data/worlds/basement_models/make_basement.py > data/worlds/basement.world"""

import math
import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
sys.path.insert(0, os.path.join(HERE, "..", "ward_models"))
import make_office as base  # noqa: E402  (primitives, walls, slabs, lights, the SDF document)
from make_ward import turned, wheel, castors  # noqa: E402  (rotated visuals, wheels, castors)

W, D, H = 11.0, 8.0, 2.4   # basement width (x), depth (y), wall height (to the joists)
T = 0.1                    # wall thickness
LX, LY = 4.0, 4.5          # the laundry room: x 0..LX, y 0..LY (partitions at x = LX, y = LY)
LD0, LD1 = 2.9, 3.8        # its doorway in the y = LY partition
ED0, ED1 = 1.0, 1.9        # the walk-out door's opening in the east wall
SX, SY = 4.8, 4.65         # the staircase: centre line x, foot of the first step (climbs to +y)
NSTEP, RISE, RUN = 12, 0.2, 0.27

base.COL.update({
    "concrete": "0.6 0.6 0.58", "block": "0.78 0.78 0.75", "appliance": "0.95 0.95 0.94",
    "steel": "0.74 0.76 0.78", "chrome": "0.82 0.84 0.87", "rubber": "0.08 0.08 0.08",
    "basket_blue": "0.25 0.45 0.8", "cloth": "0.85 0.8 0.7", "towel": "0.3 0.65 0.7",
    "ironing_cover": "0.55 0.7 0.85", "sink_grey": "0.86 0.86 0.84", "bag_red": "0.7 0.1 0.1",
    "mat_purple": "0.5 0.25 0.6", "mirror": "0.85 0.88 0.9", "furnace_grey": "0.55 0.57 0.58",
    "galvanized": "0.68 0.7 0.7", "copper": "0.72 0.45 0.2", "cardboard": "0.66 0.5 0.32",
    "tape": "0.8 0.7 0.5", "riser": "0.93 0.93 0.9", "vinyl_black": "0.1 0.1 0.11",
    "bike_grey": "0.35 0.37 0.4", "door_panel": "0.9 0.9 0.88", "water_blue": "0.35 0.5 0.75",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
ALONG_X = "0 1.5708 0"   # a cylinder's axis turned from z to x
ALONG_Y = "1.5708 0 0"   # ... from z to y


# ---- the things (local frames: x right, y forward, z up; the user stands at -y, so the front of
# an appliance is its -y face; a wall-hung thing has the wall behind it at +y) ----
def front_loader(door_colour):
    # the shared body of the washer and the dryer: a white cabinet, a round door, a control strip
    return [box("body", "appliance", 0, 0, 0.43, 0.6, 0.6, 0.86),
            turned(cyl("door_ring", "grey_plastic", 0, -0.305, 0.42, 0.21, 0.02), ALONG_Y),
            turned(cyl("door", door_colour, 0, -0.315, 0.42, 0.17, 0.01), ALONG_Y),
            box("panel", "grey_plastic", 0, -0.28, 0.8, 0.58, 0.05, 0.1),
            turned(cyl("dial", "chrome", 0.18, -0.31, 0.8, 0.03, 0.02), ALONG_Y)]


def washing_machine():
    return front_loader("glass") + [box("detergent_drawer", "white", -0.18, -0.31, 0.8, 0.15, 0.02, 0.06),
                                    cyl("hose", "grey_plastic", 0.2, 0.36, 0.6, 0.015, 0.8)]


def clothes_dryer():
    return front_loader("sink_grey") + [turned(cyl("vent", "galvanized", 0, 0.4, 0.5, 0.05, 0.2), ALONG_Y)]


def laundry_basket():
    # an open plastic basket with a heap of clothes in it, handles at its ends
    w, d, h, t = 0.55, 0.38, 0.28, 0.015
    return [box("bottom", "basket_blue", 0, 0, t / 2, w, d, t),
            box("side_front", "basket_blue", 0, -d / 2, h / 2, w, t, h),
            box("side_back", "basket_blue", 0, d / 2, h / 2, w, t, h),
            box("side_l", "basket_blue", -w / 2, 0, h / 2, t, d, h),
            box("side_r", "basket_blue", w / 2, 0, h / 2, t, d, h),
            box("clothes", "cloth", 0, 0, 0.2, w - 0.04, d - 0.04, 0.14),
            box("handle_l", "basket_blue", -w / 2 - 0.02, 0, h - 0.03, 0.03, 0.15, 0.03),
            box("handle_r", "basket_blue", w / 2 + 0.02, 0, h - 0.03, 0.03, 0.15, 0.03)]


def ironing_board():
    # the board along x with its pointed end at +x, on crossed legs
    return [box("top", "ironing_cover", -0.1, 0, 0.86, 1.0, 0.36, 0.03),
            cyl("nose", "ironing_cover", 0.4, 0, 0.86, 0.18, 0.03),
            box("iron_rest", "steel", -0.68, 0, 0.86, 0.16, 0.26, 0.02),
            turned(box("leg_a", "steel", 0, -0.12, 0.43, 0.03, 0.03, 0.98), "0 0.55 0"),
            turned(box("leg_b", "steel", 0, 0.12, 0.43, 0.03, 0.03, 0.98), "0 -0.55 0"),
            box("foot_a", "rubber", -0.22, -0.12, 0.015, 0.06, 0.32, 0.03),
            box("foot_b", "rubber", 0.22, 0.12, 0.015, 0.06, 0.32, 0.03)]


def utility_sink():
    # a deep free-standing laundry tub on four legs, the tap on its back rim
    return [box("tub", "sink_grey", 0, 0, 0.72, 0.6, 0.55, 0.36),
            box("basin", "grey_plastic", 0, -0.02, 0.89, 0.5, 0.43, 0.01),
            cyl("tap", "chrome", 0, 0.24, 0.98, 0.015, 0.18),
            box("spout", "chrome", 0, 0.17, 1.06, 0.03, 0.16, 0.03),
            cyl("drain", "grey_plastic", 0, 0, 0.35, 0.025, 0.7)] + legs("sink_grey", 0.26, 0.23, 0.56, 0.05)


def drying_rack():
    # a folding clothes airer: two leaning frames joined at the top, rails between them, a towel
    v = [turned(box(f"leg{i}", "steel", sx * 0.38, sy * 0.16, 0.5, 0.02, 0.02, 1.04), f"{sy * 0.33:g} 0 0")
         for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    v += [box(f"rail{i}_{s}", "steel", 0, s * (0.23 - 0.1 * i), 0.3 + 0.3 * i, 0.78, 0.012, 0.012)
          for i in range(3) for s in (-1, 1)]
    return v + [box("towel", "towel", 0, -0.18, 0.48, 0.5, 0.01, 0.35)]


def treadmill():
    # the belt along y, the console at the front (+y) on two uprights
    return [box("deck", "vinyl_black", 0, 0, 0.1, 0.8, 1.8, 0.16),
            box("belt", "rubber", 0, -0.05, 0.185, 0.55, 1.5, 0.01),
            box("motor_hood", "bike_grey", 0, 0.8, 0.2, 0.8, 0.3, 0.2),
            box("upright_l", "bike_grey", -0.36, 0.85, 0.7, 0.05, 0.07, 1.05),
            box("upright_r", "bike_grey", 0.36, 0.85, 0.7, 0.05, 0.07, 1.05),
            box("rail_l", "vinyl_black", -0.36, 0.6, 1.05, 0.04, 0.5, 0.04),
            box("rail_r", "vinyl_black", 0.36, 0.6, 1.05, 0.04, 0.5, 0.04),
            box("console", "vinyl_black", 0, 0.88, 1.28, 0.75, 0.12, 0.3),
            box("display", "water_blue", 0, 0.81, 1.3, 0.3, 0.01, 0.12)]


def exercise_bike():
    # an upright stationary bike facing +y: flywheel in front, saddle behind
    return [box("stabilizer_front", "bike_grey", 0, 0.42, 0.03, 0.5, 0.07, 0.06),
            box("stabilizer_rear", "bike_grey", 0, -0.42, 0.03, 0.5, 0.07, 0.06),
            box("beam", "bike_grey", 0, 0, 0.08, 0.08, 0.86, 0.06),
            turned(box("down_tube", "bike_grey", 0, 0.15, 0.45, 0.07, 0.07, 0.85), "-0.45 0 0"),
            box("seat_post", "bike_grey", 0, -0.25, 0.55, 0.05, 0.05, 0.6),
            box("saddle", "vinyl_black", 0, -0.27, 0.88, 0.2, 0.28, 0.07),
            wheel("flywheel", "chrome", 0, 0.3, 0.3, 0.23, 0.05),
            box("handle_post", "bike_grey", 0, 0.34, 0.95, 0.05, 0.05, 0.5),
            box("handlebar", "vinyl_black", 0, 0.3, 1.2, 0.5, 0.04, 0.04),
            box("console", "vinyl_black", 0, 0.38, 1.25, 0.2, 0.05, 0.14),
            box("pedal_l", "vinyl_black", -0.12, 0.05, 0.32, 0.1, 0.06, 0.02),
            box("pedal_r", "vinyl_black", 0.12, 0.05, 0.42, 0.1, 0.06, 0.02)]


def weight_bench():
    # a flat padded bench, its length along y, on a steel frame
    return [box("pad", "vinyl_black", 0, 0, 0.44, 0.3, 1.2, 0.08),
            box("frame", "steel", 0, 0, 0.37, 0.1, 1.1, 0.06),
            box("post_front", "steel", 0, 0.45, 0.19, 0.06, 0.06, 0.36),
            box("post_rear", "steel", 0, -0.45, 0.19, 0.06, 0.06, 0.36),
            box("foot_front", "steel", 0, 0.45, 0.02, 0.5, 0.06, 0.04),
            box("foot_rear", "steel", 0, -0.45, 0.02, 0.5, 0.06, 0.04)]


def dumbbell(i, x, z, r):
    return [turned(cyl(f"handle{i}", "chrome", x, 0, z, 0.016, 0.14), ALONG_Y),
            turned(cyl(f"head{i}a", "rubber", x, -0.1, z, r, 0.07), ALONG_Y),
            turned(cyl(f"head{i}b", "rubber", x, 0.1, z, r, 0.07), ALONG_Y)]


def dumbbell_rack():
    # a two-tier steel rack with a row of dumbbells on each tier, lightest on top
    v = [box("tier_low", "steel", 0, 0, 0.42, 1.2, 0.34, 0.03),
         box("tier_high", "steel", 0, 0.05, 0.78, 1.2, 0.3, 0.03)] + legs("steel", 0.57, 0.15, 0.8, 0.05)
    for i in range(5):
        x = -0.48 + 0.24 * i
        v += dumbbell(i, x, 0.5, 0.065 + 0.006 * i) + dumbbell(i + 5, x, 0.84, 0.045 + 0.004 * i)
    return v


def punching_bag():
    # a heavy bag hanging on a chain from a ceiling hook (the model stands on the floor under it)
    return [cyl("bag", "bag_red", 0, 0, 1.25, 0.18, 1.0),
            cyl("bag_top", "vinyl_black", 0, 0, 1.77, 0.17, 0.04),
            cyl("chain", "steel", 0, 0, 2.08, 0.01, 0.58),
            box("ceiling_mount", "dark_metal", 0, 0, H - 0.02, 0.12, 0.12, 0.04)]


def yoga_mat():
    return [box("mat", "mat_purple", 0, 0, 0.004, 0.61, 1.83, 0.008)]


def wall_mirror():
    # a large frameless gym mirror on a backing board; the wall is at +y
    return [box("backing", "black", 0, 0.01, 0, 2.0, 0.015, 1.5),
            box("glass", "mirror", 0, -0.005, 0, 1.96, 0.01, 1.46)]


def furnace():
    # a gas furnace: a cabinet with its front panels, the supply plenum up into the joists, the flue
    return [box("cabinet", "furnace_grey", 0, 0, 0.65, 0.6, 0.75, 1.3),
            box("panel_low", "galvanized", 0, -0.38, 0.35, 0.56, 0.01, 0.6),
            box("panel_high", "galvanized", 0, -0.38, 1.0, 0.56, 0.01, 0.55),
            box("plenum", "galvanized", 0, 0, 1.85, 0.55, 0.65, 1.1),
            box("return_duct", "galvanized", 0.45, 0.1, 0.55, 0.3, 0.4, 1.1),
            cyl("flue", "steel", -0.38, 0, 1.5, 0.06, 1.8),
            box("filter_slot", "black", 0.31, 0.1, 0.2, 0.02, 0.45, 0.04)]


def water_heater():
    return [cyl("tank", "appliance", 0, 0, 0.75, 0.28, 1.5),
            cyl("cap", "water_blue", 0, 0, 1.52, 0.27, 0.04),
            cyl("flue", "steel", 0, 0, 1.98, 0.05, 0.9),
            cyl("pipe_hot", "copper", -0.14, 0, 1.98, 0.015, 0.9),
            cyl("pipe_cold", "copper", 0.14, 0, 1.98, 0.015, 0.9),
            box("burner_door", "black", 0, -0.28, 0.2, 0.14, 0.02, 0.1),
            box("valve", "water_blue", 0, -0.28, 0.4, 0.1, 0.04, 0.08)]


def dehumidifier():
    return [box("body", "appliance", 0, 0, 0.32, 0.36, 0.28, 0.6),
            box("grille", "grey_plastic", 0, 0, 0.625, 0.34, 0.26, 0.01),
            box("tank", "water_blue", 0, -0.145, 0.16, 0.3, 0.01, 0.2),
            box("handle", "grey_plastic", 0, 0.1, 0.65, 0.2, 0.03, 0.03),
            box("panel", "black", 0, -0.145, 0.52, 0.2, 0.01, 0.06)] + castors(0.13, 0.1, 0.02)


def storage_shelf(width=1.2, depth=0.45, height=1.8):
    v = [box(f"shelf{i}", "steel", 0, 0, 0.08 + 0.56 * i, width, depth, 0.025) for i in range(4)]
    return v + legs("dark_metal", width / 2 - 0.02, depth / 2 - 0.02, height, 0.03)


def cardboard_box(sx=0.45, sy=0.35, sz=0.32):
    return [box("carton", "cardboard", 0, 0, sz / 2, sx, sy, sz),
            box("tape", "tape", 0, 0, sz + 0.001, 0.06, sy, 0.004)]


def staircase():
    # a straight wooden stair climbing +y to the floor above (it runs on up through the joists):
    # treads and white risers between two stringers, a handrail on the open east side
    v = []
    for i in range(NSTEP):
        v.append(box(f"riser{i}", "riser", 0, RUN * i, RISE * i + RISE / 2, 0.9, 0.02, RISE))
        v.append(box(f"tread{i}", "wood", 0, RUN * i + RUN / 2, RISE * (i + 1) - 0.02, 0.9, RUN + 0.02, 0.04))
    slope = math.atan2(RISE, RUN)
    length = NSTEP * RUN / math.cos(slope)
    for i, s in enumerate((-1, 1)):
        v.append(turned(box(f"stringer{i}", "wood", s * 0.47, NSTEP * RUN / 2, NSTEP * RISE / 2 - 0.1,
                            0.04, length, 0.25), f"{slope:.4f} 0 0"))
    rail_run = 1.8  # the handrail stops where it meets the joists
    v.append(turned(box("handrail", "wood", 0.5, rail_run / 2 + 0.1, 0.9 + (rail_run / 2 + 0.1) * RISE / RUN,
                        0.05, rail_run / math.cos(slope), 0.05), f"{slope:.4f} 0 0"))
    v += [box(f"baluster{i}", "wood", 0.5, 0.15 + 0.6 * i, RISE * (0.15 + 0.6 * i) / RUN + 0.45, 0.04, 0.04, 0.9)
          for i in range(4)]
    return v


def basement_window():
    # a small high window: frame, pane and the sill of its well
    return [box("frame", "white", 0, 0, 0, 0.9, 0.03, 0.45),
            box("pane", "glass", 0, -0.016, 0, 0.82, 0.004, 0.37),
            box("sill", "white", 0, -0.05, -0.24, 0.92, 0.1, 0.03)]


def exterior_door():
    # the walk-out door, closed in its opening (the office generator's door is an open leaf)
    return [box("leaf", "door_panel", 0, 0, 1.02, 0.88, 0.05, 2.04),
            box("window", "glass", 0, -0.026, 1.55, 0.5, 0.004, 0.6),
            cyl("handle", "chrome", 0.36, -0.05, 1.0, 0.015, 0.08)]


def walls():
    v, wall = base.wall_builder(H, T)
    # the outer walls, concrete block; the walk-out door's opening in the east wall
    wall(0, 0, W, 0, c="block"); wall(0, D, W, D, c="block"); wall(0, 0, 0, D, c="block")
    wall(W, 0, W, ED0, c="block"); wall(W, ED1, W, D, c="block"); wall(W, ED0, W, ED1, 2.1, H, c="block")
    # the laundry room's partitions, its doorway in the north one
    wall(LX, 0, LX, LY, c="partition")
    wall(0, LY, LD0, LY, c="partition"); wall(LD1, LY, LX, LY, c="partition")
    wall(LD0, LY, LD1, LY, 2.1, H, c="partition")
    return v


def main():
    out = base.shell(walls(), "floor_basement", "concrete", W, D, H)
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    # the laundry room (south-west): washer, dryer and sink along the south wall under a window,
    # fronts facing north (yaw 180 degrees turns local -y to +y)
    ys = T / 2 + 0.34
    add("washing_machine", (0.5, ys, 0, 3.1416), washing_machine())
    add("clothes_dryer", (1.15, ys, 0, 3.1416), clothes_dryer())
    add("laundry_basket", (1.15, ys, 0.87, 0.1), laundry_basket())
    add("utility_sink", (2.0, T / 2 + 0.3, 0, 3.1416), utility_sink())
    add("window_1", (0.85, T / 2 + 0.02, 1.85, 3.1416), basement_window())
    add("ironing_board", (0.55, 2.6, 0, 1.5708), ironing_board())
    add("drying_rack", (2.5, 2.7, 0, 0), drying_rack())
    add("door_1", (LD1 - 0.03, LY - 0.47, 0, 1.5708), base.door())  # hinged at x LD1, open inwards
    # the utility and storage corner (north-west): shelves on the west wall (fronts east)
    xs = T / 2 + 0.25
    add("storage_shelf_1", (xs, 5.3, 0, 1.5708), storage_shelf())
    add("storage_shelf_2", (xs, 6.5, 0, 1.5708), storage_shelf())
    add("furnace", (0.7, D - T / 2 - 0.42, 0, 0), furnace())
    add("water_heater", (1.9, D - T / 2 - 0.35, 0, 0), water_heater())
    add("dehumidifier", (3.3, D - T / 2 - 0.25, 0, 0), dehumidifier())
    boxes = [(xs, 5.0, 0.0925, (0.45, 0.35, 0.3)), (xs, 5.55, 0.0925, (0.4, 0.4, 0.35)),
             (xs, 5.3, 0.6525, (0.5, 0.38, 0.3)), (xs, 6.3, 0.6525, (0.45, 0.35, 0.32)),
             (xs, 6.75, 1.2125, (0.4, 0.35, 0.28)), (xs, 6.5, 0.0925, (0.55, 0.38, 0.4))]
    for i, (x, y, z, size) in enumerate(boxes, 1):
        add(f"cardboard_box_{i}", (x, y, z, 1.5708), cardboard_box(*size))
    # two more under the high end of the staircase
    add("cardboard_box_7", (SX, 7.0, 0, 0), cardboard_box(0.55, 0.45, 0.45))
    add("cardboard_box_8", (SX - 0.1, 7.55, 0, 0.2), cardboard_box(0.5, 0.4, 0.5))
    add("staircase", (SX, SY, 0, 0), staircase())
    # the home gym (east): cardio machines along the north wall facing it
    add("treadmill", (6.5, D - T / 2 - 1.05, 0, 0), treadmill())
    add("exercise_bike", (7.9, D - T / 2 - 0.7, 0, 0), exercise_bike())
    # the mirror wall (east): the weight bench beside the dumbbell rack, the yoga mat before the mirror
    xe = W - T / 2
    add("wall_mirror", (xe - 0.02, 3.9, 1.25, -1.5708), wall_mirror())
    add("yoga_mat", (xe - 1.3, 3.9, 0, 1.5708), yoga_mat())
    add("dumbbell_rack", (xe - 0.25, 5.8, 0, -1.5708), dumbbell_rack())
    add("weight_bench", (xe - 1.35, 5.8, 0, 1.5708), weight_bench())
    add("punching_bag", (7.6, 2.3, 0, 0), punching_bag())
    add("door_2", (xe, (ED0 + ED1) / 2, 0, -1.5708), exterior_door())  # the walk-out door, closed
    add("window_2", (6.6, T / 2 + 0.02, 1.85, 3.1416), basement_window())
    add("window_3", (9.2, T / 2 + 0.02, 1.85, 3.1416), basement_window())
    lights = [base.point_light(name, x, y, H - 0.1, "0.75 0.74 0.7")
              for name, x, y in (("light_laundry", 2.0, 2.3), ("light_storage", 2.0, 6.3),
                                 ("light_gym_n", 7.8, 6.0), ("light_gym_s", 8.5, 2.3))]
    print(base.world_sdf("semsplat_basement", """The semsplat basement: a house basement of 11 m x 8 m (the laundry room in
     the south-west, the furnace, water heater, dehumidifier and storage shelves with boxes in the
     north-west beside the staircase, a home gym in the east) for measuring on a world nobody
     tuned on. Generated by basement_models/make_basement.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
