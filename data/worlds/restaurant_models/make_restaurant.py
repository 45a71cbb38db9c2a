#!/usr/bin/env python3
"""Writes data/worlds/restaurant.world: a neighbourhood restaurant of 20 m x 14 m on one floor, for
measuring the semantic stack on a world nobody tuned on.

Front of house (y < 9), the street front in the south wall: the entrance (a double door) in the
south-west with the host stand, a waiting bench and a coat rack, potted plants and the exit sign
over the door; the dining room across the south and middle (small tables for two under the street
windows, tables for four, a long table for six with a high chair at its end, two booths along the
west wall, one with a high chair at its open end, a chalk menu board on the back wall, a fire
extinguisher by the kitchen door); the bar in the east (the bar counter with six bar stools, the
beer tap and the till on it, the bottle shelf on the back wall behind it, a television on the east
wall); the restrooms in the south-east corner (men's: a toilet behind a cubicle partition, a urinal,
a sink with a mirror, a hand dryer; women's: two toilets in cubicles, a sink with a mirror, a hand
dryer), their doors opening off the bar.
Back of house (y > 9), west to east: the office (desk, office chair, computer, filing cabinet, a
window), entered from the dining room; the storage room (wire storage shelves, flour sacks, produce
crates, a fire extinguisher, the back door with an exit sign over it), entered from the kitchen;
the commercial kitchen (the dish pit by the storage door with the dish sink, the dishwasher and a
mop bucket; the cooking line on the north wall: a gas range, two deep fryers and a double
convection oven under one exhaust hood; prep tables in the middle and on the north wall; a reach-in
refrigerator on the east wall and the walk-in fridge in the north-east corner; trash cans and a fire
extinguisher), entered from the dining room through the kitchen door.

Every model is inline (boxes, cylinders, spheres), so the world needs no model path. Model names
are what a world author would type; the class is the name less its _<number> ("bar_stool_3" ->
"bar stool", "walk_in_fridge" -> "walk in fridge"). The primitives and the SDF writing are the
office generator's.
Run: python3 data/worlds/restaurant_models/make_restaurant.py > data/worlds/restaurant.world"""

import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document, door, window, plant)

W, D, H = 20.0, 14.0, 3.0  # floor width (x), depth (y), wall height
T = 0.1                    # wall thickness
YB = 9.0                   # the wall between the front of house (south) and the back of house (north)
XO, XS = 3.5, 7.5          # north, west to east: office | storage room | kitchen
XR, YR, XRD = 15.0, 4.5, 17.5  # the restrooms: x > XR, y < YR; men's | women's at x = XRD
LINTEL = 2.1               # the top of the inner doorways

FRONT_DOOR = (1.6, 3.4)      # x, south wall (two leaves)
BACK_DOOR = (6.25, 7.15)     # x, north wall of the storage room
OFFICE_DOOR = (2.4, 3.3)     # x, wall y = YB
KITCHEN_DOOR = (10.4, 11.4)  # x, wall y = YB
STORAGE_DOOR = (9.6, 10.5)   # y, wall x = XS
MENS_DOOR = (15.6, 16.5)     # x, wall y = YR
WOMENS_DOOR = (18.1, 19.0)   # x, wall y = YR

N, S, E, WEST = 0.0, 3.1416, -1.5708, 1.5708  # yaw that turns a model's front (+y) north/south/east/west

