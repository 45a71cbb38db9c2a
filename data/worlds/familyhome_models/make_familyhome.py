#!/usr/bin/env python3
"""Writes data/worlds/familyhome.world: a family home of 16 m x 12 m on one floor (a bungalow with
an integral garage), the kind of house a home robot works in, for measuring the semantic stack on a
world nobody tuned on. x runs east, y north; the street front is the south wall (y = 0); the
ceiling is 2.5 m high.

South side (y < 5), west to east:
  the integral garage (x 0..4, y 0..6.4): a hatchback parked nose to the shut up-and-over garage
    door in the south wall, a chest freezer and a bicycle against the east wall, the workbench with
    its pegboard of tools on the north wall; a door into the hall (east wall) and one into the
    utility room (north wall);
  the entrance hall (x 4..7, y 0..5): the front door (south wall) standing open, a coat stand
    with coats beside it, a radiator with a mirror above it on the east wall, a house plant; the
    downstairs toilet is boxed into its north-west corner (x 4..5.8, y 3.2..5: a toilet and a
    small basin, the door in its south wall); the hall opens north into the corridor;
  the living room (x 7..12, y 0..5), entered from the hall: the sofa under the two south windows,
    the coffee table on a rug in front of it, the TV on a low TV unit against the north wall, a log
    burner on its hearth in the chimney breast of the east wall with an armchair beside it, a
    bookshelf on the west wall, a radiator, a house plant;
  the master bedroom (x 12..16, y 0..5), entered from the corridor: the double bed with its
    headboard to the east wall, a bedside table either side, the wardrobe on the west wall, a chest
    of drawers on the north wall, a radiator under the south window.
The corridor (y 5..6.4, x 4..16) joins the hall to the kitchen, the bathroom and both bedrooms.
North side (y > 6.4), west to east:
  the utility room (x 0..4, y 6.4..8.6): the washing machine, the tumble dryer and a utility base
    unit with a worktop along the west wall, the gas boiler hung on the north wall; doors into the
    garage and into the kitchen;
  the open-plan kitchen-diner (x 4..9.6, y 6.4..12, and the dining end x 0..4, y 8.6..12), entered
    from the corridor through a wide opening: the fitted kitchen along the north wall (the fridge
    freezer, base and wall units with the worktop, the integrated dishwasher, the sink under the
    window, the cooker with the extractor hood over it; the kettle and the microwave on the
    worktop), the kitchen island with three bar stools, the pedal bin, a smoke alarm; at the dining
    end the dining table with six chairs, a radiator under the window, a house plant;
  the bathroom (x 9.6..13, y 6.4..9.2), off the corridor: the bath along the north wall, the
    shower cubicle in the north-east corner, the toilet, the basin with a mirror over it;
  the home office (x 9.6..13, y 9.2..12), entered from the kitchen-diner: the desk under the north
    window with the computer monitor on it, the office chair, a bookshelf, a waste bin;
  the child's bedroom (x 13..16, y 6.4..12), off the corridor: the single bed against the north
    wall, a toy box, a small desk, a low bookshelf, a rug, a radiator.
Windows in the outer walls, internal doors standing open (openings 1.0 m wide), smoke alarms on
the ceiling of the hall, the corridor and the kitchen.

Every model is inline (boxes, cylinders, spheres), so the world needs no model path. Model names
are what a world author would type; the class is the name less its _<number> ("fridge_freezer" ->
"fridge freezer", "bar_stool_2" -> "bar stool"). The primitives and the SDF writing are the office
generator's.
Run: python3 data/worlds/familyhome_models/make_familyhome.py > data/worlds/familyhome.world"""

import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document)

W, D, H = 16.0, 12.0, 2.5  # floor width (x), depth (y), ceiling height
T = 0.1                    # wall thickness
LINTEL = 2.05              # the top of the door openings
YS, YC = 5.0, 6.4          # the corridor between y = YS and y = YC
XG = 4.0                   # the garage / utility east wall
YU = 8.6                   # the utility room | the dining end

# door openings (lo, hi) along their wall
FRONT_DOOR = (5.0, 6.0)        # x, south wall
GARAGE_DOOR = (0.4, 3.6)       # x, south wall (the up-and-over door, shut)
GARAGE_HALL = (1.6, 2.6)       # y, wall x = XG
GARAGE_UTILITY = (2.7, 3.7)    # x, wall y = YC
UTILITY_KITCHEN = (7.2, 8.2)   # y, wall x = XG
KITCHEN_ARCH = (5.0, 6.2)      # x, wall y = YC (no door)
BATH_DOOR = (10.2, 11.2)       # x, wall y = YC
CHILD_DOOR = (13.6, 14.6)      # x, wall y = YC
HALL_OPEN = (5.8, 7.0)         # x, wall y = YS (the hall opens into the corridor)
MASTER_DOOR = (12.5, 13.5)     # x, wall y = YS
LIVING_DOOR = (1.4, 2.4)       # y, wall x = 7
WC_DOOR = (4.6, 5.6)           # x, wall y = 3.2
OFFICE_DOOR = (9.5, 10.5)      # y, wall x = 9.6

N, S, E, WEST = 0.0, 3.1416, -1.5708, 1.5708  # yaw that turns a model's front (+y) north/south/east/west

