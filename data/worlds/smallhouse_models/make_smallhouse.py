#!/usr/bin/env python3
"""Writes data/worlds/smallhouse.world: a single-storey suburban small house of 14 m x 10 m in the
manner of the AWS RoboMaker small-house world (the front porch door in the middle of the south
front opening into a hallway; the living room in the south-west with a sectional sofa facing the
TV on its stand, the coffee table, an armchair by the fireplace on the west wall, a bookshelf and a
floor lamp; the kitchen in the north-west, open to the living room, with the refrigerator, a
range, cabinets with the microwave on one, the sink and the dishwasher on the west wall, the
kitchen table with four chairs, a trash can and the back door to the patio; a laundry nook north
of the hallway with a washer and a dryer; a corridor running east to the home office (desk,
office chair, monitor, printer, a wastebasket), the bathroom (toilet, bathtub with a shower, the
vanity sink under a mirror) and the bedroom (queen bed, two nightstands, dresser under a mirror,
wardrobe)) for measuring the semantic stack on a world nobody tuned on. Every model is inline
(boxes, cylinders, spheres), so the world needs no model path. Model names are what a world author
would type; the class is the name less its _<number>. The primitives and the SDF writing are the
office generator's. Run: python3 data/worlds/smallhouse_models/make_smallhouse.py > data/worlds/smallhouse.world"""