base.COL.update({
    "woodfloor": "0.52 0.37 0.24", "quarry_tile": "0.6 0.34 0.27", "tile": "0.86 0.88 0.88",
    "plaster": "0.93 0.89 0.8", "partition": "0.88 0.86 0.82", "white_tile": "0.92 0.93 0.93",
    "walnut": "0.38 0.25 0.16", "oak": "0.6 0.45 0.28", "table_wood": "0.5 0.33 0.2",
    "bar_wood": "0.32 0.2 0.12", "bar_top": "0.2 0.12 0.07", "host_wood": "0.36 0.23 0.14",
    "porcelain": "0.97 0.97 0.97", "red_vinyl": "0.55 0.1 0.1", "leather": "0.28 0.17 0.1",
    "steel": "0.78 0.79 0.8", "dark_steel": "0.45 0.46 0.48", "brass": "0.8 0.65 0.3",
    "black": "0.06 0.06 0.07", "rubber": "0.1 0.1 0.1", "mirror": "0.8 0.85 0.88",
    "bottle_green": "0.15 0.4 0.2", "bottle_amber": "0.6 0.35 0.1", "bottle_clear": "0.85 0.9 0.9",
    "bottle_blue": "0.2 0.3 0.6", "label_cream": "0.92 0.88 0.75", "chalkboard": "0.12 0.15 0.13",
    "chalk": "0.92 0.92 0.88", "burner": "0.12 0.12 0.12", "oil": "0.8 0.65 0.2",
    "oven_glass": "0.2 0.22 0.25", "filter": "0.42 0.44 0.46", "cutting_board": "0.93 0.93 0.88",
    "grey_bin": "0.42 0.45 0.48", "mop_yellow": "0.93 0.78 0.1", "mop_head": "0.86 0.85 0.8",
    "burlap": "0.86 0.8 0.66", "sack_print": "0.7 0.2 0.15", "crate_wood": "0.72 0.57 0.36",
    "crate_blue": "0.2 0.35 0.6", "tomato": "0.82 0.15 0.1", "onion": "0.8 0.63 0.35",
    "lettuce": "0.45 0.72 0.3", "potato": "0.7 0.58 0.38", "can": "0.72 0.72 0.74",
    "carton": "0.76 0.6 0.4", "jar_red": "0.7 0.2 0.1", "extinguisher_red": "0.8 0.08 0.06",
    "exit_green": "0.05 0.6 0.25", "screen": "0.05 0.06 0.08", "screen_lit": "0.25 0.45 0.6",
    "beech": "0.85 0.72 0.5", "tray_white": "0.95 0.95 0.93", "menu_cover": "0.15 0.22 0.15",
    "coat": "0.3 0.25 0.2", "coat2": "0.22 0.27 0.42", "scarf": "0.75 0.3 0.15",
    "fridge_panel": "0.86 0.87 0.88", "gasket": "0.15 0.15 0.15", "display_red": "0.85 0.1 0.1",
    "tap_red": "0.75 0.1 0.1", "tap_gold": "0.85 0.7 0.2", "tap_black": "0.1 0.1 0.1",
    "linen": "0.95 0.94 0.9", "wine_glass": "0.8 0.88 0.92", "candle": "0.95 0.92 0.8",
    "paper": "0.96 0.96 0.94", "chair_black": "0.1 0.1 0.1",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
turned, along_x, along_y, castors = base.turned, base.along_x, base.along_y, base.castors


# ---- the entrance (local frames: x right, y forward = the side a person uses, z up) ----
def host_stand():
    """The host's podium: a closed front to the arriving guests (+y), a sloping top toward the
    host behind it (-y) with the menus, the booking tablet and a small brass sign."""
    return [box("plinth", "bar_top", 0, 0, 0.04, 0.64, 0.49, 0.08),
            box("body", "host_wood", 0, 0, 0.58, 0.6, 0.45, 1.0),
            turned(box("top", "walnut", 0, -0.02, 1.12, 0.68, 0.52, 0.04), "0.2 0 0"),
            turned(box("menus", "menu_cover", -0.12, -0.06, 1.15, 0.25, 0.34, 0.03), "0.2 0 0"),
            turned(box("tablet", "black", 0.16, -0.06, 1.145, 0.2, 0.27, 0.015), "0.2 0 0"),
            box("sign", "brass", 0, 0.226, 0.88, 0.32, 0.005, 0.09)]


def waiting_bench(length=1.4):
    """A wooden bench with a leather seat pad and a back (at -y) for guests waiting for a table."""
    return [box("frame", "oak", 0, 0, 0.4, length, 0.42, 0.05),
            box("pad", "leather", 0, 0.01, 0.45, length - 0.04, 0.4, 0.06),
            box("back", "oak", 0, -0.2, 0.78, length, 0.04, 0.5),
            box("rail", "oak", 0, -0.2, 1.06, length + 0.04, 0.06, 0.05)] + \
        legs("oak", length / 2 - 0.05, 0.17, 0.38, 0.05)


def coat_rack():
    """A freestanding coat stand: a round foot, the pole, four hooks, two coats and a scarf."""
    v = [cyl("foot", "walnut", 0, 0, 0.025, 0.24, 0.05),
         cyl("pole", "walnut", 0, 0, 0.9, 0.028, 1.75),
         sph("knob", "walnut", 0, 0, 1.8, 0.045)]
    v += [box(f"hook{i}", "brass", dx * 0.08, dy * 0.08, 1.66, 0.16 if dx else 0.02, 0.16 if dy else 0.02, 0.02)
          for i, (dx, dy) in enumerate(((1, 0), (-1, 0), (0, 1), (0, -1)))]
    return v + [box("coat0", "coat", 0.15, 0, 1.22, 0.12, 0.46, 0.82),
                box("coat1", "coat2", -0.13, 0.04, 1.28, 0.1, 0.42, 0.7),
                box("scarf", "scarf", 0, 0.13, 1.45, 0.06, 0.04, 0.4)]


# ---- the dining room ----
def dining_table(w, d, places):
    """A wooden restaurant table (w x d) on four legs, laid for guests: a plate and a glass at each
    place (local offsets), salt and pepper and a candle in the middle."""
    v = [box("top", "table_wood", 0, 0, 0.745, w, d, 0.04)] + legs("walnut", w / 2 - 0.06, d / 2 - 0.06, 0.725, 0.05)
    for i, (px, py) in enumerate(places):
        gx, gy = px * 0.6 + 0.08 * (1 if py <= 0 else -1), py * 0.6
        v += [cyl(f"plate{i}", "porcelain", px, py, 0.772, 0.12, 0.012),
              cyl(f"glass{i}", "wine_glass", gx + 0.1, gy, 0.82, 0.035, 0.11)]
    return v + [cyl("salt", "porcelain", -0.04, 0, 0.8, 0.018, 0.07),
                cyl("pepper", "black", 0.04, 0, 0.8, 0.018, 0.07),
                cyl("candle", "candle", 0, 0.07, 0.79, 0.03, 0.05)]


def two_places(w):
    return [(-w / 2 + 0.17, 0), (w / 2 - 0.17, 0)]


def four_places(w, d):
    return [(-w / 2 + 0.17, 0), (w / 2 - 0.17, 0), (0, -d / 2 + 0.17), (0, d / 2 - 0.17)]


def dining_chair():
    """A wooden bistro chair with a slatted back (at -y), the guest facing +y."""
    v = [box("seat", "oak", 0, 0, 0.46, 0.44, 0.43, 0.04),
         box("top_rail", "walnut", 0, -0.2, 0.9, 0.42, 0.03, 0.07)]
    v += [box(f"slat{i}", "oak", -0.12 + 0.12 * i, -0.2, 0.68, 0.05, 0.02, 0.4) for i in range(3)]
    v += [box(f"back_post{i}", "walnut", s * 0.19, -0.2, 0.68, 0.04, 0.04, 0.46) for i, s in enumerate((-1, 1))]
    return v + legs("walnut", 0.19, 0.18, 0.44, 0.04)


def booth(w=1.3, gap=0.8):
    """A restaurant booth: two upholstered benches with high backs facing each other across the
    table between them (the table is its own model), the benches at -gap and +gap."""
    v = []
    for k, s in enumerate((-1, 1)):
        y = s * gap
        v += [box(f"base{k}", "bar_wood", 0, y, 0.2, w, 0.5, 0.4),
              box(f"cushion{k}", "red_vinyl", 0, y, 0.45, w - 0.02, 0.5, 0.1),
              box(f"back{k}", "red_vinyl", 0, y + s * 0.22, 0.85, w - 0.02, 0.1, 0.72),
              box(f"shell{k}", "bar_wood", 0, y + s * 0.3, 0.62, w, 0.05, 1.24),
              box(f"cap{k}", "bar_wood", 0, y + s * 0.27, 1.25, w + 0.02, 0.12, 0.03)]
    return v


def high_chair():
    """A wooden baby high chair: long legs, a seat at table height with a back (at -y) and arm
    rails, the tray in front, a footrest."""
    v = [box(f"leg{i}", "beech", sx * 0.2, sy * 0.2, 0.39, 0.04, 0.04, 0.78)
         for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    v += [box("seat", "beech", 0, 0, 0.8, 0.36, 0.34, 0.04),
          box("back", "beech", 0, -0.17, 1.03, 0.34, 0.03, 0.42),
          box("arm_l", "beech", -0.18, 0.02, 0.95, 0.03, 0.32, 0.03),
          box("arm_r", "beech", 0.18, 0.02, 0.95, 0.03, 0.32, 0.03),
          box("tray", "tray_white", 0, 0.22, 0.98, 0.46, 0.2, 0.03),
          box("footrest", "beech", 0, 0.19, 0.42, 0.36, 0.1, 0.02),
          box("brace_f", "beech", 0, 0.2, 0.2, 0.4, 0.02, 0.03),
          box("brace_b", "beech", 0, -0.2, 0.2, 0.4, 0.02, 0.03)]
    return v


def menu_board():
    """A chalkboard menu in a wooden frame on a wall (behind it at -y), centred on the model's
    height: a title and the day's dishes chalked on it."""
    v = [box("frame", "walnut", 0, 0, 0, 1.0, 0.03, 1.3),
         box("board", "chalkboard", 0, 0.016, 0, 0.9, 0.004, 1.2),
         box("title", "chalk", 0, 0.019, 0.45, 0.5, 0.002, 0.1)]
    v += [box(f"line{i}", "chalk", -0.05 + 0.05 * (i % 2), 0.019, 0.25 - 0.15 * i, 0.62 - 0.06 * (i % 3), 0.002, 0.04)
          for i in range(5)]
    return v + [box(f"price{i}", "chalk", 0.36, 0.019, 0.25 - 0.15 * i, 0.08, 0.002, 0.04) for i in range(5)]


# ---- the bar ----
def bar_counter(length=5.4, depth=0.7):
    """The bar: a panelled front to the customers (+y) with a brass foot rail, the thick top, the
    bartender's steel underbar on the far side (-y)."""
    v = [box("front", "bar_wood", 0, depth / 2 - 0.04, 0.53, length, 0.08, 1.06),
         box("top", "bar_top", 0, 0.05, 1.085, length + 0.1, depth + 0.1, 0.05),
         box("underbar", "steel", 0, -0.14, 0.45, length - 0.12, 0.4, 0.9),
         box("side_l", "bar_wood", -length / 2 + 0.03, 0, 0.53, 0.06, depth, 1.06),
         box("side_r", "bar_wood", length / 2 - 0.03, 0, 0.53, 0.06, depth, 1.06),
         along_x(cyl("foot_rail", "brass", 0, depth / 2 + 0.15, 0.22, 0.025, length - 0.2))]
    v += [box(f"panel{i}", "walnut", -length / 2 + 0.45 + 0.9 * i, depth / 2 + 0.002, 0.55, 0.7, 0.004, 0.75)
          for i in range(int(length / 0.9))]
    v += [box(f"rail_bracket{i}", "brass", -length / 2 + 0.3 + i * (length - 0.6) / 4, depth / 2 + 0.07, 0.22,
              0.03, 0.16, 0.03) for i in range(5)]
    return v


def bar_stool():
    """A round upholstered bar stool on a steel pedestal with a foot ring."""
    return [cyl("base", "dark_metal", 0, 0, 0.015, 0.22, 0.03),
            cyl("pedestal", "steel", 0, 0, 0.39, 0.03, 0.72),
            cyl("foot_ring", "steel", 0, 0, 0.3, 0.17, 0.02),
            cyl("seat_pan", "dark_metal", 0, 0, 0.75, 0.18, 0.03),
            cyl("cushion", "leather", 0, 0, 0.795, 0.19, 0.06)]


def bottle_shelf(length=3.0):
    """The back bar against the wall (behind it at -y): a low cabinet with a counter, a mirror
    behind three glass shelves of bottles (spirits and wines), a wooden crown on top."""
    colours = ("bottle_green", "bottle_amber", "bottle_clear", "bottle_blue", "bottle_amber")
    v = [box("cabinet", "bar_wood", 0, 0, 0.45, length, 0.45, 0.9),
         box("counter", "bar_top", 0, 0.02, 0.92, length + 0.04, 0.5, 0.04),
         box("mirror", "mirror", 0, -0.2, 1.62, length - 0.12, 0.01, 1.2),
         box("side_l", "bar_wood", -length / 2 + 0.03, -0.08, 1.62, 0.06, 0.3, 1.36),
         box("side_r", "bar_wood", length / 2 - 0.03, -0.08, 1.62, 0.06, 0.3, 1.36),
         box("crown", "bar_wood", 0, -0.07, 2.33, length + 0.04, 0.32, 0.08)]
    v += [box(f"door_seam{i}", "bar_top", -length / 2 + 0.6 * (i + 1), 0.226, 0.45, 0.01, 0.004, 0.82)
          for i in range(int(length / 0.6) - 1)]
    n = int((length - 0.3) / 0.13)
    for i in range(3):
        z = 1.12 + 0.42 * i
        v.append(box(f"shelf{i}", "glass", 0, -0.08, z, length - 0.12, 0.26, 0.015))
        for k in range(n):
            x, c = -length / 2 + 0.2 + 0.13 * k, colours[(3 * i + k) % 5]
            v += [cyl(f"bottle{i}_{k}", c, x, -0.08, z + 0.12, 0.035, 0.22),
                  cyl(f"neck{i}_{k}", c, x, -0.08, z + 0.28, 0.012, 0.1),
                  box(f"label{i}_{k}", "label_cream", x, -0.044, z + 0.1, 0.045, 0.002, 0.06)]
    v += [cyl(f"glass{k}", "wine_glass", -length / 2 + 0.3 + 0.12 * k, 0.05, 1.0, 0.04, 0.12) for k in range(8)]
    return v


def beer_tap():
    """A beer tap tower standing on the bar counter: a drip tray, the column, the T head with three
    faucets and their coloured handles, toward the bartender (+y)."""
    v = [box("drip_tray", "steel", 0, 0.12, 0.01, 0.48, 0.14, 0.02),
         cyl("column", "steel", 0, 0, 0.2, 0.035, 0.4),
         along_x(cyl("head", "steel", 0, 0, 0.42, 0.04, 0.46))]
    for i, (x, c) in enumerate(((-0.15, "tap_red"), (0, "tap_gold"), (0.15, "tap_black"))):
        v += [box(f"faucet{i}", "steel", x, 0.06, 0.38, 0.025, 0.09, 0.025),
              box(f"spout{i}", "steel", x, 0.09, 0.33, 0.02, 0.02, 0.07),
              cyl(f"handle{i}", c, x, 0.05, 0.52, 0.017, 0.16)]
    return v


def cash_register():
    """A till on a counter: the cash drawer, the keypad and the touch screen facing the cashier
    (-y), the small customer display facing +y."""
    return [box("drawer", "chair_black", 0, 0, 0.05, 0.42, 0.4, 0.1),
            box("keypad", "grey_plastic", 0, -0.09, 0.12, 0.3, 0.16, 0.04),
            turned(box("screen", "screen_lit", 0, 0.06, 0.25, 0.32, 0.02, 0.22), "0.3 0 0"),
            box("stand", "chair_black", 0, 0.08, 0.15, 0.06, 0.04, 0.1),
            box("customer_display", "screen", 0, 0.17, 0.2, 0.16, 0.02, 0.06),
            box("receipt_printer", "grey_plastic", 0.28, -0.02, 0.06, 0.14, 0.18, 0.12)]


def television():
    """A flat-screen TV on a wall bracket (the wall behind at -y), centred on the model's height."""
    return [box("bracket", "dark_metal", 0, -0.05, 0, 0.3, 0.05, 0.25),
            box("panel", "black", 0, 0, 0, 1.24, 0.05, 0.72),
            box("screen", "screen_lit", 0, 0.026, 0.01, 1.18, 0.004, 0.66)]


# ---- the kitchen ----
def gas_range(w=1.2, d=0.85):
    """A six-burner restaurant range on legs: the oven below with its door and handle toward the
    cook (+y), burner grates on top, knobs along the front, a backsplash with a shelf, a stock
    pot on the back burner."""
    v = [box("body", "steel", 0, 0, 0.53, w, d, 0.76),
         box("oven_door", "dark_steel", 0, d / 2 + 0.005, 0.46, w - 0.16, 0.01, 0.5),
         along_x(cyl("oven_handle", "steel", 0, d / 2 + 0.05, 0.75, 0.015, w - 0.3)),
         box("top", "dark_metal", 0, 0, 0.92, w, d, 0.02),
         box("backsplash", "steel", 0, -d / 2 + 0.02, 1.15, w, 0.04, 0.45),
         box("shelf", "steel", 0, -d / 2 + 0.14, 1.36, w, 0.26, 0.03)]
    v += legs("steel", w / 2 - 0.05, d / 2 - 0.05, 0.15, 0.05)
    for i in range(6):
        x, y = (-1 + (i % 3)) * w / 3, (0.17 if i < 3 else -0.17)
        v.append(cyl(f"grate{i}", "burner", x, y, 0.945, 0.13, 0.03))
        v.append(along_y(cyl(f"knob{i}", "black", -w / 2 + 0.12 + i * (w - 0.24) / 5, d / 2 + 0.02, 0.83, 0.022, 0.04)))
    return v + [cyl("stock_pot", "steel", w / 3, -0.17, 1.1, 0.16, 0.28)]


def deep_fryer():
    """A floor-standing deep fryer: the steel cabinet, the oil vat on top with two baskets whose
    handles stick out toward the cook (+y), the flue at the back."""
    v = [box("cabinet", "steel", 0, 0, 0.52, 0.45, 0.8, 0.8),
         box("door", "dark_steel", 0, 0.405, 0.5, 0.39, 0.01, 0.6),
         box("vat_rim", "dark_steel", 0, 0.03, 0.93, 0.45, 0.62, 0.02),
         box("oil", "oil", 0, 0.03, 0.942, 0.36, 0.5, 0.005),
         box("flue", "steel", 0, -0.36, 1.1, 0.43, 0.08, 0.36)]
    v += legs("steel", 0.19, 0.35, 0.12, 0.04)
    for i, x in enumerate((-0.095, 0.095)):
        v += [box(f"basket{i}", "filter", x, 0.0, 1.01, 0.16, 0.3, 0.12),
              box(f"basket_handle{i}", "black", x, 0.3, 1.05, 0.025, 0.3, 0.025)]
    return v


def convection_oven():
    """A double-stack convection oven on a steel stand: two ovens, each with a windowed door, a
    handle and a control panel on the right, toward the cook (+y)."""
    v = legs("steel", 0.46, 0.42, 0.6, 0.05) + [box("undershelf", "steel", 0, 0, 0.2, 0.96, 0.88, 0.02)]
    for k in range(2):
        z0 = 0.6 + 0.64 * k
        v += [box(f"oven{k}", "steel", 0, 0, z0 + 0.32, 1.0, 0.95, 0.62),
              box(f"door{k}", "dark_steel", -0.08, 0.478, z0 + 0.32, 0.74, 0.01, 0.52),
              box(f"window{k}", "oven_glass", -0.08, 0.484, z0 + 0.34, 0.54, 0.004, 0.34),
              box(f"panel{k}", "black", 0.39, 0.478, z0 + 0.32, 0.17, 0.01, 0.5),
              cyl(f"handle{k}", "black", 0.24, 0.5, z0 + 0.32, 0.014, 0.4),
              box(f"display{k}", "display_red", 0.39, 0.484, z0 + 0.48, 0.1, 0.004, 0.05)]
    return v


def exhaust_hood(length=3.8, depth=1.15):
    """The canopy hood over the cooking line, hung on the wall (behind it at -y): the steel
    canopy, the grease filters and lights on its underside, the duct up to the ceiling."""
    v = [box("canopy", "steel", 0, 0, 2.35, length, depth, 0.6),
         box("lip", "steel", 0, depth / 2 - 0.02, 2.02, length, 0.04, 0.08),
         box("filters", "filter", 0, -0.2, 2.045, length - 0.2, 0.5, 0.01),
         box("duct", "steel", 0, -0.2, 2.825, 0.55, 0.45, 0.35)]
    return v + [box(f"light{i}", "paper", -length / 3 + i * length / 3, 0.25, 2.045, 0.3, 0.12, 0.01) for i in range(3)]


def prep_table(w=1.8, d=0.75, splash=False):
    """A stainless steel work table: the top, an undershelf, legs; a cutting board, a mixing bowl
    and some tomatoes on it; a backsplash when it stands against a wall (at -y)."""
    v = [box("top", "steel", 0, 0, 0.89, w, d, 0.04),
         box("undershelf", "steel", 0, 0, 0.25, w - 0.08, d - 0.08, 0.02)] + legs("steel", w / 2 - 0.04, d / 2 - 0.04, 0.87)
    v += [box("cutting_board", "cutting_board", -0.3, 0.05, 0.92, 0.5, 0.35, 0.02),
          cyl("bowl", "steel", 0.45, -0.05, 0.95, 0.14, 0.08)]
    v += [sph(f"tomato{i}", "tomato", -0.4 + 0.08 * i, 0.05, 0.965, 0.035) for i in range(3)]
    if splash:
        v.append(box("backsplash", "steel", 0, -d / 2 + 0.01, 1.0, w, 0.02, 0.2))
    v += [box(f"pans{i}", "dark_steel", 0.3 * (i - 1), 0, 0.32, 0.26, 0.45, 0.12) for i in range(3)]
    return v


def refrigerator():
    """A reach-in commercial refrigerator on castors: two solid half doors with long handles toward
    the user (+y), the compressor housing on top with its grille, a temperature display."""
    v = [box("body", "steel", 0, 0, 1.05, 0.72, 0.8, 1.8),
         box("door_top", "steel", 0, 0.405, 1.5, 0.68, 0.01, 0.86),
         box("door_bottom", "steel", 0, 0.405, 0.6, 0.68, 0.01, 0.86),
         box("gasket", "gasket", 0, 0.41, 1.05, 0.68, 0.005, 0.02),
         cyl("handle_top", "dark_metal", 0.28, 0.44, 1.5, 0.015, 0.5),
         cyl("handle_bottom", "dark_metal", 0.28, 0.44, 0.6, 0.015, 0.5),
         box("compressor", "steel", 0, 0, 2.03, 0.72, 0.8, 0.16),
         box("grille", "black", 0, 0.405, 2.03, 0.6, 0.005, 0.1),
         box("display", "display_red", -0.22, 0.41, 2.03, 0.1, 0.004, 0.05)]
    return v + castors(0.3, 0.33, 0.075)


def walk_in_fridge(w=2.35, d=2.35, h=2.5):
    """A walk-in cold room built of white insulated panels, its insulated steel door on the front
    (+y) with a heavy latch handle and a kick plate, the thermometer beside the door; inside (out
    of sight behind the shut door) wire racks of stock along the side walls and the back."""
    v = [box("room", "fridge_panel", 0, 0, h / 2, w, d, h)]
    for side in (-1, 1):  # side racks 0.78 deep: the aisle between them is narrower than a robot
        v += [box(f"rack{side + 1}_{k}", "steel", side * (w / 2 - 0.1 - 0.39), -0.1, 0.3 + 0.45 * k, 0.78, d - 0.4, 0.02)
              for k in range(4)]
    v += [box(f"rack_back_{k}", "steel", 0, -d / 2 + 0.1 + 0.25, 0.3 + 0.45 * k, w - 0.2, 0.5, 0.02) for k in range(4)]
    v += [box(f"seam{i}", "grey_plastic", -w / 2 + 0.6 * (i + 1), d / 2 + 0.002, h / 2, 0.01, 0.004, h)
          for i in range(int(w / 0.6)) if abs(-w / 2 + 0.6 * (i + 1) + 0.3) > 0.55]
    return v + [box("door_frame", "gasket", -0.3, d / 2 + 0.005, 1.05, 1.0, 0.01, 2.1),
                box("door", "steel", -0.3, d / 2 + 0.03, 1.02, 0.9, 0.05, 2.0),
                box("latch", "black", 0.08, d / 2 + 0.08, 1.05, 0.06, 0.06, 0.28),
                box("kick_plate", "dark_steel", -0.3, d / 2 + 0.057, 0.15, 0.9, 0.004, 0.3),
                box("thermometer", "black", 0.5, d / 2 + 0.01, 1.7, 0.16, 0.01, 0.09),
                box("reading", "display_red", 0.5, d / 2 + 0.016, 1.7, 0.1, 0.002, 0.04)]


def dishwasher():
    """A hood-type commercial dishwasher: the wash tank below, the lifting hood above with its
    handle toward the operator (+y), the controls on the hood."""
    return [box("tank", "steel", 0, 0, 0.42, 0.7, 0.7, 0.84),
            box("hood", "steel", 0, 0, 1.35, 0.68, 0.68, 0.9),
            along_x(cyl("hood_handle", "black", 0, 0.37, 1.0, 0.018, 0.5)),
            box("controls", "black", 0.2, 0.345, 1.65, 0.2, 0.01, 0.1),
            box("lamp", "exit_green", 0.05, 0.347, 1.65, 0.03, 0.005, 0.03),
            box("pivot", "steel", 0, -0.25, 1.95, 0.3, 0.15, 0.3),
            box("rack", "grey_plastic", 0, 0, 0.92, 0.5, 0.5, 0.1)]


def dish_sink(w=1.2, d=0.7):
    """The dish pit's pre-rinse sink against the wall (behind it at -y): two deep bowls, a tall
    spring faucet with its spray head, a backsplash, legs."""
    v = [box("tub", "steel", 0, 0, 0.85, w, d, 0.2),
         box("bowl0", "dark_steel", -w / 4, 0.02, 0.952, w / 2 - 0.08, d - 0.15, 0.005),
         box("bowl1", "dark_steel", w / 4, 0.02, 0.952, w / 2 - 0.08, d - 0.15, 0.005),
         box("backsplash", "steel", 0, -d / 2 + 0.02, 1.1, w, 0.04, 0.3),
         cyl("riser", "steel", -w / 4, -d / 2 + 0.1, 1.3, 0.015, 0.7),
         cyl("spring", "dark_steel", -w / 4, -d / 2 + 0.18, 1.35, 0.03, 0.3),
         box("arm", "steel", -w / 4, -d / 2 + 0.16, 1.64, 0.02, 0.16, 0.02),
         cyl("spray_head", "black", -w / 4, -d / 2 + 0.2, 1.15, 0.022, 0.12),
         box("faucet", "steel", w / 4, -d / 2 + 0.1, 1.05, 0.03, 0.16, 0.03)]
    return v + legs("steel", w / 2 - 0.04, d / 2 - 0.04, 0.75)


def trash_can():
    """A round grey commercial trash can with a rim, a black bag showing at the top."""
    return [cyl("body", "grey_bin", 0, 0, 0.36, 0.26, 0.72),
            cyl("rim", "grey_bin", 0, 0, 0.73, 0.28, 0.03),
            cyl("bag", "black", 0, 0, 0.75, 0.24, 0.02)]


def mop_bucket():
    """A yellow mop bucket on castors with its wringer, the mop standing in it."""
    return [box("bucket", "mop_yellow", 0, 0, 0.21, 0.45, 0.35, 0.32),
            box("water", "dark_steel", -0.05, 0, 0.36, 0.3, 0.3, 0.01),
            box("wringer", "mop_yellow", 0.13, 0, 0.47, 0.17, 0.3, 0.22),
            cyl("mop_head", "mop_head", -0.08, 0, 0.3, 0.08, 0.14),
            turned(cyl("mop_handle", "light_wood", -0.14, 0, 0.95, 0.014, 1.3), "0 -0.12 0")] + \
        castors(0.19, 0.14, 0.025)


# ---- the storage room ----
def storage_shelf(w=1.5, d=0.45, fill=0):
    """A chrome wire shelving unit against a wall (behind it at -y): four shelves on four posts,
    stocked with tins, jars and cartons."""
    v = [cyl(f"post{i}", "steel", sx * (w / 2 - 0.02), sy * (d / 2 - 0.02), 0.93, 0.013, 1.86)
         for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    for i, z in enumerate((0.15, 0.65, 1.15, 1.65)):
        v.append(box(f"shelf{i}", "steel", 0, 0, z, w, d, 0.02))
        kind = (i + fill) % 3
        if kind == 0:  # tins
            v += [cyl(f"tin{i}_{k}", "can", -w / 2 + 0.12 + 0.14 * k, 0.05 * (k % 2), z + 0.09, 0.055, 0.16)
                  for k in range(int((w - 0.1) / 0.14))]
        elif kind == 1:  # cartons
            v += [box(f"carton{i}_{k}", "carton", -w / 2 + 0.22 + 0.36 * k, 0, z + 0.14, 0.32, 0.36, 0.26)
                  for k in range(int((w - 0.1) / 0.36))]
        else:  # jars
            v += [cyl(f"jar{i}_{k}", "jar_red", -w / 2 + 0.1 + 0.12 * k, -0.05 + 0.1 * (k % 2), z + 0.1, 0.045, 0.18)
                  for k in range(int((w - 0.1) / 0.12))]
    return v


def flour_sack():
    """A full sack of flour lying flat, its printed label on top."""
    return [box("body", "burlap", 0, 0, 0.09, 0.62, 0.42, 0.16),
            box("puff", "burlap", 0, 0, 0.16, 0.52, 0.34, 0.05),
            box("label", "sack_print", 0, 0, 0.186, 0.26, 0.2, 0.002),
            box("tie", "burlap", 0.33, 0, 0.09, 0.06, 0.2, 0.1)]


def crate(produce="tomato", c="crate_wood"):
    """An open produce crate of slats, full of vegetables."""
    v = [box("bottom", c, 0, 0, 0.02, 0.5, 0.35, 0.02),
         box("side_n", c, 0, 0.165, 0.14, 0.5, 0.02, 0.26),
         box("side_s", c, 0, -0.165, 0.14, 0.5, 0.02, 0.26),
         box("end_w", c, -0.24, 0, 0.14, 0.02, 0.35, 0.26),
         box("end_e", c, 0.24, 0, 0.14, 0.02, 0.35, 0.26)]
    r = 0.08 if produce == "lettuce" else 0.05
    nx, ny = (3, 2) if produce == "lettuce" else (4, 3)
    v += [sph(f"{produce}{i}_{k}", produce, -0.2 + 0.4 * (i + 0.5) / nx, -0.14 + 0.28 * (k + 0.5) / ny, 0.24 - r / 2, r)
          for i in range(nx) for k in range(ny)]
    return v


# ---- the office ----
def computer():
    """A desktop computer on a desk: the monitor facing the user (+y) on its stand, the keyboard and
    the mouse in front, the tower beside it."""
    return [box("screen", "black", 0, 0, 0.3, 0.56, 0.04, 0.34),
            box("display", "screen_lit", 0, 0.021, 0.3, 0.52, 0.002, 0.3),
            box("neck", "dark_metal", 0, -0.04, 0.1, 0.05, 0.04, 0.16),
            box("foot", "dark_metal", 0, -0.02, 0.01, 0.22, 0.16, 0.02),
            box("keyboard", "black", 0, 0.3, 0.012, 0.44, 0.14, 0.025),
            box("mouse", "black", 0.3, 0.3, 0.015, 0.06, 0.1, 0.03),
            box("tower", "black", 0.48, 0, 0.21, 0.18, 0.42, 0.42)]


# ---- the restrooms ----
def toilet():
    """A toilet: the cistern against the wall (-y), the bowl, seat and lid in front of it."""
    return [box("cistern", "porcelain", 0, -0.22, 0.62, 0.42, 0.18, 0.4),
            cyl("bowl", "porcelain", 0, 0.05, 0.2, 0.19, 0.4),
            cyl("seat", "porcelain", 0, 0.06, 0.41, 0.21, 0.03),
            turned(cyl("lid", "porcelain", 0, -0.12, 0.62, 0.2, 0.02), "-0.25 0 0"),
            box("flush", "steel", 0, -0.22, 0.83, 0.1, 0.06, 0.02)]


def urinal():
    """A wall-hung urinal (the wall behind at -y) with its chrome flush valve above."""
    return [box("back", "porcelain", 0, 0.02, 0.85, 0.38, 0.08, 0.7),
            cyl("bowl", "porcelain", 0, 0.14, 0.72, 0.16, 0.36),
            box("lip", "porcelain", 0, 0.22, 0.88, 0.3, 0.06, 0.05),
            cyl("valve", "steel", 0, 0.05, 1.35, 0.02, 0.25),
            box("lever", "steel", 0.05, 0.08, 1.25, 0.08, 0.02, 0.02)]


def sink():
    """A wall-hung wash basin (the wall behind at -y) with its tap and a soap dispenser."""
    return [box("basin", "porcelain", 0, 0.22, 0.8, 0.5, 0.42, 0.15),
            box("bowl", "tile", 0, 0.24, 0.86, 0.38, 0.3, 0.04),
            cyl("tap", "steel", 0, 0.06, 0.95, 0.02, 0.16),
            box("spout", "steel", 0, 0.12, 1.02, 0.03, 0.12, 0.02),
            cyl("trap", "steel", 0, 0.1, 0.55, 0.03, 0.35),
            box("soap", "white", 0.3, 0.045, 1.15, 0.1, 0.08, 0.18)]


def mirror(w=0.6, h=0.8):
    """A washroom mirror on the wall (behind at -y), centred on the model's height."""
    return [box("frame", "steel", 0, 0, 0, w + 0.04, 0.02, h + 0.04),
            box("glass", "mirror", 0, 0.011, 0, w, 0.004, h)]


def hand_dryer():
    """A wall-mounted electric hand dryer (the wall behind at -y), its nozzle pointing down."""
    return [box("body", "porcelain", 0, 0.08, 1.2, 0.28, 0.16, 0.3),
            box("nozzle", "steel", 0, 0.1, 1.03, 0.08, 0.08, 0.05),
            box("badge", "dark_metal", 0, 0.161, 1.26, 0.1, 0.002, 0.04)]


# ---- safety ----
def fire_extinguisher():
    """A red extinguisher on its wall bracket (the wall behind at -y)."""
    return [box("bracket", "dark_metal", 0, -0.08, 0.85, 0.1, 0.02, 0.3),
            cyl("body", "extinguisher_red", 0, 0, 0.8, 0.08, 0.5),
            sph("shoulder", "extinguisher_red", 0, 0, 1.05, 0.08),
            cyl("head", "black", 0, 0, 1.15, 0.025, 0.08),
            box("handle", "black", 0, 0.04, 1.19, 0.03, 0.12, 0.02),
            turned(cyl("hose", "black", 0.07, 0.03, 1.0, 0.012, 0.3), "0 0.3 0"),
            box("tag", "paper", 0, 0.081, 0.75, 0.06, 0.002, 0.09)]


def exit_sign():
    """The green illuminated exit sign over a door (the wall behind at -y): the running man."""
    return [box("body", "exit_green", 0, 0, 0, 0.42, 0.05, 0.16),
            box("man", "white", -0.1, 0.026, 0, 0.06, 0.004, 0.11),
            box("arrow", "white", 0.08, 0.026, 0, 0.16, 0.004, 0.04)]


def walls():
    """The outer walls with the front door (south) and the back door (north, from the storage
    room); the wall between the front and the back of house with the office and kitchen doors; the
    partitions of the office, the storage room (its door into the kitchen) and the restrooms (two
    doors off the bar, the divider between men's and women's, the cubicle partitions)."""
    v, wall = base.wall_builder(H, T)

    def with_openings(fixed, along, lo, hi, openings, c, top=LINTEL):
        """A wall along x (along = 'x', y = fixed) or y with the openings (lo..hi) in it."""
        cut = lo
        for a, b in openings:
            if along == "x":
                wall(cut, fixed, a, fixed, c=c); wall(a, fixed, b, fixed, top, H, c=c)
            else:
                wall(fixed, cut, fixed, a, c=c); wall(fixed, a, fixed, b, top, H, c=c)
            cut = b
        if along == "x": wall(cut, fixed, hi, fixed, c=c)
        else: wall(fixed, cut, fixed, hi, c=c)

    with_openings(0, "x", 0, W, (FRONT_DOOR,), "plaster", 2.3)
    with_openings(D, "x", 0, W, (BACK_DOOR,), "plaster")
    wall(0, 0, 0, D); wall(W, 0, W, D)
    with_openings(YB, "x", 0, W, (OFFICE_DOOR, KITCHEN_DOOR), "plaster")
    wall(XO, YB, XO, D, c="partition")
    with_openings(XS, "y", YB, D, (STORAGE_DOOR,), "partition")
    # the restrooms: west partition closed, doors in the north one, the divider, two cubicle walls
    wall(XR, 0, XR, YR, c="white_tile")
    with_openings(YR, "x", XR, W, (MENS_DOOR, WOMENS_DOOR), "white_tile")
    wall(XRD, 0, XRD, YR, c="white_tile")
    wall(16.2, T / 2, 16.2, 1.55, 0, 2.0, c="partition")
    wall(18.75, T / 2, 18.75, 1.55, 0, 2.0, c="partition")
    return v


def floor():
    """The floor: oak planks in front of house, red quarry tiles in the kitchen and storage room,
    white tiles in the restrooms (thin tiles laid over the slab)."""
    v = base.floor_slab("floor_restaurant", "woodfloor", W, D)
    v.append(box("kitchen", "quarry_tile", (XO + W) / 2, (YB + D) / 2, 0.0005, W - XO, D - YB, 0.001))
    v.append(box("restrooms", "tile", (XR + W) / 2, YR / 2, 0.0005, W - XR, YR, 0.001))
    return v


def entrance(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    e0, e1 = FRONT_DOOR
    add("door_1", (e0 + 0.04, 0.47, 0, WEST), base.door())  # two leaves swung open into the room
    add("door_2", (e1 - 0.04, 0.47, 0, WEST), base.door())
    add("exit_sign_1", ((e0 + e1) / 2, T / 2 + 0.03, 2.45, N), exit_sign())
    add("host_stand", (4.25, 1.6, 0, S), host_stand())
    add("waiting_bench", (T / 2 + 0.24, 2.05, 0, E), waiting_bench())
    add("coat_rack", (0.42, 3.45, 0, N), coat_rack())
    add("potted_plant_1", (0.55, 0.5, 0, N), base.plant())
    add("potted_plant_2", (4.55, 0.45, 0, N), base.plant())


def dining_room(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    t, c = [0], [0]

    def table(x, y, w, d, places):
        t[0] += 1
        add(f"dining_table_{t[0]}", (x, y, 0, N), dining_table(w, d, places))

    def chair(x, y, yaw):
        c[0] += 1
        add(f"dining_chair_{c[0]}", (x, y, 0, yaw), dining_chair())

    # tables for two under the street windows
    for i, x in enumerate((6.3, 8.7, 11.1), 1):
        add(f"window_{i}", (x, T / 2 + 0.02, 1.55, N), base.window())
        table(x, 0.85, 0.7, 0.7, two_places(0.7))
        chair(x - 0.6, 0.85, E); chair(x + 0.6, 0.85, WEST)
    add("window_4", (13.6, T / 2 + 0.02, 1.55, N), base.window())
    # tables for four
    for x, y in ((6.3, 3.4), (8.9, 3.4), (11.5, 3.4), (6.8, 6.0), (9.4, 6.0)):
        table(x, y, 0.9, 0.9, four_places(0.9, 0.9))
        chair(x - 0.65, y, E); chair(x + 0.65, y, WEST); chair(x, y - 0.65, N); chair(x, y + 0.65, S)
    # the long table for six, a high chair at its east end
    x, y = 4.0, 7.4
    table(x, y, 1.8, 0.9, [(-0.55, -0.28), (0, -0.28), (0.55, -0.28), (-0.55, 0.28), (0, 0.28), (0.55, 0.28),
                           (-0.75, 0), (0.75, 0)])
    for dx in (-0.55, 0, 0.55):
        chair(x + dx, y - 0.7, N); chair(x + dx, y + 0.7, S)
    chair(x - 1.15, y, E)
    add("high_chair_1", (x + 1.15, y, 0, WEST), high_chair())
    # two booths along the west wall, a high chair at the open end of the first
    for k, y in enumerate((5.3, 7.6), 1):
        add(f"booth_{k}", (0.8, y, 0, N), booth())
        table(0.75, y, 1.2, 0.7, [(-0.3, -0.2), (0.3, -0.2), (-0.3, 0.2), (0.3, 0.2)])
    add("high_chair_2", (1.85, 5.3, 0, WEST), high_chair())
    add("menu_board", (6.4, YB - T / 2 - 0.02, 1.75, S), menu_board())
    add("fire_extinguisher_1", (12.3, YB - T / 2 - 0.1, 0, S), fire_extinguisher())
    add("potted_plant_3", (12.9, 0.5, 0, N), base.plant())
    add("potted_plant_4", (13.2, 8.45, 0, N), base.plant())


def bar(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    add("bar_counter", (16.6, 7.3, 0, S), bar_counter(5.4))  # front to the south, the bartender north of it
    for i in range(6):
        add(f"bar_stool_{i + 1}", (14.35 + 0.9 * i, 6.45, 0, N), bar_stool())
    add("beer_tap", (15.1, 7.3, 1.11, N), beer_tap())  # the faucets toward the bartender
    add("cash_register", (18.5, 7.35, 1.11, S), cash_register())  # its screen toward the bartender
    add("bottle_shelf", (16.4, YB - T / 2 - 0.23, 0, S), bottle_shelf(3.0))
    add("television", (W - T / 2 - 0.05, 5.9, 2.05, WEST), television())


def restrooms(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    m0, m1 = MENS_DOOR
    w0, w1 = WOMENS_DOOR
    add("door_3", (m0 + 0.04, YR - 0.47, 0, WEST), base.door())  # hinged at the doorway's west side
    add("door_4", (w1 - 0.04, YR - 0.47, 0, WEST), base.door())  # hinged at its east side
    # the men's: a toilet behind the cubicle wall, a urinal, the sink and mirror on the divider
    add("toilet_1", (15.6, T / 2 + 0.31, 0, N), toilet())
    add("urinal", (16.85, T / 2 + 0.02, 0, N), urinal())
    add("sink_1", (XRD - T / 2 - 0.01, 2.9, 0, WEST), sink())
    add("mirror_1", (XRD - T / 2 - 0.02, 2.9, 1.55, WEST), mirror(0.5, 0.7))
    add("hand_dryer_1", (XRD - T / 2 - 0.01, 1.95, 0, WEST), hand_dryer())
    add("trash_can_1", (15.35, 3.2, 0, N), trash_can())
    # the women's: two toilets in cubicles, the sink and mirror on the divider, a hand dryer
    add("toilet_2", (18.1, T / 2 + 0.31, 0, N), toilet())
    add("toilet_3", (19.4, T / 2 + 0.31, 0, N), toilet())
    add("sink_2", (XRD + T / 2 + 0.01, 2.9, 0, E), sink())
    add("mirror_2", (XRD + T / 2 + 0.02, 2.9, 1.55, E), mirror(0.5, 0.7))
    add("hand_dryer_2", (W - T / 2 - 0.01, 2.7, 0, WEST), hand_dryer())
    add("trash_can_2", (19.65, 3.6, 0, N), trash_can())


def office(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    o0, o1 = OFFICE_DOOR
    add("door_5", (o1 - 0.04, YB + 0.47, 0, WEST), base.door())  # hinged at the doorway's east side
    add("desk", (1.5, D - T / 2 - 0.38, 0, N), base.desk())
    add("office_chair", (1.5, D - 1.1, 0, N), base.office_chair())
    add("computer", (1.5, D - T / 2 - 0.32, 0.75, S), computer())
    add("filing_cabinet", (3.05, D - T / 2 - 0.33, 0, S), base.filing_cabinet())
    add("window_5", (T / 2 + 0.02, 11.6, 1.5, E), base.window())
    add("trash_can_3", (0.4, 12.6, 0, N), trash_can())


def storage_room(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    b0, b1 = BACK_DOOR
    s0, s1 = STORAGE_DOOR
    add("door_6", ((b0 + b1) / 2, D - 0.06, 0, S), base.door())  # the back door, shut
    add("exit_sign_2", ((b0 + b1) / 2, D - T / 2 - 0.03, 2.45, S), exit_sign())
    add("door_7", (XS - 0.47, s1 - 0.04, 0, N), base.door())  # hinged at the doorway's north side
    add("storage_shelf_1", (XO + T / 2 + 0.24, 10.75, 0, E), storage_shelf(1.5, 0.45, 0))
    add("storage_shelf_2", (XO + T / 2 + 0.24, 12.75, 0, E), storage_shelf(1.5, 0.45, 1))
    add("storage_shelf_3", (5.2, D - T / 2 - 0.24, 0, S), storage_shelf(1.5, 0.45, 2))
    for i, (x, y, z, yaw) in enumerate(((4.45, 9.4, 0, 0), (5.1, 9.4, 0, 0), (4.75, 9.42, 0.19, 0.1),
                                        (5.75, 9.4, 0, 0)), 1):
        add(f"flour_sack_{i}", (x, y, z, yaw), flour_sack())
    for i, (x, y, z, produce, c) in enumerate(((6.25, 11.9, 0, "tomato", "crate_wood"),
                                               (6.25, 11.9, 0.28, "onion", "crate_wood"),
                                               (6.85, 11.9, 0, "potato", "crate_blue"),
                                               (6.55, 12.5, 0, "lettuce", "crate_blue")), 1):
        add(f"crate_{i}", (x, y, z, N), crate(produce, c))
    add("fire_extinguisher_2", (XS - T / 2 - 0.1, 12.9, 0, WEST), fire_extinguisher())


def kitchen(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    k0, k1 = KITCHEN_DOOR
    wall_n = D - T / 2  # the north wall's kitchen face
    add("door_8", (k1 - 0.04, YB + 0.47, 0, WEST), base.door())  # the kitchen door, hinged at its east side
    # the dish pit in the north-west, by the storage door
    add("dish_sink", (8.3, wall_n - 0.36, 0, S), dish_sink())
    add("dishwasher", (9.3, wall_n - 0.36, 0, S), dishwasher())
    add("mop_bucket", (XS + T / 2 + 0.28, 12.2, 0, E), mop_bucket())
    add("trash_can_4", (10.05, wall_n - 0.3, 0, N), trash_can())
    add("fire_extinguisher_3", (10.75, wall_n - 0.1, 0, S), fire_extinguisher())
    # the cooking line on the north wall under one hood
    add("gas_range", (11.9, wall_n - 0.43, 0, S), gas_range())
    add("deep_fryer_1", (12.8, wall_n - 0.41, 0, S), deep_fryer())
    add("deep_fryer_2", (13.28, wall_n - 0.41, 0, S), deep_fryer())
    add("convection_oven", (14.15, wall_n - 0.48, 0, S), convection_oven())
    add("exhaust_hood", (12.95, wall_n - 0.58, 0, S), exhaust_hood(3.8))
    # prep tables: two in the middle, one on the north wall
    add("prep_table_1", (12.3, 11.2, 0, N), prep_table())
    add("prep_table_2", (14.3, 11.2, 0, S), prep_table())
    add("prep_table_3", (16.3, wall_n - 0.38, 0, S), prep_table(1.8, 0.75, True))
    add("trash_can_5", (16.4, 10.0, 0, N), trash_can())
    # cold storage: the reach-in refrigerator on the east wall, the walk-in in the north-east corner
    add("refrigerator", (W - T / 2 - 0.42, 10.1, 0, WEST), refrigerator())
    add("walk_in_fridge", (W - T / 2 - 1.2, D - T / 2 - 1.2, 0, WEST), walk_in_fridge())


def main():
    out = [base.model("walls", (0, 0, 0, 0), walls()),
           base.model("floor", (0, 0, 0, 0), floor()),
           base.model("ceiling", (0, 0, 0, 0), base.ceiling_slab(W, D, H))]
    entrance(out)
    dining_room(out)
    bar(out)
    restrooms(out)
    office(out)
    storage_room(out)
    kitchen(out)
    warm, cool = "0.85 0.78 0.66", "0.8 0.8 0.78"
    lights = [base.point_light(name, x, y, H - 0.25, rgb)
              for name, x, y, rgb in (("light_entrance", 2.5, 2.2, warm), ("light_dining_sw", 6.5, 2.0, warm),
                                      ("light_dining_se", 10.5, 2.0, warm), ("light_dining_nw", 3.5, 6.5, warm),
                                      ("light_dining_ne", 8.5, 6.5, warm), ("light_bar", 16.5, 6.8, warm),
                                      ("light_mens", 16.2, 2.3, cool), ("light_womens", 18.8, 2.3, cool),
                                      ("light_office", 1.7, 11.5, cool), ("light_storage", 5.5, 11.5, cool),
                                      ("light_kitchen_w", 9.5, 11.5, cool), ("light_kitchen_m", 13.5, 11.2, cool),
                                      ("light_kitchen_e", 17.0, 10.3, cool))]
    print(base.world_sdf("semsplat_restaurant", """The semsplat restaurant: a neighbourhood restaurant of 20 m x 14 m on one floor (front of
     house: the entrance with the host stand and a waiting bench, the dining room with tables for
     two, four and six, booths and high chairs, the bar with its stools, bottle shelf and beer tap,
     the restrooms in the south-east corner; back of house: the office, the storage room with the
     back door, the commercial kitchen with the dish pit, the cooking line under the hood, prep
     tables, a reach-in refrigerator and the walk-in fridge) for measuring on a world nobody tuned
     on. Generated by restaurant_models/make_restaurant.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