base.COL.update({
    "plaster": "0.93 0.91 0.86", "garage_plaster": "0.8 0.8 0.78", "brick_breast": "0.62 0.36 0.28",
    "oak_woodfloor": "0.62 0.46 0.3", "floor_tile": "0.82 0.8 0.76", "carpet": "0.62 0.58 0.52",
    "kids_carpet": "0.5 0.62 0.72", "concrete": "0.55 0.55 0.54", "bath_tile": "0.88 0.9 0.9",
    "white": "0.96 0.96 0.95", "gloss_white": "0.98 0.98 0.97", "cream": "0.92 0.88 0.78",
    "sage": "0.56 0.64 0.52", "oak": "0.66 0.5 0.32", "walnut": "0.4 0.27 0.17", "pine": "0.82 0.68 0.46",
    "worktop_oak": "0.58 0.42 0.26", "laminate_grey": "0.45 0.46 0.47", "steel": "0.78 0.79 0.8",
    "chrome": "0.85 0.86 0.88", "black": "0.06 0.06 0.07", "dark_metal": "0.2 0.2 0.22",
    "rubber": "0.1 0.1 0.1", "glass": "0.6 0.75 0.85", "mirror": "0.8 0.85 0.88",
    "screen": "0.05 0.06 0.08", "screen_lit": "0.25 0.4 0.55", "porcelain": "0.97 0.97 0.97",
    "sofa_fabric": "0.32 0.4 0.5", "armchair_fabric": "0.6 0.45 0.3", "cushion_mustard": "0.8 0.62 0.2",
    "rug_red": "0.6 0.2 0.18", "rug_border": "0.85 0.78 0.6", "rug_kids": "0.3 0.6 0.4",
    "cast_iron": "0.12 0.12 0.12", "fire_glow": "0.95 0.5 0.1", "slate": "0.25 0.26 0.28",
    "log": "0.45 0.3 0.18", "wicker": "0.7 0.55 0.33", "leaf": "0.2 0.5 0.22", "pot": "0.6 0.3 0.18",
    "book_red": "0.65 0.15 0.12", "book_blue": "0.15 0.25 0.55", "book_green": "0.2 0.45 0.25",
    "book_cream": "0.9 0.85 0.7", "book_black": "0.12 0.12 0.12",
    "duvet": "0.9 0.9 0.86", "pillow": "0.97 0.97 0.95", "headboard_fabric": "0.55 0.55 0.6",
    "kids_duvet": "0.3 0.55 0.85", "toy_red": "0.85 0.15 0.1", "toy_yellow": "0.95 0.8 0.1",
    "toy_blue": "0.15 0.4 0.85", "toybox_blue": "0.35 0.55 0.8",
    "car_red": "0.62 0.08 0.08", "tyre": "0.08 0.08 0.08", "headlight": "0.95 0.95 0.85",
    "taillight": "0.8 0.05 0.05", "bike_green": "0.15 0.5 0.3", "pegboard": "0.7 0.58 0.4",
    "tool_red": "0.75 0.12 0.1", "tool_handle": "0.6 0.45 0.25", "garage_door": "0.88 0.88 0.86",
    "coat": "0.3 0.25 0.2", "coat2": "0.22 0.27 0.42", "scarf": "0.75 0.3 0.15",
    "radiator_white": "0.95 0.95 0.94", "hob_glass": "0.08 0.08 0.09", "ring": "0.3 0.3 0.3",
    "oven_glass": "0.15 0.17 0.2", "display_green": "0.2 0.8 0.4", "boiler_white": "0.94 0.94 0.92",
    "copper": "0.72 0.45 0.2", "fabric": "0.2 0.2 0.24", "paper": "0.96 0.96 0.94",
    "shower_tray": "0.95 0.95 0.95", "grey_plastic": "0.75 0.75 0.73", "chair_oak": "0.6 0.45 0.28",
    "seat_pad": "0.5 0.52 0.45", "freezer_white": "0.93 0.93 0.92",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
turned, along_x, along_y, castors = base.turned, base.along_x, base.along_y, base.castors


# ---- structure (local frames of the things: x right, y forward = the side a person uses, z up) ----
def door(w=0.95, h=2.0):
    """An internal door leaf standing open at 90 degrees in its doorway: a panelled white leaf with
    a chrome lever handle on each face."""
    return [box("leaf", "gloss_white", 0, 0, h / 2 + 0.01, w, 0.04, h),
            box("panel_top", "white", 0, 0.021, h * 0.72, w - 0.25, 0.002, h * 0.36),
            box("panel_bottom", "white", 0, 0.021, h * 0.28, w - 0.25, 0.002, h * 0.4),
            box("lever_a", "chrome", w / 2 - 0.1, 0.05, 1.0, 0.12, 0.02, 0.02),
            box("lever_b", "chrome", w / 2 - 0.1, -0.05, 1.0, 0.12, 0.02, 0.02)]


def front_door(w=0.95, h=2.0):
    """The front door leaf, open into the hall: a painted composite leaf with a glazed top panel,
    a letterbox, a knocker and a pull handle."""
    return [box("leaf", "sage", 0, 0, h / 2 + 0.01, w, 0.05, h),
            box("glazing", "glass", 0, 0.026, h * 0.78, w - 0.35, 0.003, 0.45),
            box("letterbox", "chrome", 0, 0.027, 1.0, 0.28, 0.004, 0.06),
            cyl("knocker", "chrome", 0, 0.03, 1.35, 0.04, 0.02),
            box("pull", "chrome", w / 2 - 0.1, 0.06, 1.05, 0.03, 0.03, 0.3)]


def garage_door(w=3.2, h=2.1):
    """The up-and-over garage door, shut in its opening: a ribbed steel panel and a handle."""
    v = [box("panel", "garage_door", 0, 0, h / 2, w, 0.05, h),
         box("handle", "dark_metal", 0, 0.04, 0.95, 0.2, 0.03, 0.05)]
    return v + [box(f"rib{i}", "steel", 0, 0.028, 0.25 + 0.4 * i, w - 0.1, 0.006, 0.04) for i in range(5)]


def window(w=1.2, h=1.2, sill=True):
    """A white uPVC casement window on a wall (the wall behind at -y), centred on the model's
    height: the frame, two panes with a mullion between, a sill below."""
    return [box("frame", "white", 0, 0, 0, w + 0.08, 0.04, h + 0.08),
            box("pane_l", "glass", -w / 4, 0.021, 0, w / 2 - 0.04, 0.004, h - 0.04),
            box("pane_r", "glass", w / 4, 0.021, 0, w / 2 - 0.04, 0.004, h - 0.04),
            box("mullion", "white", 0, 0.024, 0, 0.05, 0.01, h)] + \
        ([box("sill", "white", 0, 0.08, -h / 2 - 0.04, w + 0.14, 0.16, 0.03)] if sill else [])


def smoke_alarm():
    """A round white smoke alarm on the ceiling (the model's height is the ceiling): the base
    plate, the domed detector with its vents, the red status light."""
    return [cyl("base", "white", 0, 0, -0.01, 0.065, 0.02),
            cyl("detector", "white", 0, 0, -0.035, 0.055, 0.03),
            cyl("vent", "grey_plastic", 0, 0, -0.052, 0.035, 0.004),
            sph("led", "toy_red", 0.04, 0, -0.05, 0.006)]


def radiator(w=1.0, h=0.6):
    """A white double-panel steel radiator on a wall (behind at -y): the panels, the convector
    fins on top, the valves at both ends."""
    v = [box("panel_front", "radiator_white", 0, 0.03, 0.15 + h / 2, w, 0.025, h),
         box("panel_back", "radiator_white", 0, -0.02, 0.15 + h / 2, w, 0.025, h),
         box("grille", "grey_plastic", 0, 0.005, 0.15 + h + 0.005, w, 0.06, 0.01)]
    v += [box(f"flute{i}", "white", -w / 2 + 0.05 + 0.1 * i, 0.044, 0.15 + h / 2, 0.02, 0.004, h - 0.04)
          for i in range(int(w / 0.1))]
    return v + [cyl("valve_l", "chrome", -w / 2 - 0.04, 0.01, 0.1, 0.02, 0.12),
                cyl("valve_r", "chrome", w / 2 + 0.04, 0.01, 0.1, 0.02, 0.12)]


def mirror(w=0.6, h=0.8, c="oak"):
    """A mirror hung on a wall (behind it at -y), centred on the model's height, in a frame."""
    return [box("frame", c, 0, 0, 0, w + 0.06, 0.025, h + 0.06),
            box("glass", "mirror", 0, 0.013, 0, w, 0.004, h)]


def plant(scale=1.0):
    """A house plant: a terracotta pot, the stem and a ball of leaves."""
    s = scale
    return [cyl("pot", "pot", 0, 0, 0.15 * s, 0.15 * s, 0.3 * s), cyl("soil", "log", 0, 0, 0.3 * s, 0.13 * s, 0.01),
            cyl("stem", "walnut", 0, 0, 0.42 * s, 0.015, 0.25 * s), sph("foliage", "leaf", 0, 0, 0.7 * s, 0.3 * s)]


# ---- the hall ----
def coat_stand():
    """A freestanding wooden coat stand: a round foot, the pole, six hooks, two coats and a scarf."""
    v = [cyl("foot", "walnut", 0, 0, 0.025, 0.22, 0.05),
         cyl("pole", "walnut", 0, 0, 0.9, 0.025, 1.75),
         sph("knob", "walnut", 0, 0, 1.8, 0.04)]
    v += [box(f"hook{i}", "walnut", dx * 0.08, dy * 0.08, 1.66, 0.16 if dx else 0.02, 0.16 if dy else 0.02, 0.02)
          for i, (dx, dy) in enumerate(((1, 0), (-1, 0), (0, 1), (0, -1)))]
    return v + [box("coat0", "coat", 0.14, 0, 1.22, 0.12, 0.44, 0.8),
                box("coat1", "coat2", -0.12, 0.03, 1.3, 0.1, 0.4, 0.66),
                box("scarf", "scarf", 0, 0.12, 1.45, 0.06, 0.04, 0.38)]


# ---- the kitchen-diner ----
def kitchen_unit(w=0.8, d=0.6, top="worktop_oak"):
    """A fitted kitchen base unit against a wall (behind at -y): the cabinet on its plinth with
    doors and bar handles, a drawer line, the worktop on top (0.94 m)."""
    n = max(1, round(w / 0.6))
    v = [box("plinth", "laminate_grey", 0, 0.02, 0.05, w, d - 0.08, 0.1),
         box("carcass", "cream", 0, 0, 0.5, w, d - 0.02, 0.8),
         box("worktop", top, 0, 0.01, 0.92, w, d + 0.02, 0.04)]
    for i in range(n):
        x = -w / 2 + w / n * (i + 0.5)
        v += [box(f"door{i}", "cream", x, d / 2, 0.42, w / n - 0.01, 0.02, 0.62),
              box(f"drawer{i}", "cream", x, d / 2, 0.8, w / n - 0.01, 0.02, 0.16),
              box(f"handle{i}", "steel", x, d / 2 + 0.02, 0.8, 0.14, 0.015, 0.015),
              box(f"door_handle{i}", "steel", x + w / n / 2 - 0.06, d / 2 + 0.02, 0.6, 0.015, 0.015, 0.12)]
    return v


def wall_unit(w=1.2, d=0.34):
    """Fitted kitchen wall cupboards hung on the wall (behind at -y) over the worktop, their
    underside at the model's height: the cabinet, doors with handles at the bottom corner, an
    under-cabinet light strip."""
    n = max(1, round(w / 0.6))
    v = [box("cabinet", "cream", 0, 0, 0.35, w, d, 0.7),
         box("light_strip", "paper", 0, 0.05, -0.005, w - 0.1, 0.04, 0.01)]
    for i in range(n):
        x = -w / 2 + w / n * (i + 0.5)
        v += [box(f"door{i}", "cream", x, d / 2 + 0.01, 0.35, w / n - 0.01, 0.02, 0.68),
              box(f"handle{i}", "steel", x + w / n / 2 - 0.06, d / 2 + 0.03, 0.12, 0.015, 0.015, 0.12)]
    return v


def kitchen_sink(w=1.0, d=0.6):
    """The sink unit under the window (the wall behind at -y): the base cabinet, the worktop with
    an inset stainless bowl and a ribbed drainer, a swan-neck mixer tap, washing-up liquid."""
    return [box("plinth", "laminate_grey", 0, 0.02, 0.05, w, d - 0.08, 0.1),
            box("carcass", "cream", 0, 0, 0.5, w, d - 0.02, 0.8),
            box("door_l", "cream", -w / 4, d / 2, 0.5, w / 2 - 0.01, 0.02, 0.78),
            box("door_r", "cream", w / 4, d / 2, 0.5, w / 2 - 0.01, 0.02, 0.78),
            box("worktop", "worktop_oak", 0, 0.01, 0.92, w, d + 0.02, 0.04),
            box("bowl", "steel", -0.18, 0.03, 0.905, 0.5, 0.4, 0.04),
            box("basin_floor", "dark_metal", -0.18, 0.03, 0.885, 0.44, 0.34, 0.005),
            box("drainer", "steel", 0.3, 0.03, 0.942, 0.34, 0.42, 0.005),
            cyl("tap", "chrome", -0.18, -0.22, 1.06, 0.018, 0.28),
            box("spout", "chrome", -0.18, -0.13, 1.2, 0.025, 0.18, 0.025),
            box("lever", "chrome", -0.12, -0.22, 1.12, 0.08, 0.015, 0.015),
            cyl("washing_up_liquid", "display_green", 0.32, -0.2, 1.03, 0.03, 0.18)]


def cooker(w=0.6, d=0.6):
    """A freestanding electric cooker: the oven with its glass door and handle toward the cook
    (+y), a grill compartment above it, the ceramic hob with four rings on top, the control knobs
    along the front."""
    v = [box("body", "steel", 0, 0, 0.46, w, d, 0.88),
         box("oven_door", "black", 0, d / 2 + 0.01, 0.36, w - 0.04, 0.02, 0.5),
         box("oven_window", "oven_glass", 0, d / 2 + 0.022, 0.36, w - 0.2, 0.004, 0.3),
         along_x(cyl("oven_handle", "chrome", 0, d / 2 + 0.05, 0.63, 0.012, w - 0.12)),
         box("grill_door", "black", 0, d / 2 + 0.01, 0.75, w - 0.04, 0.02, 0.14),
         box("hob", "hob_glass", 0, 0, 0.915, w, d, 0.01),
         box("control_panel", "dark_metal", 0, d / 2 + 0.01, 0.86, w, 0.02, 0.06)]
    v += [cyl(f"ring{i}", "ring", sx * 0.14, sy * 0.13, 0.921, 0.09 if i % 2 else 0.07, 0.002)
          for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    v += [along_y(cyl(f"knob{i}", "chrome", -0.21 + 0.14 * i, d / 2 + 0.03, 0.86, 0.018, 0.03)) for i in range(4)]
    return v


def extractor_hood(w=0.6, d=0.5):
    """A chimney cooker hood on the wall (behind at -y) over the cooker: the stainless canopy with
    its grease filter and light, the chimney up to the ceiling."""
    return [box("canopy", "steel", 0, d / 2 - 0.2, 1.72, w, d, 0.08),
            box("canopy_top", "steel", 0, -0.04, 1.8, w - 0.1, 0.35, 0.1),
            box("filter", "dark_metal", 0, d / 2 - 0.2, 1.679, w - 0.06, d - 0.1, 0.003),
            box("light", "paper", 0, d / 2 - 0.08, 1.678, 0.1, 0.06, 0.003),
            box("chimney", "steel", 0, -0.05, 2.16, 0.26, 0.24, 0.62),
            box("controls", "black", 0, d / 2 + 0.051, 1.72, 0.2, 0.003, 0.03)]


def fridge_freezer(w=0.65, d=0.68, h=1.85):
    """A tall white fridge freezer: the fridge door above, the freezer door below, long vertical
    handles on the right toward the user (+y), a water dispenser panel, feet."""
    return [box("body", "gloss_white", 0, 0, h / 2 + 0.02, w, d, h),
            box("fridge_door", "white", 0, d / 2 + 0.02, 0.8 + (h - 0.78) / 2, w - 0.01, 0.04, h - 0.8),
            box("freezer_door", "white", 0, d / 2 + 0.02, 0.42, w - 0.01, 0.04, 0.74),
            box("gap", "dark_metal", 0, d / 2 + 0.02, 0.8, w - 0.01, 0.042, 0.01),
            cyl("fridge_handle", "steel", w / 2 - 0.06, d / 2 + 0.07, 1.25, 0.012, 0.5),
            cyl("freezer_handle", "steel", w / 2 - 0.06, d / 2 + 0.07, 0.6, 0.012, 0.3),
            box("dispenser", "grey_plastic", -0.12, d / 2 + 0.045, 1.25, 0.18, 0.01, 0.26),
            box("feet", "black", 0, 0, 0.01, w - 0.05, d - 0.05, 0.02)]


def dishwasher(w=0.6, d=0.58):
    """An integrated dishwasher in the run of units (the wall behind at -y): its cream door panel
    to match the units with a bar handle, the control strip along the top edge, the worktop over
    it."""
    return [box("body", "steel", 0, -0.01, 0.45, w - 0.01, d - 0.04, 0.8),
            box("door", "cream", 0, d / 2, 0.47, w - 0.01, 0.02, 0.72),
            box("kick", "laminate_grey", 0, 0.02, 0.05, w, d - 0.08, 0.1),
            box("control_strip", "dark_metal", 0, d / 2 - 0.01, 0.86, w - 0.02, 0.02, 0.04),
            box("handle", "steel", 0, d / 2 + 0.02, 0.78, 0.3, 0.015, 0.015),
            box("worktop", "worktop_oak", 0, 0.01, 0.92, w, d + 0.04, 0.04)]


def microwave():
    """A countertop microwave (stands on the worktop): the body, the dark glass door, the control
    panel on the right with a small display and buttons."""
    return [box("body", "steel", 0, 0, 0.15, 0.5, 0.38, 0.29),
            box("door", "oven_glass", -0.06, 0.191, 0.15, 0.34, 0.004, 0.24),
            box("panel", "black", 0.18, 0.191, 0.15, 0.12, 0.004, 0.24),
            box("display", "display_green", 0.18, 0.194, 0.23, 0.08, 0.002, 0.03),
            box("handle", "chrome", 0.1, 0.2, 0.15, 0.015, 0.02, 0.18),
            box("feet", "black", 0, 0, 0.005, 0.44, 0.32, 0.01)]


def kettle():
    """A cordless electric jug kettle on its power base: the body, lid, spout and handle."""
    return [cyl("power_base", "black", 0, 0, 0.01, 0.09, 0.02),
            cyl("body", "steel", 0, 0, 0.13, 0.08, 0.22),
            cyl("lid", "black", 0, 0, 0.245, 0.06, 0.01),
            box("spout", "steel", 0, 0.09, 0.2, 0.04, 0.05, 0.05),
            box("handle", "black", 0, -0.11, 0.15, 0.03, 0.03, 0.2),
            box("handle_top", "black", 0, -0.08, 0.245, 0.03, 0.08, 0.02),
            box("water_window", "glass", 0.07, 0.04, 0.12, 0.005, 0.02, 0.12)]


def kitchen_island(w=2.0, d=0.6, top_d=1.1):
    """A kitchen island: cabinets with drawers toward the kitchen units (+y), an overhanging oak
    worktop on the other side (-y) for the bar stools, a fruit bowl on it."""
    v = [box("plinth", "laminate_grey", 0, 0.25, 0.05, w - 0.04, d - 0.06, 0.1),
         box("body", "sage", 0, 0.25, 0.5, w, d, 0.8),
         box("back_panel", "sage", 0, 0.25 - d / 2, 0.5, w, 0.02, 0.8),
         box("worktop", "worktop_oak", 0, 0, 0.92, w + 0.1, top_d, 0.04),
         cyl("fruit_bowl", "white", 0.4, 0.1, 0.97, 0.14, 0.06)]
    v += [sph(f"fruit{i}", ("toy_red", "toy_yellow", "leaf")[i % 3], 0.34 + 0.06 * i, 0.1, 1.01, 0.04) for i in range(3)]
    for i in range(3):
        x = -w / 3 + w / 3 * i
        v += [box(f"drawer{i}_{k}", "sage", x, 0.25 + d / 2 + 0.01, 0.2 + 0.28 * k, w / 3 - 0.01, 0.02, 0.26)
              for k in range(3)]
        v += [box(f"handle{i}_{k}", "steel", x, 0.25 + d / 2 + 0.03, 0.28 + 0.28 * k, 0.14, 0.015, 0.015)
              for k in range(3)]
    return v


def bar_stool():
    """A kitchen bar stool: a round padded seat at counter height, a low back (at -y), four
    splayed black legs and a foot ring."""
    return [cyl("seat", "black", 0, 0, 0.64, 0.19, 0.03),
            cyl("pad", "seat_pad", 0, 0, 0.67, 0.18, 0.04),
            box("back", "black", 0, -0.17, 0.8, 0.3, 0.03, 0.18),
            cyl("foot_ring", "chrome", 0, 0, 0.28, 0.16, 0.015)] + legs("black", 0.13, 0.13, 0.63, 0.03)


def dining_table(w=1.6, d=0.9):
    """A solid oak dining table on four legs, a runner and a jug of flowers in the middle."""
    return [box("top", "oak", 0, 0, 0.74, w, d, 0.04),
            box("apron", "oak", 0, 0, 0.67, w - 0.16, d - 0.16, 0.1),
            box("runner", "cream", 0, 0, 0.762, w - 0.4, 0.3, 0.004),
            cyl("jug", "white", 0, 0, 0.84, 0.06, 0.16),
            sph("flowers", "cushion_mustard", 0, 0, 0.97, 0.1)] + legs("oak", w / 2 - 0.06, d / 2 - 0.06, 0.72, 0.07)


def dining_chair():
    """An oak dining chair with a spindle back (at -y) and a seat pad, the sitter facing +y."""
    v = [box("seat", "chair_oak", 0, 0, 0.45, 0.44, 0.42, 0.04),
         box("pad", "seat_pad", 0, 0.01, 0.48, 0.38, 0.36, 0.03),
         box("top_rail", "chair_oak", 0, -0.19, 0.88, 0.42, 0.04, 0.06)]
    v += [box(f"spindle{i}", "chair_oak", -0.14 + 0.07 * i, -0.19, 0.67, 0.02, 0.02, 0.38) for i in range(5)]
    return v + legs("chair_oak", 0.19, 0.18, 0.43, 0.04) + [
        box(f"back_post{i}", "chair_oak", s * 0.19, -0.19, 0.67, 0.04, 0.04, 0.44) for i, s in enumerate((-1, 1))]


def bin_():
    """A stainless steel pedal bin: the body, the domed lid, the foot pedal at the front (+y)."""
    return [cyl("body", "steel", 0, 0, 0.33, 0.15, 0.62),
            cyl("lid", "steel", 0, 0, 0.655, 0.152, 0.03),
            sph("lid_dome", "steel", 0, 0, 0.66, 0.03),
            box("pedal", "black", 0, 0.17, 0.04, 0.12, 0.06, 0.02),
            cyl("base_ring", "black", 0, 0, 0.015, 0.155, 0.03)]


# ---- the living room ----
def sofa(w=2.1, d=0.92):
    """A three-seater fabric sofa: the base, three seat cushions, back cushions (at -y), arms,
    two scatter cushions, short legs."""
    v = [box("base", "sofa_fabric", 0, 0, 0.25, w, d, 0.3),
         box("back", "sofa_fabric", 0, -d / 2 + 0.1, 0.6, w, 0.2, 0.5),
         box("arm_l", "sofa_fabric", -w / 2 + 0.09, 0, 0.5, 0.18, d, 0.3),
         box("arm_r", "sofa_fabric", w / 2 - 0.09, 0, 0.5, 0.18, d, 0.3)]
    cw = (w - 0.36) / 3
    v += [box(f"seat_cushion{i}", "sofa_fabric", -w / 2 + 0.18 + cw * (i + 0.5), 0.08, 0.45, cw - 0.01, d - 0.25, 0.12)
          for i in range(3)]
    v += [box(f"back_cushion{i}", "sofa_fabric", -w / 2 + 0.18 + cw * (i + 0.5), -d / 2 + 0.27, 0.7, cw - 0.02, 0.14, 0.4)
          for i in range(3)]
    v += [box("scatter_cushion_l", "cushion_mustard", -w / 2 + 0.35, -0.1, 0.68, 0.4, 0.14, 0.38),
          box("scatter_cushion_r", "cushion_mustard", w / 2 - 0.35, -0.1, 0.68, 0.4, 0.14, 0.38)]
    return v + legs("walnut", w / 2 - 0.08, d / 2 - 0.08, 0.1, 0.05)


def armchair():
    """A fabric wing armchair: the seat, the back (at -y) with wings, rolled arms, a seat cushion,
    turned legs."""
    return [box("base", "armchair_fabric", 0, 0, 0.27, 0.84, 0.82, 0.3),
            box("cushion", "armchair_fabric", 0, 0.05, 0.48, 0.56, 0.62, 0.12),
            box("back", "armchair_fabric", 0, -0.34, 0.75, 0.84, 0.16, 0.8),
            box("wing_l", "armchair_fabric", -0.37, -0.22, 0.9, 0.1, 0.3, 0.4),
            box("wing_r", "armchair_fabric", 0.37, -0.22, 0.9, 0.1, 0.3, 0.4),
            box("arm_l", "armchair_fabric", -0.36, 0.04, 0.55, 0.12, 0.74, 0.26),
            box("arm_r", "armchair_fabric", 0.36, 0.04, 0.55, 0.12, 0.74, 0.26)] + legs("walnut", 0.36, 0.35, 0.12, 0.05)


def coffee_table(w=1.1, d=0.6):
    """A low oak coffee table with a shelf underneath, magazines and a remote control on it."""
    return [box("top", "oak", 0, 0, 0.42, w, d, 0.04),
            box("shelf", "oak", 0, 0, 0.12, w - 0.1, d - 0.1, 0.02),
            box("magazine", "book_red", -0.25, 0.05, 0.445, 0.22, 0.3, 0.01),
            box("magazine2", "book_cream", -0.22, 0.02, 0.455, 0.22, 0.3, 0.01),
            box("remote", "black", 0.25, -0.05, 0.45, 0.05, 0.17, 0.02),
            cyl("mug", "white", 0.35, 0.12, 0.485, 0.04, 0.09)] + legs("oak", w / 2 - 0.05, d / 2 - 0.05, 0.4, 0.05)


def tv(w=1.23, h=0.71):
    """A 55-inch flat-screen TV on its pedestal stand (stands on the TV unit), the screen toward the
    viewers (+y)."""
    return [box("foot", "dark_metal", 0, 0, 0.01, 0.4, 0.22, 0.02),
            box("neck", "dark_metal", 0, -0.02, 0.08, 0.08, 0.04, 0.14),
            box("panel", "black", 0, 0, 0.14 + h / 2, w, 0.05, h),
            box("screen", "screen_lit", 0, 0.026, 0.14 + h / 2, w - 0.04, 0.004, h - 0.04)]


def tv_unit(w=1.6, d=0.42):
    """A low oak TV unit (media console) against the wall: two cupboards, an open middle shelf with
    a set-top box and a games console, short legs."""
    return [box("body", "oak", 0, 0, 0.3, w, d, 0.4),
            box("door_l", "walnut", -w / 3, d / 2 + 0.005, 0.3, w / 3 - 0.02, 0.01, 0.36),
            box("door_r", "walnut", w / 3, d / 2 + 0.005, 0.3, w / 3 - 0.02, 0.01, 0.36),
            box("shelf_void", "black", 0, d / 2 - 0.04, 0.3, w / 3 - 0.04, 0.02, 0.32),
            box("set_top_box", "dark_metal", 0, 0.1, 0.2, 0.3, 0.2, 0.05),
            box("console", "white", 0, 0.1, 0.35, 0.3, 0.22, 0.07)] + legs("walnut", w / 2 - 0.06, d / 2 - 0.06, 0.1, 0.04)


def bookshelf(w=0.9, d=0.3, h=1.9, c="oak"):
    """A bookcase against a wall (behind at -y): the sides, the back, shelves filled with books of
    different colours and heights."""
    n = max(2, int(h / 0.38))
    v = [box("side_l", c, -w / 2 + 0.01, 0, h / 2, 0.02, d, h),
         box("side_r", c, w / 2 - 0.01, 0, h / 2, 0.02, d, h),
         box("back", c, 0, -d / 2 + 0.005, h / 2, w, 0.01, h),
         box("top", c, 0, 0, h - 0.01, w, d, 0.02)]
    colours = ("book_red", "book_blue", "book_green", "book_cream", "book_black")
    for i in range(n):
        z = 0.04 + i * (h - 0.06) / n
        v.append(box(f"shelf{i}", c, 0, 0, z, w - 0.04, d, 0.02))
        k, x = 0, -w / 2 + 0.04
        while x < w / 2 - 0.08:
            bw, bh = 0.03 + 0.01 * ((k * 7 + i) % 3), 0.2 + 0.03 * ((k * 5 + i) % 4)
            v.append(box(f"book{i}_{k}", colours[(k + 2 * i) % 5], x + bw / 2, 0.02, z + 0.01 + bh / 2, bw, d - 0.08, bh))
            x += bw + 0.004
            k += 1
    return v


def rug(w, d, c="rug_red", border="rug_border"):
    """A rug on the floor: the border and the patterned field (a few millimetres thick)."""
    return [box("rug_border", border, 0, 0, 0.004, w, d, 0.008),
            box("rug_field", c, 0, 0, 0.0085, w - 0.16, d - 0.16, 0.002),
            box("rug_medallion", border, 0, 0, 0.0098, w * 0.3, d * 0.3, 0.0006)]


def log_burner():
    """A cast-iron multi-fuel log burner in the fireplace recess (the chimney breast behind at -y):
    the slate hearth in front, the stove on short legs with its glass door, the fire glowing
    behind it, the flue pipe into the chimney, a wicker basket of logs beside the hearth."""
    v = [box("hearth", "slate", 0, 0.1, 0.025, 1.3, 0.8, 0.05),
         box("stove", "cast_iron", 0, -0.12, 0.42, 0.46, 0.38, 0.5),
         box("stove_top", "cast_iron", 0, -0.12, 0.68, 0.5, 0.42, 0.02),
         box("door", "cast_iron", 0, 0.075, 0.4, 0.38, 0.02, 0.36),
         box("door_glass", "oven_glass", 0, 0.086, 0.42, 0.28, 0.004, 0.24),
         box("fire", "fire_glow", 0, 0.08, 0.36, 0.22, 0.004, 0.1),
         cyl("flue", "cast_iron", 0, -0.15, 0.9, 0.065, 0.42),
         box("handle", "chrome", 0.15, 0.1, 0.42, 0.02, 0.03, 0.08)]
    v += [box(f"leg{i}", "cast_iron", sx * 0.19, -0.12 + sy * 0.15, 0.11, 0.04, 0.04, 0.12)
          for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    v += [box("log_basket", "wicker", 0.9, 0.2, 0.18, 0.4, 0.32, 0.32)]
    v += [along_x(cyl(f"log{i}", "log", 0.9, 0.12 + 0.08 * i, 0.36, 0.04, 0.38)) for i in range(3)]
    return v


# ---- the utility room ----
def washing_machine():
    """A front-loading washing machine: the white cabinet, the round door with its glass porthole
    toward the user (+y), the detergent drawer and the control panel with a dial."""
    v = [box("body", "white", 0, 0, 0.43, 0.6, 0.58, 0.84),
         box("top", "white", 0, 0, 0.855, 0.6, 0.6, 0.01),
         box("control_panel", "grey_plastic", 0, 0.291, 0.76, 0.6, 0.004, 0.12),
         box("drawer", "white", -0.19, 0.3, 0.76, 0.18, 0.02, 0.08),
         box("display", "display_green", 0.1, 0.294, 0.77, 0.1, 0.002, 0.04),
         box("kick", "grey_plastic", 0, 0.29, 0.05, 0.58, 0.006, 0.08)]
    return v + [along_y(cyl("door_ring", "chrome", 0, 0.3, 0.42, 0.2, 0.03)),
                along_y(cyl("porthole", "oven_glass", 0, 0.316, 0.42, 0.15, 0.004)),
                along_y(cyl("dial", "chrome", 0.2, 0.3, 0.77, 0.03, 0.02)),
                box("laundry", "kids_duvet", 0, 0.1, 0.36, 0.3, 0.3, 0.12)]


def tumble_dryer():
    """A condenser tumble dryer: like the washer beside it, a larger plain round door, the water
    tank drawer at top left, a lint-filter hatch at the bottom."""
    return [box("body", "white", 0, 0, 0.43, 0.6, 0.58, 0.84),
            box("top", "white", 0, 0, 0.855, 0.6, 0.6, 0.01),
            box("control_panel", "grey_plastic", 0, 0.291, 0.76, 0.6, 0.004, 0.12),
            box("water_tank", "white", -0.19, 0.3, 0.76, 0.2, 0.02, 0.08),
            along_y(cyl("dial", "chrome", 0.18, 0.3, 0.77, 0.03, 0.02)),
            along_y(cyl("door", "white", 0, 0.3, 0.42, 0.22, 0.03)),
            along_y(cyl("door_window", "grey_plastic", 0, 0.316, 0.42, 0.16, 0.004)),
            box("filter_hatch", "grey_plastic", 0, 0.292, 0.1, 0.5, 0.004, 0.1)]


def boiler():
    """A wall-hung gas combi boiler (the wall behind at -y), its underside at the model's height:
    the white casing, the pressure gauge and controls behind a flap, copper pipes below, the flue
    into the wall."""
    return [box("casing", "boiler_white", 0, 0, 0.36, 0.42, 0.3, 0.72),
            box("flap", "grey_plastic", 0, 0.151, 0.06, 0.36, 0.004, 0.1),
            cyl("gauge", "white", -0.1, 0.153, 0.07, 0.03, 0.004),
            box("display", "display_green", 0.08, 0.153, 0.07, 0.08, 0.002, 0.03),
            box("flue", "white", 0, -0.05, 0.8, 0.12, 0.2, 0.16)] + \
        [cyl(f"pipe{i}", "copper", -0.15 + 0.075 * i, -0.05, -0.2, 0.011, 0.4) for i in range(5)]


# ---- the home office ----
def desk(w=1.4, d=0.7):
    """A home-office desk: a white top on an oak frame, a drawer pedestal on the right."""
    return [box("top", "white", 0, 0, 0.735, w, d, 0.03),
            box("pedestal", "white", w / 2 - 0.22, 0, 0.36, 0.4, d - 0.05, 0.7),
            box("drawer_line", "grey_plastic", w / 2 - 0.22, d / 2 - 0.02, 0.5, 0.36, 0.005, 0.005),
            box("modesty_panel", "oak", -0.2, -d / 2 + 0.02, 0.5, w - 0.5, 0.02, 0.4)] + \
        [box(f"leg{i}", "oak", -w / 2 + 0.03, s * (d / 2 - 0.03), 0.36, 0.04, 0.04, 0.72) for i, s in enumerate((-1, 1))]


def office_chair():
    """A swivel office chair: a mesh back (at -y), the padded seat, arms, the gas column, five
    castors on a star base."""
    v = [box("seat", "fabric", 0, 0, 0.48, 0.5, 0.48, 0.08),
         box("back", "fabric", 0, -0.24, 0.82, 0.46, 0.04, 0.55),
         box("lumbar", "black", 0, -0.23, 0.66, 0.44, 0.03, 0.08),
         cyl("column", "dark_metal", 0, 0, 0.27, 0.025, 0.36),
         box("arm_l", "black", -0.27, 0, 0.64, 0.04, 0.3, 0.04),
         box("arm_r", "black", 0.27, 0, 0.64, 0.04, 0.3, 0.04),
         box("arm_post_l", "black", -0.27, 0, 0.56, 0.03, 0.03, 0.14),
         box("arm_post_r", "black", 0.27, 0, 0.56, 0.03, 0.03, 0.14)]
    import math
    for i in range(5):
        a = 2 * math.pi * i / 5
        v.append(turned(box(f"spoke{i}", "dark_metal", 0.14 * math.cos(a), 0.14 * math.sin(a), 0.07, 0.28, 0.04, 0.03),
                        f"0 0 {a:.4f}"))
        v.append(sph(f"castor{i}", "rubber", 0.29 * math.cos(a), 0.29 * math.sin(a), 0.03, 0.03))
    return v


def monitor():
    """A 27-inch computer monitor on its stand (stands on the desk), the screen toward the user
    (+y), a keyboard and a mouse in front of it."""
    return [box("foot", "dark_metal", 0, -0.05, 0.01, 0.24, 0.18, 0.02),
            box("neck", "dark_metal", 0, -0.08, 0.14, 0.05, 0.03, 0.24),
            box("panel", "black", 0, -0.05, 0.37, 0.62, 0.03, 0.37),
            box("screen", "screen_lit", 0, -0.034, 0.375, 0.59, 0.002, 0.33),
            box("keyboard", "black", 0, 0.22, 0.012, 0.44, 0.14, 0.025),
            box("mouse", "black", 0.32, 0.22, 0.015, 0.06, 0.1, 0.03)]


# ---- the bedrooms ----
def double_bed(w=1.5, l=2.1):
    """A double bed (1.5 m wide): the upholstered headboard at -y, the divan base, the mattress, the duvet,
    a throw across it, two pillows; the foot of the bed at +y."""
    return [box("headboard", "headboard_fabric", 0, -l / 2 + 0.04, 0.65, w + 0.1, 0.08, 1.3),
            box("base", "headboard_fabric", 0, 0.04, 0.22, w, l - 0.08, 0.36),
            box("mattress", "white", 0, 0.04, 0.49, w - 0.04, l - 0.12, 0.2),
            box("duvet", "duvet", 0, 0.22, 0.6, w + 0.02, l - 0.5, 0.05),
            box("throw", "cushion_mustard", 0, l / 2 - 0.35, 0.63, w + 0.04, 0.4, 0.02),
            box("pillow_l", "pillow", -w / 4, -l / 2 + 0.3, 0.64, w / 2 - 0.1, 0.4, 0.12),
            box("pillow_r", "pillow", w / 4, -l / 2 + 0.3, 0.64, w / 2 - 0.1, 0.4, 0.12)]


def single_bed(w=0.95, l=2.0):
    """A child's single bed: a pine frame with a headboard (at -y) and a low footboard, the
    mattress, a blue duvet, a pillow and a teddy bear."""
    return [box("headboard", "pine", 0, -l / 2 + 0.03, 0.45, w, 0.05, 0.9),
            box("footboard", "pine", 0, l / 2 - 0.03, 0.3, w, 0.05, 0.6),
            box("rail_l", "pine", -w / 2 + 0.03, 0, 0.3, 0.05, l - 0.1, 0.15),
            box("rail_r", "pine", w / 2 - 0.03, 0, 0.3, 0.05, l - 0.1, 0.15),
            box("mattress", "white", 0, 0, 0.42, w - 0.1, l - 0.12, 0.18),
            box("duvet", "kids_duvet", 0, 0.15, 0.53, w - 0.06, l - 0.45, 0.05),
            box("pillow", "pillow", 0, -l / 2 + 0.25, 0.56, w - 0.25, 0.32, 0.1),
            sph("teddy", "armchair_fabric", 0.2, -l / 2 + 0.5, 0.63, 0.1),
            sph("teddy_head", "armchair_fabric", 0.2, -l / 2 + 0.5, 0.78, 0.07)] + legs("pine", w / 2 - 0.03, l / 2 - 0.03, 0.24, 0.05)


def bedside_table():
    """A small oak bedside table with a drawer, a reading lamp and an alarm clock on top."""
    return [box("body", "oak", 0, 0, 0.33, 0.45, 0.4, 0.5),
            box("drawer", "walnut", 0, 0.201, 0.46, 0.4, 0.005, 0.14),
            cyl("knob", "chrome", 0, 0.21, 0.46, 0.015, 0.02),
            cyl("lamp_base", "cream", -0.1, -0.05, 0.65, 0.06, 0.14),
            cyl("lamp_shade", "cream", -0.1, -0.05, 0.8, 0.11, 0.16),
            box("clock", "black", 0.12, 0.05, 0.62, 0.1, 0.05, 0.07)] + legs("oak", 0.19, 0.16, 0.08, 0.04)


def wardrobe(w=1.8, d=0.6, h=2.1):
    """A double wardrobe against a wall (behind at -y): three hinged white doors with long handles,
    a plinth and a cornice."""
    v = [box("carcass", "white", 0, 0, h / 2, w, d, h),
         box("plinth", "oak", 0, 0.01, 0.04, w, d - 0.02, 0.08),
         box("cornice", "oak", 0, 0.01, h - 0.02, w + 0.04, d + 0.02, 0.04)]
    for i in range(3):
        x = -w / 3 + w / 3 * i
        v += [box(f"door{i}", "gloss_white", x, d / 2 + 0.01, h / 2, w / 3 - 0.01, 0.02, h - 0.14),
              cyl(f"handle{i}", "chrome", x + (0.24 if i < 2 else -0.24), d / 2 + 0.04, 1.1, 0.01, 0.4)]
    return v


def chest_of_drawers(w=0.9, d=0.45, h=0.95):
    """An oak chest of drawers: two small drawers over three long ones, wooden knobs, a jewellery
    box and a framed photo on top."""
    v = [box("carcass", "oak", 0, 0, h / 2 + 0.05, w, d, h - 0.1),
         box("top", "oak", 0, 0, h - 0.03, w + 0.02, d + 0.02, 0.03)] + legs("walnut", w / 2 - 0.05, d / 2 - 0.05, 0.1, 0.05)
    for k in range(3):
        z = 0.2 + 0.22 * k
        v += [box(f"drawer{k}", "walnut", 0, d / 2 + 0.005, z, w - 0.04, 0.01, 0.2),
              cyl(f"knob{k}_l", "walnut", -w / 4, d / 2 + 0.02, z, 0.018, 0.02),
              cyl(f"knob{k}_r", "walnut", w / 4, d / 2 + 0.02, z, 0.018, 0.02)]
    for k, s in enumerate((-1, 1)):
        v += [box(f"small_drawer{k}", "walnut", s * w / 4, d / 2 + 0.005, 0.85, w / 2 - 0.03, 0.01, 0.14),
              cyl(f"small_knob{k}", "walnut", s * w / 4, d / 2 + 0.02, 0.85, 0.018, 0.02)]
    return v + [box("jewellery_box", "book_red", -0.2, 0, 0.98, 0.2, 0.14, 0.08),
                box("photo_frame", "black", 0.2, -0.1, 1.05, 0.18, 0.02, 0.22)]


def toy_box():
    """A painted wooden toy box with its lid propped open (at -y), toys heaped inside: blocks, a
    ball, a toy truck."""
    return [box("body", "toybox_blue", 0, 0, 0.23, 0.8, 0.45, 0.42),
            box("rim", "white", 0, 0, 0.445, 0.82, 0.47, 0.03),
            turned(box("lid", "toybox_blue", 0, -0.3, 0.6, 0.82, 0.03, 0.45), "0.35 0 0"),
            sph("ball", "toy_red", -0.2, 0.05, 0.5, 0.1),
            box("block0", "toy_yellow", 0.05, 0.05, 0.47, 0.1, 0.1, 0.1),
            box("block1", "toy_blue", 0.15, -0.05, 0.47, 0.1, 0.1, 0.1),
            box("truck", "toy_red", 0.25, 0.08, 0.48, 0.2, 0.1, 0.1),
            box("handle_l", "white", -0.41, 0, 0.32, 0.02, 0.12, 0.04),
            box("handle_r", "white", 0.41, 0, 0.32, 0.02, 0.12, 0.04)]


def kids_desk():
    """A small pine desk for a child with a pot of crayons and a drawing pad on it."""
    return [box("top", "pine", 0, 0, 0.6, 1.0, 0.5, 0.03),
            box("drawer", "pine", 0.3, 0.0, 0.53, 0.34, 0.44, 0.1),
            cyl("crayons", "toy_yellow", -0.35, -0.1, 0.66, 0.04, 0.09),
            box("drawing_pad", "paper", 0, 0.05, 0.618, 0.3, 0.22, 0.005)] + legs("pine", 0.46, 0.21, 0.585, 0.04)


# ---- the bathrooms ----
def bath(w=1.7, d=0.75):
    """A white acrylic bath against the wall (behind at -y): the tub with its rolled rim, the side
    panel toward the user (+y), chrome mixer taps at one end."""
    return [box("panel", "gloss_white", 0, 0.01, 0.27, w, d - 0.02, 0.54),
            box("rim", "porcelain", 0, 0, 0.555, w, d, 0.03),
            box("tub", "bath_tile", 0, 0, 0.56, w - 0.16, d - 0.16, 0.01),
            cyl("tap_l", "chrome", -w / 2 + 0.1, -0.1, 0.62, 0.018, 0.1),
            cyl("tap_r", "chrome", -w / 2 + 0.1, 0.1, 0.62, 0.018, 0.1),
            box("spout", "chrome", -w / 2 + 0.14, 0, 0.65, 0.12, 0.03, 0.03)]


def shower(w=0.9, d=0.9):
    """A corner shower cubicle: the low tray, two clear glass walls with a chrome frame (the room's
    walls behind and beside it), the riser rail with the shower head, a mixer valve, a shelf with a
    shampoo bottle."""
    return [box("tray", "shower_tray", 0, 0, 0.03, w, d, 0.06),
            box("glass_front", "glass", 0.05, d / 2 - 0.01, 1.02, w - 0.1, 0.008, 1.9),
            box("glass_side", "glass", -w / 2 + 0.01, 0.0, 1.02, 0.008, d - 0.02, 1.9),
            box("frame_top", "chrome", 0, d / 2 - 0.01, 1.98, w, 0.02, 0.02),
            box("frame_side_top", "chrome", -w / 2 + 0.01, 0, 1.98, 0.02, d, 0.02),
            cyl("rail", "chrome", 0.15, -d / 2 + 0.04, 1.3, 0.012, 0.9),
            along_y(cyl("head", "chrome", 0.15, -d / 2 + 0.12, 1.95, 0.07, 0.02)),
            box("arm", "chrome", 0.15, -d / 2 + 0.08, 1.97, 0.02, 0.1, 0.02),
            box("valve", "chrome", -0.15, -d / 2 + 0.03, 1.1, 0.14, 0.04, 0.14),
            box("shelf", "chrome", w / 2 - 0.15, -d / 2 + 0.08, 1.4, 0.2, 0.12, 0.01),
            cyl("shampoo", "toy_blue", w / 2 - 0.15, -d / 2 + 0.08, 1.49, 0.03, 0.17)]


def toilet():
    """A close-coupled toilet: the cistern against the wall (at -y) with a push-button flush, the
    pedestal and bowl, the seat and the lid raised."""
    return [box("cistern", "porcelain", 0, -0.24, 0.6, 0.38, 0.17, 0.4),
            cyl("flush_button", "chrome", 0, -0.24, 0.805, 0.03, 0.01),
            cyl("pedestal", "porcelain", 0, 0.02, 0.18, 0.13, 0.36),
            cyl("bowl", "porcelain", 0, 0.06, 0.33, 0.19, 0.1),
            cyl("seat", "white", 0, 0.06, 0.395, 0.2, 0.025),
            box("lid", "white", 0, -0.12, 0.6, 0.36, 0.025, 0.4),
            cyl("toilet_roll", "paper", 0.35, -0.2, 0.6, 0.055, 0.1)]


def basin(w=0.55, d=0.45, pedestal=True):
    """A white ceramic wash basin on a pedestal (or wall-hung, small) against the wall (behind at
    -y): the bowl, a chrome mixer tap, a soap dispenser."""
    v = [box("basin", "porcelain", 0, 0.0, 0.8, w, d, 0.16),
         box("bowl", "bath_tile", 0, 0.02, 0.875, w - 0.12, d - 0.14, 0.01),
         cyl("tap", "chrome", 0, -d / 2 + 0.06, 0.93, 0.018, 0.12),
         box("spout", "chrome", 0, -d / 2 + 0.11, 0.98, 0.025, 0.1, 0.02),
         cyl("soap", "sage", w / 2 - 0.08, -d / 2 + 0.07, 0.94, 0.03, 0.12)]
    if pedestal:
        v.append(box("pedestal", "porcelain", 0, -0.06, 0.36, 0.2, 0.2, 0.72))
    else:
        v.append(cyl("trap", "chrome", 0, -0.1, 0.58, 0.03, 0.28))
    return v


# ---- the garage ----
def car(w=1.78, l=4.25):
    """A red five-door hatchback (the front at +y): the body, the cabin with its windscreen and side
    windows, four wheels, headlights, tail lights, wing mirrors, number plates."""
    v = [box("body", "car_red", 0, 0, 0.55, w, l, 0.6),
         box("bonnet_slope", "car_red", 0, l / 2 - 0.55, 0.86, w - 0.08, 1.0, 0.05),
         box("cabin", "car_red", 0, -0.35, 1.13, w - 0.16, 2.2, 0.56),
         box("windscreen", "glass", 0, 0.76, 1.13, w - 0.24, 0.02, 0.5),
         box("rear_window", "glass", 0, -1.46, 1.13, w - 0.26, 0.02, 0.46),
         box("window_l", "glass", -w / 2 + 0.075, -0.35, 1.15, 0.01, 2.0, 0.4),
         box("window_r", "glass", w / 2 - 0.075, -0.35, 1.15, 0.01, 2.0, 0.4),
         box("headlight_l", "headlight", -0.6, l / 2 + 0.005, 0.7, 0.34, 0.01, 0.12),
         box("headlight_r", "headlight", 0.6, l / 2 + 0.005, 0.7, 0.34, 0.01, 0.12),
         box("taillight_l", "taillight", -0.68, -l / 2 - 0.005, 0.78, 0.26, 0.01, 0.14),
         box("taillight_r", "taillight", 0.68, -l / 2 - 0.005, 0.78, 0.26, 0.01, 0.14),
         box("plate_front", "white", 0, l / 2 + 0.006, 0.45, 0.52, 0.01, 0.11),
         box("plate_rear", "toy_yellow", 0, -l / 2 - 0.006, 0.58, 0.52, 0.01, 0.11),
         box("bumper_front", "black", 0, l / 2 - 0.02, 0.32, w, 0.06, 0.14),
         box("bumper_rear", "black", 0, -l / 2 + 0.02, 0.32, w, 0.06, 0.14),
         box("mirror_l", "car_red", -w / 2 - 0.06, 0.65, 0.98, 0.12, 0.08, 0.1),
         box("mirror_r", "car_red", w / 2 + 0.06, 0.65, 0.98, 0.12, 0.08, 0.1)]
    for i, (sx, sy) in enumerate(((-1, 1), (1, 1), (-1, -1), (1, -1))):
        v += [along_x(cyl(f"tyre{i}", "tyre", sx * (w / 2 - 0.1), sy * 1.3, 0.31, 0.31, 0.2)),
              along_x(cyl(f"hub{i}", "steel", sx * (w / 2 - 0.0), sy * 1.3, 0.31, 0.17, 0.01))]
    return v


def bicycle():
    """An adult's bicycle standing on its kickstand, along y: two wheels with tyres, the green frame,
    the saddle, the handlebars."""
    v = []
    for i, y in enumerate((-0.52, 0.52)):
        v += [along_x(cyl(f"tyre{i}", "tyre", 0, y, 0.34, 0.34, 0.04)),
              along_x(cyl(f"rim{i}", "steel", 0, y, 0.34, 0.3, 0.045)),
              along_x(cyl(f"hub{i}", "dark_metal", 0, y, 0.34, 0.04, 0.08))]
    v += [turned(box("down_tube", "bike_green", 0, 0.15, 0.55, 0.04, 0.04, 0.75), "-0.85 0 0"),
          box("top_tube", "bike_green", 0, 0.05, 0.82, 0.04, 0.6, 0.04),
          turned(box("seat_tube", "bike_green", 0, -0.2, 0.6, 0.04, 0.04, 0.6), "0.25 0 0"),
          turned(box("chain_stay", "bike_green", 0, -0.36, 0.36, 0.03, 0.35, 0.03), "0 0 0"),
          turned(box("fork", "bike_green", 0, 0.47, 0.55, 0.03, 0.03, 0.5), "-0.2 0 0"),
          box("saddle", "black", 0, -0.27, 0.95, 0.14, 0.26, 0.06),
          box("stem", "dark_metal", 0, 0.42, 0.92, 0.03, 0.03, 0.22),
          box("handlebar", "dark_metal", 0, 0.42, 1.03, 0.58, 0.03, 0.03),
          box("grip_l", "black", -0.27, 0.42, 1.03, 0.1, 0.035, 0.035),
          box("grip_r", "black", 0.27, 0.42, 1.03, 0.1, 0.035, 0.035),
          along_x(cyl("chainring", "dark_metal", 0.02, -0.05, 0.3, 0.1, 0.01)),
          box("kickstand", "dark_metal", 0.08, -0.1, 0.15, 0.02, 0.02, 0.3)]
    return v


def workbench(w=1.8, d=0.6):
    """A garage workbench against the wall (behind at -y): a thick beech top on a steel frame with a
    lower shelf, a vice at the front-left, a toolbox on the shelf, a pegboard on the wall above
    with hammers, spanners, a saw and screwdrivers hung on it."""
    v = [box("top", "pine", 0, 0, 0.88, w, d, 0.05),
         box("shelf", "pine", 0, 0, 0.2, w - 0.06, d - 0.06, 0.02),
         box("vice_body", "dark_metal", -w / 2 + 0.2, d / 2 - 0.05, 0.95, 0.16, 0.18, 0.1),
         box("vice_jaw", "dark_metal", -w / 2 + 0.2, d / 2 + 0.06, 0.96, 0.16, 0.04, 0.12),
         box("toolbox", "tool_red", 0.4, 0, 0.33, 0.5, 0.25, 0.24),
         box("pegboard", "pegboard", 0, -d / 2 + 0.01, 1.55, w, 0.02, 0.9)] + legs("dark_metal", w / 2 - 0.04, d / 2 - 0.04, 0.86, 0.05)
    px = -w / 2 + 0.2
    for i in range(6):
        x = px + i * 0.28
        if i % 3 == 0:  # hammer
            v += [box(f"hammer_handle{i}", "tool_handle", x, -d / 2 + 0.04, 1.45, 0.03, 0.02, 0.3),
                  box(f"hammer_head{i}", "dark_metal", x, -d / 2 + 0.04, 1.62, 0.12, 0.03, 0.04)]
        elif i % 3 == 1:  # spanner set
            v += [box(f"spanner{i}_{k}", "chrome", x - 0.06 + 0.04 * k, -d / 2 + 0.03, 1.5, 0.02, 0.01, 0.2 + 0.03 * k)
                  for k in range(4)]
        else:  # screwdrivers
            v += [box(f"screwdriver{i}_{k}", "tool_red", x - 0.04 + 0.04 * k, -d / 2 + 0.035, 1.5, 0.025, 0.025, 0.22)
                  for k in range(3)]
    return v + [box("saw", "steel", w / 2 - 0.2, -d / 2 + 0.03, 1.75, 0.5, 0.01, 0.14),
                box("saw_handle", "tool_handle", w / 2 - 0.5, -d / 2 + 0.03, 1.75, 0.12, 0.02, 0.12)]


def chest_freezer(w=1.0, d=0.65, h=0.85):
    """A white chest freezer: the cabinet, the lid with a recessed handle at the front (+y), the
    power lights, the lid shut."""
    return [box("cabinet", "freezer_white", 0, 0, h / 2, w, d, h - 0.02),
            box("lid", "white", 0, 0, h - 0.005, w + 0.01, d + 0.01, 0.05),
            box("handle", "grey_plastic", 0, d / 2 + 0.01, h - 0.04, 0.3, 0.02, 0.04),
            box("lights", "display_green", w / 2 - 0.12, d / 2 + 0.002, h - 0.12, 0.06, 0.004, 0.02),
            box("base", "grey_plastic", 0, 0, 0.02, w - 0.04, d - 0.04, 0.04)]


# ---- the house ----
def walls():
    """The outer walls (the front door and the garage door in the south wall); the corridor's walls
    (the hall opening, the master bedroom door, the kitchen opening, the bathroom and child's
    bedroom doors); the garage's and the utility room's walls; the downstairs toilet boxed into the
    hall; the walls between the living room and the master bedroom, the kitchen and the bathroom
    and office, the bathroom and the office, the child's bedroom; the chimney breast with its
    fireplace recess in the living room."""
    v, wall = base.wall_builder(H, T)

    def with_openings(fixed, along, lo, hi, openings, c="plaster", top=LINTEL):
        cut = lo
        for op in openings:
            a, b = op[0], op[1]
            t = op[2] if len(op) > 2 else top
            if along == "x":
                wall(cut, fixed, a, fixed, c=c); wall(a, fixed, b, fixed, t, H, c=c)
            else:
                wall(fixed, cut, fixed, a, c=c); wall(fixed, a, fixed, b, t, H, c=c)
            cut = b
        if along == "x": wall(cut, fixed, hi, fixed, c=c)
        else: wall(fixed, cut, fixed, hi, c=c)

    with_openings(0, "x", 0, W, ((*GARAGE_DOOR, 2.1), (*FRONT_DOOR, LINTEL)))
    wall(0, D, W, D); wall(0, 0, 0, D); wall(W, 0, W, D)
    with_openings(XG, "y", 0, YU, (GARAGE_HALL, UTILITY_KITCHEN))
    with_openings(YC, "x", 0, W, (GARAGE_UTILITY, KITCHEN_ARCH, BATH_DOOR, CHILD_DOOR))
    wall(0, YU, XG, YU)                                    # utility | dining end
    with_openings(YS, "x", XG, W, (HALL_OPEN, MASTER_DOOR))
    wall(5.8, 3.2, 5.8, YS)                                # the downstairs toilet: east wall
    with_openings(3.2, "x", XG, 5.8, (WC_DOOR,))           # and its south wall with the door
    with_openings(7.0, "y", 0, YS, (LIVING_DOOR,))         # hall | living room
    wall(12.0, 0, 12.0, YS)                                # living room | master bedroom
    with_openings(9.6, "y", YC, D, (OFFICE_DOOR,))         # kitchen | bathroom, office
    wall(9.6, 9.2, 13.0, 9.2)                              # bathroom | office
    wall(13.0, YC, 13.0, D)                                # bathroom, office | child's bedroom
    # the chimney breast on the living room's east wall, its fireplace recess (y 2.2..3.0)
    for k, (y0, y1) in enumerate(((1.85, 2.2), (3.0, 3.35))):
        v.append(box(f"chimney_breast_jamb{k}", "brick_breast", 11.75, (y0 + y1) / 2, H / 2, 0.4, y1 - y0, H))
    v.append(box("chimney_breast_top", "brick_breast", 11.75, 2.6, (1.1 + H) / 2, 0.4, 0.8, H - 1.1))
    v.append(box("splashback_tiles_kitchen", "bath_tile", (4.7 + 9.55) / 2, D - T / 2 - 0.005, 1.2, 9.55 - 4.7, 0.01, 0.5))
    v.append(box("splashback_tiles_utility", "bath_tile", T / 2 + 0.005, 8.17, 1.2, 0.01, 0.74, 0.5))
    v.append(box("chimney_breast_mantel", "oak", 11.53, 2.6, 1.12, 0.1, 1.6, 0.06))
    return v


def floor():
    """The floor: oak planks in the hall, the living room and the corridor; porcelain tiles in the
    kitchen-diner and the utility room; carpet in the bedrooms and the office; bathroom tiles in the
    bathroom and the downstairs toilet; bare concrete in the garage (finishes laid over the slab)."""
    v = base.floor_slab("floor_slab", "concrete", W, D)

    def lay(name, c, x0, y0, x1, y1):
        v.append(box(name, c, (x0 + x1) / 2, (y0 + y1) / 2, 0.0005, x1 - x0, y1 - y0, 0.001))
    lay("hall", "oak_woodfloor", XG, 0, 7.0, YS)
    lay("corridor", "oak_woodfloor", XG, YS, W, YC)
    lay("living", "oak_woodfloor", 7.0, 0, 12.0, YS)
    lay("master", "carpet", 12.0, 0, W, YS)
    lay("utility", "floor_tile", 0, YC, XG, YU)
    lay("kitchen", "floor_tile", XG, YC, 9.6, D)
    lay("dining", "floor_tile", 0, YU, XG, D)
    lay("bathroom", "bath_tile", 9.6, YC, 13.0, 9.2)
    lay("downstairs_wc", "bath_tile", XG, 3.2, 5.8, YS)
    lay("office", "carpet", 9.6, 9.2, 13.0, D)
    lay("child", "kids_carpet", 13.0, YC, W, D)
    return v


def south_rooms(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    ws = T / 2  # the south wall's inner face
    # the garage
    g0, g1 = GARAGE_DOOR
    add("door_1", ((g0 + g1) / 2, 0.0, 0, N), garage_door(g1 - g0 - 0.02))
    add("car", (1.3, 2.62, 0, S), car())  # nose to the garage door
    add("chest_freezer", (XG - T / 2 - 0.34, 0.9, 0, WEST), chest_freezer())
    add("bicycle", (XG - T / 2 - 0.33, 4.15, 0, N), bicycle())
    add("workbench", (1.25, YC - T / 2 - 0.31, 0, S), workbench())
    # the hall
    f0, f1 = FRONT_DOOR
    add("door_2", (f1 - 0.04, ws + 0.49, 0, WEST), front_door())  # the front door, open, hinged at its east side
    h0, h1 = GARAGE_HALL
    add("door_3", (XG - T / 2 - 0.49, h1 - 0.04, 0, N), door())  # garage -> hall, open into the garage
    add("coat_stand", (6.55, 0.5, 0, N), coat_stand())
    add("radiator_1", (7.0 - T / 2 - 0.06, 3.9, 0, WEST), radiator(1.0))
    add("mirror_1", (7.0 - T / 2 - 0.015, 3.9, 1.55, WEST), mirror(0.6, 0.85))
    add("plant_1", (4.42, 0.45, 0, N), plant(0.9))
    add("smoke_alarm_1", (5.6, 1.8, H, N), smoke_alarm())
    # the downstairs toilet
    c0, c1 = WC_DOOR
    add("door_4", (c1 - 0.04, 3.2 - T / 2 - 0.49, 0, WEST), door())  # opens out into the hall
    add("toilet_1", (XG + T / 2 + 0.34, 4.35, 0, E), toilet())
    add("basin_1", (5.3, YS - T / 2 - 0.17, 0, S), basin(0.42, 0.32, pedestal=False))
    # the living room
    l0, l1 = LIVING_DOOR
    add("door_5", (7.0 + T / 2 + 0.49, l1 - 0.04, 0, N), door())
    add("window_1", (8.3, ws + 0.02, 1.5, N), window(1.2, 1.2))
    add("window_2", (10.5, ws + 0.02, 1.5, N), window(1.2, 1.2))
    add("sofa", (9.3, 0.72, 0, N), sofa())
    add("rug_1", (9.3, 2.25, 0, N), rug(2.4, 1.7))
    add("coffee_table", (9.3, 2.15, 0.01, N), coffee_table())
    add("tv_unit", (9.3, YS - T / 2 - 0.23, 0, S), tv_unit())
    add("tv", (9.3, YS - T / 2 - 0.2, 0.5, S), tv())
    add("log_burner", (11.55, 2.6, 0, WEST), log_burner())  # its origin at the breast's face
    add("armchair", (11.1, 4.15, 0, WEST), armchair())
    add("bookshelf_1", (7.0 + T / 2 + 0.16, 4.15, 0, E), bookshelf(0.9, 0.3, 1.9))
    add("radiator_2", (7.0 + T / 2 + 0.06, 0.75, 0, E), radiator(0.8))
    add("plant_2", (11.6, 0.45, 0, N), plant(1.1))
    # the master bedroom
    m0, m1 = MASTER_DOOR
    add("door_6", (m1 - 0.04, YS - T / 2 - 0.49, 0, WEST), door())
    add("window_3", (14.0, ws + 0.02, 1.5, N), window(1.2, 1.2))
    add("window_4", (W - T / 2 - 0.02, 4.3, 1.5, WEST), window(0.9, 1.2))
    add("double_bed", (W - T / 2 - 1.06, 2.4, 0, WEST), double_bed())
    add("bedside_table_1", (W - T / 2 - 0.21, 1.35, 0, WEST), bedside_table())
    add("bedside_table_2", (W - T / 2 - 0.21, 3.45, 0, WEST), bedside_table())
    add("wardrobe", (12.0 + T / 2 + 0.31, 2.2, 0, E), wardrobe())
    add("chest_of_drawers", (14.8, YS - T / 2 - 0.24, 0, S), chest_of_drawers())
    add("radiator_3", (14.0, ws + 0.06, 0, N), radiator(1.0))
    add("smoke_alarm_2", (10.5, (YS + YC) / 2, H, N), smoke_alarm())  # the corridor


def north_rooms(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    wn = D - T / 2  # the north wall's inner face
    # the utility room
    u0, u1 = GARAGE_UTILITY
    add("door_7", (u0 + 0.04, YC + T / 2 + 0.49, 0, WEST), door())  # garage -> utility, hinged at the west
    k0, k1 = UTILITY_KITCHEN
    add("door_8", (XG - T / 2 - 0.49, k1 - 0.04, 0, N), door())  # utility -> kitchen, open into the utility
    add("washing_machine", (T / 2 + 0.31, 6.85, 0, E), washing_machine())
    add("tumble_dryer", (T / 2 + 0.31, 7.47, 0, E), tumble_dryer())
    add("kitchen_unit_1", (T / 2 + 0.3, 8.17, 0, E), kitchen_unit(0.74, top="laminate_grey"))
    add("window_5", (T / 2 + 0.02, 8.17, 1.55, E), window(0.6, 0.9, sill=False))
    add("boiler", (2.3, YU - T / 2 - 0.16, 1.2, S), boiler())
    # the kitchen along the north wall, west to east
    add("fridge_freezer", (4.38, wn - 0.35, 0, S), fridge_freezer())
    add("kitchen_unit_2", (5.15, wn - 0.3, 0, S), kitchen_unit(0.8))
    add("kitchen_unit_5", (5.45, wn - 0.17, 1.45, S), wall_unit(1.4))  # wall cupboards over unit 2 and the dishwasher
    add("dishwasher", (5.85, wn - 0.3, 0, S), dishwasher())
    add("kitchen_sink", (6.65, wn - 0.3, 0, S), kitchen_sink())
    add("window_6", (6.65, wn - 0.02, 1.72, S), window(0.9, 0.9, sill=False))
    add("kitchen_unit_3", (7.45, wn - 0.3, 0, S), kitchen_unit(0.6))
    add("kettle", (7.45, wn - 0.38, 0.94, S), kettle())
    add("cooker", (8.05, wn - 0.3, 0, S), cooker())
    add("extractor_hood", (8.05, wn - 0.05, 0, S), extractor_hood())
    add("kitchen_unit_4", (8.95, wn - 0.3, 0, S), kitchen_unit(1.2))
    add("kitchen_unit_6", (8.95, wn - 0.17, 1.45, S), wall_unit(1.2))
    add("microwave", (9.1, wn - 0.33, 0.94, S), microwave())
    # the island with its stools on the south side, the bin
    add("kitchen_island", (6.6, 9.25, 0, N), kitchen_island())
    for i, x in enumerate((5.95, 6.6, 7.25), 1):
        add(f"bar_stool_{i}", (x, 8.33, 0, N), bar_stool())
    add("bin_1", (9.38, 8.7, 0, WEST), bin_())
    add("smoke_alarm_3", (6.6, 7.6, H, N), smoke_alarm())
    # the dining end
    yd = (YU + T / 2 + wn) / 2  # the table in the middle of the dining end
    add("dining_table", (2.0, yd, 0, N), dining_table(1.4, 0.8))
    for i, (x, y, yaw) in enumerate(((1.65, yd - 0.62, N), (2.35, yd - 0.62, N), (1.65, yd + 0.62, S),
                                     (2.35, yd + 0.62, S), (1.08, yd, E), (2.92, yd, WEST)), 1):
        add(f"dining_chair_{i}", (x, y, 0, yaw), dining_chair())
    add("window_7", (T / 2 + 0.02, yd, 1.5, E), window(1.2, 1.2))
    add("window_8", (2.0, wn - 0.02, 1.5, S), window(1.2, 1.2, sill=False))
    add("radiator_4", (T / 2 + 0.06, yd, 0, E), radiator(1.0))
    add("plant_3", (0.42, 11.55, 0, N), plant(1.0))
    # the bathroom
    b0, b1 = BATH_DOOR
    add("door_9", (b0 + 0.04, YC + T / 2 + 0.49, 0, WEST), door())
    add("bath", (10.5, 9.2 - T / 2 - 0.38, 0, S), bath())
    add("shower", (13.0 - T / 2 - 0.45, 9.2 - T / 2 - 0.45, 0, S), shower())
    add("toilet_2", (13.0 - T / 2 - 0.34, 7.3, 0, WEST), toilet())
    add("basin_2", (9.6 + T / 2 + 0.23, 7.6, 0, E), basin())
    add("mirror_2", (9.6 + T / 2 + 0.015, 7.6, 1.5, E), mirror(0.5, 0.7, "chrome"))
    # the home office
    o0, o1 = OFFICE_DOOR
    add("door_10", (9.6 + T / 2 + 0.49, o1 - 0.04, 0, N), door())
    add("window_9", (11.4, wn - 0.02, 1.5, S), window(1.2, 1.2))
    add("desk_1", (11.4, wn - 0.36, 0, S), desk())
    add("monitor", (11.3, wn - 0.32, 0.75, S), monitor())
    add("office_chair", (11.4, 10.75, 0, N), office_chair())
    add("bookshelf_2", (13.0 - T / 2 - 0.16, 10.3, 0, WEST), bookshelf(0.9, 0.3, 1.9, "walnut"))
    add("bin_2", (10.2, 11.7, 0, N), [cyl("body", "grey_plastic", 0, 0, 0.15, 0.13, 0.3),
                                      box("paper", "paper", 0, 0, 0.28, 0.12, 0.1, 0.04)])
    # the child's bedroom
    c0, c1 = CHILD_DOOR
    add("door_11", (c0 + 0.04, YC + T / 2 + 0.49, 0, WEST), door())
    add("window_10", (14.0, wn - 0.02, 1.4, S), window(1.0, 1.1))
    add("window_11", (W - T / 2 - 0.02, 7.5, 1.4, WEST), window(1.0, 1.1))
    add("single_bed", (W - T / 2 - 0.5, wn - 1.0, 0, S), single_bed())
    add("toy_box", (W - T / 2 - 0.25, 8.6, 0, WEST), toy_box())
    add("desk_2", (13.0 + T / 2 + 0.27, 8.1, 0, E), kids_desk())
    add("bookshelf_3", (13.0 + T / 2 + 0.16, 10.4, 0, E), bookshelf(0.8, 0.3, 1.15, "pine"))
    add("rug_2", (14.2, 9.6, 0, N), rug(1.3, 1.0, "rug_kids", "white"))
    add("radiator_5", (14.0, wn - 0.06, 0, S), radiator(0.8))


def main():
    out = [base.model("walls", (0, 0, 0, 0), walls()),
           base.model("floor", (0, 0, 0, 0), floor()),
           base.model("ceiling", (0, 0, 0, 0), base.ceiling_slab(W, D, H))]
    south_rooms(out)
    north_rooms(out)
    warm, cool = "0.85 0.78 0.66", "0.8 0.8 0.78"
    lights = [base.point_light(name, x, y, H - 0.2, rgb)
              for name, x, y, rgb in (("light_garage", 2.2, 3.2, cool), ("light_hall", 5.5, 1.8, warm),
                                      ("light_wc", 4.9, 4.1, cool), ("light_living", 9.5, 2.5, warm),
                                      ("light_master", 14.0, 2.5, warm), ("light_corridor_w", 6.5, 5.7, warm),
                                      ("light_corridor_e", 12.5, 5.7, warm), ("light_utility", 2.0, 7.7, cool),
                                      ("light_kitchen", 6.8, 9.8, cool), ("light_dining", 2.0, 10.5, warm),
                                      ("light_bathroom", 11.3, 7.8, cool), ("light_office", 11.3, 10.6, cool),
                                      ("light_child", 14.5, 9.2, warm))]
    print(base.world_sdf("semsplat_familyhome", """The semsplat family home: a bungalow of 16 m x 12 m on one floor (south:
     the integral garage with the car, the entrance hall with the downstairs toilet, the living room
     with the log burner, the master bedroom; the corridor; north: the utility room, the open-plan
     kitchen-diner with the island and the dining table, the bathroom, the home office, the child's
     bedroom) for measuring on a world nobody tuned on. Generated by
     familyhome_models/make_familyhome.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