import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
sys.path.insert(0, os.path.join(HERE, "..", "ward_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document, door, window, desk)
from make_ward import turned  # noqa: E402  (rotated visuals)

W, D, H = 14.0, 10.0, 2.6  # house width (x), depth (y), wall height
T = 0.1                    # wall thickness
HX0, HX1 = 5.5, 7.5        # the hallway between its walls, x 5.5..7.5, y 0..6.5
FD0, FD1 = 6.05, 6.95      # the front door in the south wall
BD0, BD1 = 4.0, 4.9        # the back door (to the patio) in the kitchen's north wall
KY = 5.5                   # the living room (y < KY) and the kitchen (y > KY), west of the hallway
LY = 6.5                   # the laundry nook north of the hallway (y > LY)
CY0, CY1 = 4.5, 5.5        # the corridor east of the hallway: office and bathroom south, bedroom north
OX = 10.5                  # office (x < OX) and bathroom (x > OX)
UP = 2.1                   # the top of every doorway

base.COL.update({
    "oak_floor": "0.62 0.48 0.33", "sofa_grey": "0.45 0.46 0.5", "cushion": "0.55 0.56 0.6",
    "armchair_fabric": "0.45 0.3 0.22", "brick": "0.55 0.27 0.2", "soot": "0.08 0.07 0.07",
    "stone": "0.7 0.68 0.64", "steel": "0.72 0.73 0.75", "fridge_white": "0.95 0.96 0.97",
    "cabinet_white": "0.93 0.92 0.88", "counter_top": "0.3 0.3 0.32", "hob_black": "0.1 0.1 0.11",
    "screen": "0.1 0.12 0.15", "porcelain": "0.97 0.97 0.98", "mirror": "0.75 0.82 0.88",
    "linen": "0.92 0.9 0.85", "duvet": "0.35 0.45 0.6", "walnut": "0.4 0.27 0.17",
    "book_red": "0.6 0.15 0.12", "book_blue": "0.18 0.28 0.55", "book_green": "0.2 0.45 0.3",
    "glass_door": "0.55 0.65 0.75", "rubber": "0.1 0.1 0.1", "tile": "0.85 0.87 0.88",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
BOOKS = ("book_red", "book_blue", "book_green")


# ---- the things (local frames: x right, y forward = the side a person faces, z up) ----
def sectional_sofa():
    """An L-shaped sectional: a three-seat run facing +y and a chaise on its right running forward."""
    v = [box("base", "sofa_grey", 0, 0, 0.22, 2.6, 0.9, 0.4),
         box("back", "sofa_grey", 0, -0.35, 0.62, 2.6, 0.2, 0.45),
         box("arm_l", "sofa_grey", -1.22, 0, 0.52, 0.16, 0.9, 0.2),
         box("chaise", "sofa_grey", 0.85, 0.9, 0.22, 0.9, 0.9, 0.4),
         box("chaise_arm", "sofa_grey", 1.22, 0.45, 0.52, 0.16, 1.8, 0.2)]
    return v + [box(f"cushion{i}", "cushion", -0.85 + 0.85 * i, 0.05, 0.46, 0.8, 0.75, 0.08) for i in range(3)] \
        + [box("cushion_chaise", "cushion", 0.85, 0.9, 0.46, 0.8, 0.85, 0.08)]


def coffee_table():
    return [box("top", "walnut", 0, 0, 0.42, 1.1, 0.6, 0.04), box("shelf", "walnut", 0, 0, 0.12, 1.0, 0.5, 0.02)] \
        + legs("walnut", 0.5, 0.25, 0.4, 0.05)


def tv_stand():
    """A low media console facing +y: top, two doors and an open middle bay."""
    return [box("body", "walnut", 0, 0, 0.28, 1.6, 0.45, 0.5),
            box("bay", "soot", 0, 0.2, 0.28, 0.5, 0.06, 0.3),
            box("door_l", "wood", -0.55, 0.226, 0.28, 0.48, 0.004, 0.42),
            box("door_r", "wood", 0.55, 0.226, 0.28, 0.48, 0.004, 0.42)] + legs("dark_metal", 0.75, 0.18, 0.03, 0.04)


def television():
    """A flat screen on its foot, standing on the TV stand, the picture looking along +y."""
    return [box("foot", "dark_metal", 0, 0, 0.01, 0.4, 0.22, 0.02),
            box("neck", "dark_metal", 0, -0.02, 0.08, 0.08, 0.04, 0.14),
            box("panel", "black", 0, 0, 0.5, 1.25, 0.05, 0.72),
            box("picture", "screen", 0, 0.026, 0.5, 1.19, 0.004, 0.66)]


def armchair():
    return [box("seat", "armchair_fabric", 0, 0.03, 0.25, 0.85, 0.8, 0.42),
            box("back", "armchair_fabric", 0, -0.34, 0.7, 0.85, 0.16, 0.5),
            box("arm_l", "armchair_fabric", -0.36, 0.03, 0.56, 0.13, 0.8, 0.2),
            box("arm_r", "armchair_fabric", 0.36, 0.03, 0.56, 0.13, 0.8, 0.2),
            box("cushion", "cushion", 0, 0.06, 0.5, 0.58, 0.66, 0.08)]


def fireplace():
    """A brick chimney breast on the wall behind it (-y), the firebox and hearth at +y, a mantel."""
    return [box("breast", "brick", 0, -0.05, H / 2, 1.5, 0.4, H),
            box("firebox", "soot", 0, 0.15, 0.42, 0.8, 0.02, 0.6),
            box("hearth", "stone", 0, 0.3, 0.05, 1.6, 0.3, 0.1),
            box("mantel", "walnut", 0, 0.2, 1.12, 1.7, 0.2, 0.08),
            box("log1", "wood", -0.1, 0.05, 0.2, 0.5, 0.1, 0.1), box("log2", "wood", 0.1, 0.05, 0.3, 0.5, 0.1, 0.1)]


def bookshelf():
    """A tall open bookcase facing +y, its back to a wall, five shelves of books."""
    v = [box("side_l", "walnut", -0.49, 0, 0.95, 0.03, 0.33, 1.9),
         box("side_r", "walnut", 0.49, 0, 0.95, 0.03, 0.33, 1.9),
         box("back", "walnut", 0, -0.155, 0.95, 0.95, 0.02, 1.9), box("top", "walnut", 0, 0, 1.89, 1.0, 0.33, 0.03)]
    for i in range(5):
        z = 0.08 + 0.38 * i
        v.append(box(f"shelf{i}", "walnut", 0, 0, z, 0.95, 0.31, 0.02))
        v += [box(f"book{i}_{k}", BOOKS[(i + k) % 3], -0.36 + 0.09 * k, 0.01, z + 0.13, 0.06, 0.22, 0.24)
              for k in range(8 - (i % 3))]
    return v


def floor_lamp():
    return [cyl("foot", "dark_metal", 0, 0, 0.015, 0.16, 0.03), cyl("pole", "steel", 0, 0, 0.8, 0.015, 1.55),
            cyl("shade", "lamp_shade", 0, 0, 1.62, 0.2, 0.3)]


def refrigerator():
    """A fridge-freezer: the freezer door at the bottom, the fridge door above, the doors at +y."""
    return [box("body", "fridge_white", 0, 0, 0.9, 0.8, 0.72, 1.8),
            box("seam", "dark_metal", 0, 0.361, 0.62, 0.78, 0.004, 0.01),
            box("handle_fridge", "steel", 0.33, 0.39, 1.15, 0.03, 0.03, 0.5),
            box("handle_freezer", "steel", 0.33, 0.39, 0.45, 0.03, 0.03, 0.3)]


def kitchen_cabinet(width=1.0, wall_unit=True):
    """A base cabinet with its worktop (doors at +y) and, unless a window is above it, a wall cupboard."""
    v = [box("carcass", "cabinet_white", 0, 0, 0.44, width, 0.58, 0.88),
         box("worktop", "counter_top", 0, 0.01, 0.9, width, 0.62, 0.04),
         box("plinth", "soot", 0, 0.22, 0.04, width, 0.1, 0.08),
         box("handle1", "steel", -width / 4, 0.3, 0.78, 0.12, 0.02, 0.02),
         box("handle2", "steel", width / 4, 0.3, 0.78, 0.12, 0.02, 0.02)]
    if wall_unit:
        v.append(box("wall_unit", "cabinet_white", 0, -0.13, 1.85, width, 0.34, 0.7))
    return v


def stove():
    """A freestanding range: the oven door at +y, four burners on the hob, a back guard."""
    v = [box("body", "steel", 0, 0, 0.45, 0.76, 0.62, 0.9),
         box("oven_door", "glass_door", 0, 0.312, 0.4, 0.6, 0.004, 0.45),
         box("hob", "hob_black", 0, 0, 0.915, 0.76, 0.62, 0.03),
         box("back_guard", "steel", 0, -0.29, 1.0, 0.76, 0.04, 0.2)]
    return v + [cyl(f"burner{i}", "soot", sx * 0.18, sy * 0.14, 0.935, 0.09, 0.01)
                for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]


def microwave():
    return [box("body", "black", 0, 0, 0.15, 0.5, 0.38, 0.3),
            box("window", "glass_door", -0.06, 0.191, 0.15, 0.3, 0.002, 0.2),
            box("keypad", "grey_plastic", 0.18, 0.191, 0.15, 0.08, 0.002, 0.22)]


def kitchen_sink():
    """The sink unit: a base cabinet, its worktop with the bowl sunk in it and a mixer tap behind."""
    v = kitchen_cabinet(1.0, wall_unit=False)
    return v + [box("bowl", "steel", 0, 0.02, 0.86, 0.6, 0.42, 0.12),
                cyl("tap", "steel", 0, -0.24, 1.05, 0.015, 0.3),
                turned(cyl("spout", "steel", 0, -0.16, 1.19, 0.012, 0.18), "1.5708 0 0")]


def dishwasher():
    return [box("body", "steel", 0, 0, 0.43, 0.6, 0.58, 0.86),
            box("panel", "black", 0, 0.292, 0.8, 0.56, 0.004, 0.08),
            box("handle", "steel", 0, 0.31, 0.72, 0.4, 0.02, 0.02),
            box("worktop", "counter_top", 0, 0.01, 0.9, 0.6, 0.62, 0.04)]


def kitchen_table():
    return [box("top", "light_wood", 0, 0, 0.74, 1.4, 0.9, 0.04)] + legs("light_wood", 0.64, 0.39, 0.72, 0.06)


def dining_chair():
    """A wooden kitchen chair, the seat toward +y, the back at -y."""
    return [box("seat", "light_wood", 0, 0, 0.46, 0.44, 0.42, 0.04),
            box("back", "light_wood", 0, -0.2, 0.75, 0.42, 0.03, 0.5)] + legs("light_wood", 0.19, 0.18, 0.44, 0.035)


def trash_can():
    return [cyl("body", "steel", 0, 0, 0.33, 0.17, 0.66), cyl("lid", "black", 0, 0, 0.67, 0.175, 0.03)]


def washing_machine():
    """A front loader, the porthole door at +y."""
    return [box("body", "white", 0, 0, 0.43, 0.6, 0.6, 0.85),
            box("panel", "grey_plastic", 0, 0.28, 0.8, 0.56, 0.05, 0.08),
            turned(cyl("door", "glass_door", 0, 0.3, 0.42, 0.18, 0.02), "1.5708 0 0"),
            turned(cyl("ring", "steel", 0, 0.305, 0.42, 0.2, 0.01), "1.5708 0 0")]


def dryer():
    """A tumble dryer beside the washer: a plain white door at +y and a lint drawer."""
    return [box("body", "white", 0, 0, 0.43, 0.6, 0.6, 0.85),
            box("panel", "grey_plastic", 0, 0.28, 0.8, 0.56, 0.05, 0.08),
            turned(cyl("door", "white", 0, 0.3, 0.42, 0.2, 0.02), "1.5708 0 0"),
            box("lint_drawer", "grey_plastic", 0.2, 0.302, 0.7, 0.12, 0.004, 0.04)]


def office_chair():
    return base.office_chair() + [box(f"leg{i}", "dark_metal", 0.14 * dx, 0.14 * dy, 0.04, 0.28 if dx else 0.04,
                                      0.28 if dy else 0.04, 0.03)
                                  for i, (dx, dy) in enumerate(((1, 0), (-1, 0), (0, 1), (0, -1)))]


def printer():
    """A desktop laser printer on its own low cabinet, the paper tray at +y."""
    return [box("cabinet", "grey_plastic", 0, 0, 0.3, 0.6, 0.5, 0.6),
            box("body", "white", 0, 0, 0.78, 0.48, 0.42, 0.36),
            box("tray", "white", 0, 0.25, 0.7, 0.3, 0.1, 0.02),
            box("output", "dark_metal", 0, 0.05, 0.965, 0.3, 0.2, 0.01)]


def bed():
    """A queen bed, its head (headboard, pillows) at +y."""
    return [box("frame", "walnut", 0, 0, 0.2, 1.6, 2.1, 0.3),
            box("mattress", "linen", 0, -0.05, 0.47, 1.52, 1.98, 0.24),
            box("duvet", "duvet", 0, -0.3, 0.6, 1.56, 1.4, 0.04),
            box("pillow_l", "linen", -0.38, 0.75, 0.64, 0.6, 0.35, 0.12),
            box("pillow_r", "linen", 0.38, 0.75, 0.64, 0.6, 0.35, 0.12),
            box("headboard", "walnut", 0, 1.03, 0.75, 1.66, 0.06, 1.1)]


def nightstand():
    return [box("body", "walnut", 0, 0, 0.28, 0.48, 0.42, 0.5), box("top", "walnut", 0, 0, 0.55, 0.5, 0.44, 0.03),
            box("drawer", "wood", 0, 0.212, 0.38, 0.4, 0.004, 0.16),
            box("knob", "steel", 0, 0.22, 0.38, 0.04, 0.02, 0.03)] + legs("walnut", 0.2, 0.17, 0.05, 0.04)


def dresser():
    """A chest of drawers facing +y, four drawers."""
    v = [box("body", "walnut", 0, 0, 0.45, 1.4, 0.5, 0.86), box("top", "walnut", 0, 0, 0.89, 1.44, 0.52, 0.03)]
    return v + [box(f"drawer{i}", "wood", 0, 0.252, 0.14 + 0.2 * i, 1.3, 0.004, 0.16) for i in range(4)]


def wardrobe():
    """A two-door wardrobe facing +y."""
    return [box("body", "walnut", 0, 0, 1.0, 1.2, 0.6, 2.0),
            box("door_l", "wood", -0.3, 0.302, 1.0, 0.58, 0.004, 1.9),
            box("door_r", "wood", 0.3, 0.302, 1.0, 0.58, 0.004, 1.9),
            box("handle_l", "steel", -0.05, 0.31, 1.05, 0.02, 0.02, 0.3),
            box("handle_r", "steel", 0.05, 0.31, 1.05, 0.02, 0.02, 0.3)]


def mirror(w=0.8, h=1.0):
    """A framed mirror hung on a wall: the glass looks along +y (the wall behind it at -y)."""
    return [box("frame", "walnut", 0, 0, 0, w, 0.03, h), box("glass", "mirror", 0, 0.016, 0, w - 0.08, 0.004, h - 0.08)]


def toilet():
    """A close-coupled toilet: the cistern against the wall (-y), the bowl and seat toward +y."""
    return [box("cistern", "porcelain", 0, -0.25, 0.6, 0.42, 0.18, 0.42),
            box("pedestal", "porcelain", 0, 0.02, 0.2, 0.28, 0.4, 0.4),
            cyl("bowl", "porcelain", 0, 0.08, 0.36, 0.19, 0.12),
            cyl("seat", "white", 0, 0.08, 0.43, 0.2, 0.02),
            box("flush", "steel", 0.12, -0.25, 0.83, 0.05, 0.03, 0.02)]


def bathtub():
    """A built-in bath along the wall behind it (-y) with a shower head and a tap on that wall."""
    return [box("shell", "porcelain", 0, 0, 0.28, 1.65, 0.75, 0.56),
            box("water", "tile", 0, 0.0, 0.5, 1.5, 0.6, 0.02),
            cyl("shower_pipe", "steel", 0.6, -0.34, 1.45, 0.012, 1.1),
            turned(cyl("shower_head", "steel", 0.6, -0.26, 1.98, 0.08, 0.03), "0.5 0 0"),
            box("tap", "steel", 0.6, -0.33, 0.7, 0.08, 0.06, 0.06)]


def bathroom_sink():
    """A vanity: a cabinet with doors at +y, the basin on top and the tap behind."""
    return [box("cabinet", "cabinet_white", 0, 0, 0.4, 0.9, 0.5, 0.8),
            box("top", "stone", 0, 0.01, 0.82, 0.92, 0.52, 0.04),
            cyl("basin", "porcelain", 0, 0.04, 0.86, 0.19, 0.08),
            cyl("tap", "steel", 0, -0.18, 0.93, 0.015, 0.18),
            box("door_l", "cabinet_white", -0.22, 0.252, 0.4, 0.42, 0.004, 0.7),
            box("door_r", "cabinet_white", 0.22, 0.252, 0.4, 0.42, 0.004, 0.7)]


def walls():
    """Outer walls with the front and back doors; the hallway, the laundry nook and the corridor."""
    v, wall = base.wall_builder(H, T)
    # outer walls: south (the front door), north (the back door), west, east
    wall(0, 0, FD0, 0); wall(FD1, 0, W, 0); wall(FD0, 0, FD1, 0, UP, H)
    wall(0, D, BD0, D); wall(BD1, D, W, D); wall(BD0, D, BD1, D, UP, H)
    wall(0, 0, 0, D); wall(W, 0, W, D)
    # the hallway's west wall: the living room's archway (y 1.8..3.2), closed to the kitchen and nook
    wall(HX0, 0, HX0, 1.8); wall(HX0, 1.8, HX0, 3.2, UP, H); wall(HX0, 3.2, HX0, D)
    # living room | kitchen, open through a wide doorway at x 4.3..5.3
    wall(0, KY, 4.3, KY); wall(4.3, KY, 5.3, KY, UP, H); wall(5.3, KY, HX0, KY)
    # the laundry nook's mouth on the hallway (x 5.8..7.2), its east wall shared with the bedroom
    wall(HX0, LY, 5.8, LY); wall(5.8, LY, 7.2, LY, UP, H); wall(7.2, LY, HX1, LY)
    # the hallway's east wall: the office's west wall (y 0..4.5), then open to the corridor
    wall(HX1, 0, HX1, CY0); wall(HX1, CY1, HX1, D)
    # the corridor's south side: the office door (x 8.0..8.9) and the bathroom door (x 11.2..12.1)
    wall(HX1, CY0, 8.0, CY0); wall(8.0, CY0, 8.9, CY0, UP, H); wall(8.9, CY0, 11.2, CY0)
    wall(11.2, CY0, 12.1, CY0, UP, H); wall(12.1, CY0, W, CY0)
    wall(OX, 0, OX, CY0)  # office | bathroom
    # the corridor's north side: the bedroom door (x 9.0..9.9)
    wall(HX1, CY1, 9.0, CY1); wall(9.0, CY1, 9.9, CY1, UP, H); wall(9.9, CY1, W, CY1)
    return v


def house(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    # doors, each open door leaf hinged at one side of its opening and swung into the room
    add("door_1", (FD0 + 0.04, 0.47, 0, 1.5708), base.door())          # front (porch) door
    add("door_2", (BD0 + 0.04, D - 0.47, 0, 1.5708), base.door())      # back door to the patio
    add("door_3", (8.04, CY0 - 0.47, 0, 1.5708), base.door())          # office
    add("door_4", (11.24, CY0 - 0.47, 0, 1.5708), base.door())         # bathroom
    add("door_5", (9.04, CY1 + 0.47, 0, 1.5708), base.door())          # bedroom
    # windows on the inner faces of the outer walls
    south, north = T / 2 + 0.02, D - T / 2 - 0.02
    west, east = T / 2 + 0.02, W - T / 2 - 0.02
    add("window_1", (4.4, south, 1.6, 0), base.window())             # living room, front
    add("window_2", (west, 1.1, 1.6, 1.5708), base.window())         # living room, west
    add("window_3", (west, 8.2, 1.65, 1.5708), base.window())        # kitchen, over the sink
    add("window_4", (2.4, north, 1.75, 0), base.window())            # kitchen, over the range
    add("window_5", (9.0, south, 1.6, 0), base.window())             # office, behind the desk
    add("window_6", (11.3, south, 1.7, 0), base.window())            # bathroom
    add("window_7", (east, 7.8, 1.6, 1.5708), base.window())         # bedroom, east
    add("window_8", (8.8, north, 1.6, 0), base.window())             # bedroom, north

    # the living room (south-west): the TV on its stand on the south wall, the sectional facing it
    add("tv_stand", (2.6, T / 2 + 0.25, 0, 0), tv_stand())
    add("television", (2.6, T / 2 + 0.25, 0.53, 0), television())
    add("sectional_sofa", (2.7, 4.4, 0, 3.1416), sectional_sofa())    # its chaise on the west end
    add("coffee_table", (2.9, 2.4, 0, 0), coffee_table())
    add("fireplace", (T / 2 + 0.25, 2.8, 0, -1.5708), fireplace())     # on the west wall
    add("armchair", (1.05, 1.15, 0, 0.7854), armchair())                 # by the fireplace, toward the TV
    add("bookshelf", (HX0 - T / 2 - 0.17, 4.3, 0, 1.5708), bookshelf())  # on the hallway wall
    add("floor_lamp", (0.9, 4.85, 0, 0), floor_lamp())                   # at the sofa's west end

    # the kitchen (north-west): fridge, cabinets, range on the north wall; sink run on the west wall
    add("refrigerator", (0.47, D - T / 2 - 0.37, 0, 3.1416), refrigerator())
    add("kitchen_cabinet_1", (1.4, D - T / 2 - 0.3, 0, 3.1416), kitchen_cabinet(1.0, wall_unit=False))
    add("stove", (2.28, D - T / 2 - 0.32, 0, 3.1416), stove())
    add("kitchen_cabinet_2", (3.16, D - T / 2 - 0.3, 0, 3.1416), kitchen_cabinet(1.0, wall_unit=False))
    add("microwave", (3.2, D - T / 2 - 0.32, 0.92, 3.1416), microwave())
    add("kitchen_sink", (T / 2 + 0.3, 8.2, 0, -1.5708), kitchen_sink())
    add("dishwasher", (T / 2 + 0.3, 7.4, 0, -1.5708), dishwasher())
    add("kitchen_cabinet_3", (T / 2 + 0.3, 6.6, 0, -1.5708), kitchen_cabinet(1.0))
    add("kitchen_table", (2.9, 7.4, 0, 0), kitchen_table())
    for i, (x, y, yaw) in enumerate(((2.55, 8.3, 3.1416), (3.25, 8.3, 3.1416), (2.55, 6.5, 0), (3.25, 6.5, 0)), 1):
        add(f"dining_chair_{i}", (x, y, 0, yaw), dining_chair())
    add("trash_can_1", (5.2, 9.6, 0, 0), trash_can())                    # by the back door

    # the laundry nook (north of the hallway): washer and dryer side by side on the north wall
    add("washing_machine", (6.05, D - T / 2 - 0.32, 0, 3.1416), washing_machine())
    add("dryer", (6.85, D - T / 2 - 0.32, 0, 3.1416), dryer())

    # the home office (south-east of the hallway): the desk under the window, chair north of it
    add("desk", (9.0, T / 2 + 0.4, 0, 0), base.desk())
    add("office_chair", (9.0, 1.2, 0, 3.1416), office_chair())
    add("computer_monitor", (9.0, 0.32, 0.75, 0), base.monitor())
    add("printer", (OX - T / 2 - 0.27, 2.5, 0, 1.5708), printer())
    add("trash_can_2", (7.85, 0.35, 0, 0), trash_can())

    # the bathroom (south-east corner): bath on the south wall, toilet east, vanity and mirror west
    add("bathtub", (13.1, T / 2 + 0.38, 0, 0), bathtub())
    add("toilet", (W - T / 2 - 0.34, 2.3, 0, 1.5708), toilet())
    add("bathroom_sink", (OX + T / 2 + 0.26, 2.0, 0, -1.5708), bathroom_sink())
    add("mirror_2", (OX + T / 2 + 0.02, 2.0, 1.55, -1.5708), mirror(0.7, 0.9))

    # the bedroom (north-east): the bed's head on the north wall, nightstands, dresser and mirror
    add("bed", (11.0, D - T / 2 - 1.07, 0, 0), bed())
    add("nightstand_1", (9.87, D - T / 2 - 0.24, 0, 3.1416), nightstand())
    add("nightstand_2", (12.13, D - T / 2 - 0.24, 0, 3.1416), nightstand())
    add("dresser", (11.5, CY1 + T / 2 + 0.27, 0, 0), dresser())
    add("mirror_1", (11.5, CY1 + T / 2 + 0.02, 1.5, 0), mirror(0.9, 1.0))
    add("wardrobe", (HX1 + T / 2 + 0.31, 7.5, 0, -1.5708), wardrobe())


def main():
    out = base.shell(walls(), "floor_smallhouse", "oak_floor", W, D, H)
    house(out)
    lights = [base.point_light(name, x, y, 2.4, "0.8 0.78 0.72")
              for name, x, y in (("light_living", 2.7, 2.7), ("light_kitchen", 2.7, 7.7),
                                 ("light_hall", 6.5, 3.0), ("light_laundry", 6.5, 8.5),
                                 ("light_office", 9.0, 2.3), ("light_bathroom", 12.2, 2.3),
                                 ("light_bedroom", 10.8, 7.7), ("light_corridor", 12.0, 5.0))]
    print(base.world_sdf("semsplat_smallhouse", """The semsplat small house: a single-storey suburban house of 14 m x 10 m
     (the front door into a hallway; the living room in the south-west; the kitchen in the north-west
     with the back door to the patio; a laundry nook; the home office, the bathroom and the bedroom
     off a corridor in the east) for measuring on a world nobody tuned on. Generated by
     smallhouse_models/make_smallhouse.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
