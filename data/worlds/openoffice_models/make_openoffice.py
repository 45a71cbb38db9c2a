#!/usr/bin/env python3
"""Writes data/worlds/openoffice.world: a modern open-plan tech office of 28 m x 18 m on one floor,
for measuring the semantic stack on a world nobody tuned on. x runs west to east, y south to north;
the street front with the main entrance is the south wall.

South band (y < 6), west to east:
  the bike store (x < 3.5, y < 5): a rack of four Sheffield hoops along the west wall, a window, its
    outside door in the south wall (shut), its inner door into the reception;
  the reception (x 3.5..11): the main entrance (a double door) in the south wall; the reception
    desk with its monitor and the receptionist's task chair behind it, a sign-in tablet kiosk in
    front of it, a sofa for visitors along the west wall with a coffee table, a coat stand and a
    fire extinguisher by the entrance, two potted plants, two windows; a wide opening north into
    the open-plan workspace;
  meeting room 1 (x 11..15.5) and meeting room 2 (x 15.5..20), each entered by a door in its north
    wall: an oval meeting table for six with six meeting chairs, a conference speakerphone on the
    table, a wall-mounted display screen on the end wall, a whiteboard on the other end wall (the
    two whiteboards back to back on the shared wall), a window;
  the quiet corner of the workspace (x > 20): two phone booths (quiet pods) against meeting room
    2's east wall, three standing desks with monitors under the south windows, two lockers on the
    east wall, a potted plant, a fire extinguisher.
The open-plan workspace (y 6..13 and the west column x < 3.5, y 5..13): five banks of four desks
  (two facing two across a desk divider), each desk with a monitor, a docking station, a pedestal
  under it and a task chair; in the west column three lockers on the bike store's wall, two
  standing desks with monitors under the west windows, a potted plant; windows in the east wall.
North band (y > 13), west to east:
  the toilets (x < 5.5): three toilets in cubicles along the north wall, two wash basins with
    mirrors above them and a hand dryer on the west wall, a second hand dryer and a waste bin on
    the east wall; the door in the south wall;
  the print alcove (x 5.5..11, y 13..15), open to the workspace: the multifunction printer and the
    shredder against the east wall, a recycling bin, the first aid point (a first aid kit on the
    wall) and a fire extinguisher on the west wall;
  the comms cupboard (x 5.5..8, y > 15), door from the alcove: the server rack, a UPS beside it, a
    wall-mounted air conditioning unit;
  the stationery / store cupboard (x 8..11, y > 15), door from the alcove: two shelving units and
    cardboard boxes on the floor;
  the office kitchen (x 11..19): along the north wall two kitchen counters with the kitchen sink and
    the dishwasher between them, the fridge and a water dispenser; a coffee machine and a microwave
    on the counters; a high kitchen table with four stools in the middle, a waste bin and a
    recycling bin on the west wall, a fire extinguisher, two windows; entered from the workspace
    through a wide opening in its south wall and from the breakout area through its east wall;
  the breakout area (x > 19), open to the workspace: a sofa on the north wall with a coffee table
    in front, three bean bags, a foosball table, two potted plants, windows.

Every model is inline (boxes, cylinders, spheres), so the world needs no model path. Model names
are what a world author would type; the class is the name less its _<number> ("task_chair_12" ->
"task chair", "ups" -> "ups"). The primitives, lights and the SDF document are the office
generator's; every model function here is this world's own.
Run: python3 data/worlds/openoffice_models/make_openoffice.py > data/worlds/openoffice.world"""

import math
import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document, window, plant)

W, D, H = 28.0, 18.0, 2.8   # floor width (x), depth (y), wall height
T = 0.1                     # wall thickness
F = T / 2                   # half a wall: a wall's face is this far from its line
LINTEL = 2.1                # the top of the inner doorways

N, S, E, WEST = 0.0, 3.1416, -1.5708, 1.5708  # yaw that turns a model's front (+y) north/south/east/west

base.COL.update({
    "carpet_tile": "0.36 0.38 0.42", "tile": "0.85 0.86 0.86", "concrete": "0.6 0.6 0.58",
    "plaster": "0.93 0.93 0.91", "partition": "0.86 0.88 0.9", "white_tile": "0.93 0.94 0.94",
    "oak": "0.72 0.56 0.38", "birch": "0.86 0.76 0.6", "walnut": "0.4 0.27 0.17",
    "desk_white": "0.93 0.93 0.92", "steel": "0.75 0.76 0.78", "chrome": "0.82 0.83 0.85",
    "aluminium": "0.78 0.79 0.8", "charcoal": "0.16 0.17 0.19", "rubber": "0.1 0.1 0.1",
    "mesh_black": "0.1 0.1 0.12", "fabric_navy": "0.16 0.2 0.35", "fabric_teal": "0.12 0.45 0.45",
    "fabric_grey": "0.45 0.47 0.5", "sofa_grey": "0.5 0.52 0.56", "sofa_orange": "0.85 0.45 0.15",
    "felt_green": "0.3 0.48 0.35", "felt_grey": "0.55 0.57 0.6", "cushion_yellow": "0.92 0.75 0.2",
    "cushion_red": "0.75 0.18 0.2", "cushion_blue": "0.2 0.4 0.75", "screen_lit": "0.25 0.45 0.65",
    "led_green": "0.1 0.9 0.3", "led_blue": "0.2 0.5 1.0", "led_red": "0.9 0.1 0.1",
    "locker_blue": "0.28 0.42 0.62", "pedestal_grey": "0.68 0.7 0.72", "recycle_green": "0.15 0.55 0.3",
    "bin_steel": "0.7 0.71 0.73", "paper": "0.96 0.96 0.94", "carton": "0.74 0.58 0.38",
    "tape": "0.82 0.72 0.5", "porcelain": "0.97 0.97 0.97", "mirror": "0.8 0.85 0.88",
    "first_aid_green": "0.05 0.55 0.3", "extinguisher_red": "0.8 0.08 0.06",
    "glass_door": "0.62 0.74 0.8", "worktop": "0.3 0.3 0.32", "cabinet_white": "0.95 0.95 0.94",
    "fridge_white": "0.94 0.94 0.93", "field_green": "0.1 0.5 0.2", "player_red": "0.8 0.15 0.1",
    "player_blue": "0.15 0.3 0.8", "water_blue": "0.45 0.65 0.9", "coat_camel": "0.65 0.5 0.32",
    "coat_navy": "0.15 0.18 0.3", "marker_blue": "0.1 0.2 0.8", "marker_red": "0.8 0.1 0.1",
    "galvanised": "0.7 0.72 0.72", "server_grey": "0.35 0.36 0.38", "magazine": "0.8 0.3 0.25",
    "coffee": "0.3 0.18 0.1", "mug": "0.9 0.9 0.88",
})
box, cyl, sph = base.box, base.cyl, base.sph
turned, along_x, along_y, castors = base.turned, base.along_x, base.along_y, base.castors


def legs(c, hx, hy, h, s=0.04):
    return [box(f"leg{i}", c, sx * hx, sy * hy, h / 2, s, s, h)
            for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]


# ---- local frames: x right, y forward = the side a person uses (or the face that shows), z up ----
def door(w=0.92):
    """A door leaf standing open at 90 degrees beside its opening (or shut in it)."""
    return [box("leaf", "oak", 0, 0, 1.02, w, 0.04, 2.04),
            cyl("handle", "chrome", w / 2 - 0.08, 0.04, 1.0, 0.015, 0.06),
            cyl("handle_back", "chrome", w / 2 - 0.08, -0.04, 1.0, 0.015, 0.06)]


# ---- the reception ----
def reception_desk(w=2.6, d=0.8):
    """The reception counter: a tall closed front to the visitors (+y) with a raised ledge and a
    logo strip, the receptionist's low worktop behind it (-y), a cable grommet."""
    return [box("front", "desk_white", 0, d / 2 - 0.04, 0.55, w, 0.08, 1.1),
            box("ledge", "oak", 0, d / 2 - 0.12, 1.12, w + 0.04, 0.26, 0.04),
            box("logo", "led_blue", 0, d / 2 + 0.002, 0.8, 0.8, 0.004, 0.08),
            box("worktop", "birch", 0, -0.06, 0.735, w - 0.1, d - 0.14, 0.03),
            box("end_l", "desk_white", -w / 2 + 0.03, 0, 0.55, 0.06, d, 1.1),
            box("end_r", "desk_white", w / 2 - 0.03, 0, 0.55, 0.06, d, 1.1),
            box("plinth", "charcoal", 0, 0.2, 0.04, w - 0.1, 0.3, 0.08),
            cyl("grommet", "charcoal", -0.6, -0.2, 0.752, 0.03, 0.004)]


def sign_in_kiosk():
    """A visitor sign-in kiosk: a weighted foot, a slim column and a tablet on a tilted holder,
    its screen toward the visitor (+y)."""
    return [box("foot", "charcoal", 0, 0, 0.01, 0.42, 0.42, 0.02),
            box("column", "aluminium", 0, 0, 0.53, 0.08, 0.08, 1.02),
            turned(box("holder", "charcoal", 0, 0.02, 1.1, 0.32, 0.24, 0.03), "-0.5 0 0"),
            turned(box("tablet_screen", "screen_lit", 0, 0.03, 1.116, 0.26, 0.18, 0.004), "-0.5 0 0"),
            box("badge_printer", "desk_white", 0, 0.05, 0.85, 0.16, 0.1, 0.1)]


def coat_stand():
    """A freestanding coat stand: a round foot, the pole, six hooks, a coat and a jacket."""
    v = [cyl("foot", "walnut", 0, 0, 0.02, 0.25, 0.04),
         cyl("pole", "walnut", 0, 0, 0.9, 0.025, 1.76),
         sph("knob", "walnut", 0, 0, 1.8, 0.04)]
    for i in range(6):
        a = i * math.pi / 3
        v.append(turned(box(f"hook{i}", "chrome", 0.07 * math.cos(a), 0.07 * math.sin(a), 1.68, 0.14, 0.015, 0.015),
                        f"0 0 {a:.4f}"))
    return v + [box("coat", "coat_camel", 0.14, 0, 1.22, 0.1, 0.44, 0.86),
                box("jacket", "coat_navy", -0.13, 0.02, 1.32, 0.1, 0.4, 0.64)]


def sofa(c="sofa_grey", w=2.0, d=0.88):
    """A modern three-seat sofa: a plinth on short legs, seat cushions, back cushions against the
    back (-y), two arms, a couple of scatter cushions."""
    v = [box("base", c, 0, 0, 0.27, w, d, 0.24),
         box("back", c, 0, -d / 2 + 0.1, 0.62, w, 0.2, 0.5),
         box("arm_l", c, -w / 2 + 0.08, 0.02, 0.5, 0.16, d - 0.04, 0.24),
         box("arm_r", c, w / 2 - 0.08, 0.02, 0.5, 0.16, d - 0.04, 0.24)]
    v += [box(f"seat_cushion{i}", c, -w / 3 + 0.08 + i * (w - 0.32) / 3 - 0.02 * (i - 1) + 0.0, 0.06, 0.45,
              (w - 0.36) / 3 - 0.02, d - 0.26, 0.12) for i in range(3)]
    v += [box("cushion_l", "cushion_yellow", -w / 2 + 0.34, -d / 2 + 0.28, 0.66, 0.36, 0.12, 0.34),
          box("cushion_r", "cushion_yellow", w / 2 - 0.34, -d / 2 + 0.28, 0.66, 0.36, 0.12, 0.34)]
    return v + legs("walnut", w / 2 - 0.08, d / 2 - 0.08, 0.15, 0.05)


def coffee_table(w=1.1, d=0.6):
    """A low oak coffee table on four legs, a couple of magazines and a mug on it."""
    return [box("top", "oak", 0, 0, 0.41, w, d, 0.04),
            box("shelf", "oak", 0, 0, 0.14, w - 0.1, d - 0.1, 0.02),
            box("magazine", "magazine", -0.2, 0.05, 0.435, 0.28, 0.21, 0.01),
            box("magazine2", "paper", -0.15, -0.1, 0.435, 0.28, 0.21, 0.01),
            cyl("mug", "mug", 0.3, 0.1, 0.48, 0.04, 0.1)] + legs("walnut", w / 2 - 0.05, d / 2 - 0.05, 0.39, 0.04)


# ---- the workspace ----
def desk(w=1.6, d=0.8):
    """A bench desk: a white top on two end frames, a cable tray along the back (+y), the user at
    the front (-y)."""
    return [box("top", "desk_white", 0, 0, 0.735, w, d, 0.03),
            box("frame_l", "charcoal", -w / 2 + 0.04, 0, 0.36, 0.04, d - 0.1, 0.72),
            box("frame_r", "charcoal", w / 2 - 0.04, 0, 0.36, 0.04, d - 0.1, 0.72),
            box("foot_l", "charcoal", -w / 2 + 0.04, 0, 0.015, 0.06, d - 0.06, 0.03),
            box("foot_r", "charcoal", w / 2 - 0.04, 0, 0.015, 0.06, d - 0.06, 0.03),
            box("cable_tray", "charcoal", 0, d / 2 - 0.08, 0.6, w - 0.2, 0.12, 0.08)]


def standing_desk(w=1.4, d=0.7, h=1.05):
    """A sit-stand desk raised to standing height: the top on two telescopic legs with feet, the
    height control at the front (-y)."""
    return [box("top", "birch", 0, 0, h, w, d, 0.03),
            box("column_l", "charcoal", -w / 2 + 0.12, 0, (h - 0.015) / 2 + 0.02, 0.07, 0.07, h - 0.055),
            box("column_r", "charcoal", w / 2 - 0.12, 0, (h - 0.015) / 2 + 0.02, 0.07, 0.07, h - 0.055),
            box("foot_l", "charcoal", -w / 2 + 0.12, 0, 0.02, 0.07, d - 0.06, 0.04),
            box("foot_r", "charcoal", w / 2 - 0.12, 0, 0.02, 0.07, d - 0.06, 0.04),
            box("crossbar", "charcoal", 0, 0, h - 0.04, w - 0.3, 0.05, 0.05),
            box("control", "black", w / 2 - 0.2, -d / 2 + 0.03, h - 0.03, 0.12, 0.05, 0.03)]


def monitor():
    """A flat computer monitor on a stand, its screen toward the user (+y)."""
    return [box("bezel", "black", 0, 0, 0.4, 0.62, 0.03, 0.37),
            box("screen", "screen_lit", 0, 0.016, 0.41, 0.59, 0.002, 0.33),
            box("neck", "aluminium", 0, -0.05, 0.16, 0.05, 0.03, 0.3),
            box("foot", "aluminium", 0, -0.02, 0.006, 0.24, 0.18, 0.012)]


def docking_station():
    """A laptop docking station lying on the desk: a slim black block with ports and a light."""
    return [box("body", "black", 0, 0, 0.0125, 0.22, 0.08, 0.025),
            box("light", "led_green", 0.08, 0.041, 0.015, 0.02, 0.002, 0.006),
            box("ports", "charcoal", 0, -0.041, 0.012, 0.16, 0.002, 0.012)]


def pedestal():
    """A mobile under-desk pedestal: three drawers (a pencil tray, a middle and a file drawer),
    their handles toward the user (+y), on castors, a cushion top."""
    v = [box("body", "pedestal_grey", 0, 0, 0.325, 0.4, 0.56, 0.55)]
    for i, (z, h) in enumerate(((0.53, 0.1), (0.41, 0.12), (0.2, 0.28))):
        v += [box(f"drawer{i}", "desk_white", 0, 0.281, z, 0.38, 0.002, h - 0.01),
              box(f"handle{i}", "aluminium", 0, 0.29, z + h / 2 - 0.03, 0.16, 0.015, 0.012)]
    return v + [box("lock", "chrome", 0.14, 0.283, 0.57, 0.02, 0.004, 0.02)] + castors(0.16, 0.23, 0.025)


def desk_divider(w=1.6):
    """A fabric desk screen between two facing desks, held on the desk tops by two clamps."""
    return [box("panel", "fabric_teal", 0, 0, 0.935, w - 0.04, 0.03, 0.43),
            box("rail", "aluminium", 0, 0, 1.155, w - 0.04, 0.035, 0.01),
            box("clamp_l", "aluminium", -w / 2 + 0.25, 0, 0.76, 0.06, 0.12, 0.02),
            box("clamp_r", "aluminium", w / 2 - 0.25, 0, 0.76, 0.06, 0.12, 0.02)]


def task_chair(c="fabric_navy"):
    """An ergonomic swivel task chair: a five-star base on castors, the gas lift, the seat, a
    mesh back (at -y) with a lumbar pad and a headrest, two arms; the user faces +y."""
    v = [cyl("hub", "black", 0, 0, 0.08, 0.05, 0.06),
         cyl("gas_lift", "chrome", 0, 0, 0.27, 0.025, 0.32),
         box("mechanism", "black", 0, 0, 0.43, 0.22, 0.22, 0.04),
         box("seat", c, 0, 0.03, 0.49, 0.5, 0.48, 0.08),
         box("back", "mesh_black", 0, -0.24, 0.86, 0.46, 0.04, 0.56),
         box("lumbar", c, 0, -0.215, 0.7, 0.3, 0.02, 0.12),
         box("spine", "black", 0, -0.265, 0.7, 0.06, 0.02, 0.42),
         box("headrest", "mesh_black", 0, -0.25, 1.24, 0.28, 0.04, 0.14),
         box("arm_l", "black", -0.26, 0.0, 0.66, 0.05, 0.26, 0.03),
         box("arm_r", "black", 0.26, 0.0, 0.66, 0.05, 0.26, 0.03),
         box("arm_post_l", "black", -0.26, -0.02, 0.57, 0.03, 0.04, 0.16),
         box("arm_post_r", "black", 0.26, -0.02, 0.57, 0.03, 0.04, 0.16)]
    for i in range(5):
        a = math.pi / 2 + i * 2 * math.pi / 5
        v += [turned(box(f"spoke{i}", "black", 0.14 * math.cos(a), 0.14 * math.sin(a), 0.07, 0.28, 0.04, 0.03),
                     f"0 0 {a:.4f}"),
              sph(f"castor{i}", "rubber", 0.28 * math.cos(a), 0.28 * math.sin(a), 0.03, 0.03)]
    return v


def locker(cols=3, rows=2):
    """A steel locker bank of 0.9 m: three columns of two doors toward the user (+y), each door
    with vents, a number plate and a key lock."""
    w, d, h = 0.9, 0.45, 1.85
    v = [box("body", "locker_blue", 0, 0, h / 2 + 0.05, w, d, h - 0.1),
         box("plinth", "charcoal", 0, -0.01, 0.025, w - 0.02, d - 0.04, 0.05)]
    cw, rh = w / cols, (h - 0.1) / rows
    for c in range(cols):
        x = -w / 2 + cw * (c + 0.5)
        if c:
            v.append(box(f"seam{c}", "charcoal", -w / 2 + cw * c, d / 2 + 0.001, h / 2 + 0.05, 0.006, 0.003, h - 0.12))
        for r in range(rows):
            z = 0.05 + rh * (r + 0.5)
            v += [box(f"plate{c}_{r}", "paper", x, d / 2 + 0.002, z + rh / 2 - 0.12, 0.08, 0.003, 0.04),
                  box(f"lock{c}_{r}", "chrome", x + cw / 2 - 0.05, d / 2 + 0.004, z, 0.02, 0.006, 0.04),
                  box(f"vent{c}_{r}", "charcoal", x, d / 2 + 0.002, z + rh / 2 - 0.25, 0.16, 0.003, 0.06)]
        v.append(box(f"row_seam{c}", "charcoal", x, d / 2 + 0.001, 0.05 + rh, cw - 0.01, 0.003, 0.006))
    return v


def printer():
    """A floor-standing multifunction printer (print, copy, scan): the paper drawers below, the
    print engine, the output tray, the scanner with its lid and the touch panel at the front (+y)."""
    v = [box("base", "pedestal_grey", 0, 0, 0.25, 0.62, 0.6, 0.5),
         box("engine", "desk_white", 0, 0, 0.7, 0.62, 0.6, 0.4),
         box("output_gap", "charcoal", 0, 0.05, 0.94, 0.5, 0.45, 0.08),
         box("output_paper", "paper", 0.05, 0.05, 0.905, 0.3, 0.22, 0.01),
         box("scanner", "desk_white", 0, -0.02, 1.05, 0.62, 0.56, 0.14),
         box("lid", "charcoal", 0, -0.02, 1.135, 0.58, 0.5, 0.03),
         turned(box("panel", "charcoal", 0.12, 0.32, 1.06, 0.3, 0.12, 0.02), "0.6 0 0"),
         turned(box("panel_screen", "screen_lit", 0.12, 0.325, 1.07, 0.24, 0.09, 0.003), "0.6 0 0")]
    v += [box(f"drawer{i}", "desk_white", 0, 0.301, 0.1 + 0.15 * i, 0.58, 0.002, 0.13) for i in range(3)]
    v += [box(f"drawer_handle{i}", "charcoal", 0, 0.305, 0.14 + 0.15 * i, 0.2, 0.008, 0.02) for i in range(3)]
    return v + castors(0.26, 0.25, 0.02)


def shredder():
    """An office paper shredder: the waste bin body with a window, the cutting head on top with its
    feed slot and switch."""
    return [box("bin", "charcoal", 0, 0, 0.3, 0.4, 0.3, 0.6),
            box("window", "glass", 0, 0.151, 0.3, 0.2, 0.002, 0.3),
            box("head", "black", 0, 0, 0.645, 0.42, 0.32, 0.09),
            box("slot", "paper", 0, 0, 0.691, 0.3, 0.01, 0.002),
            box("switch", "led_green", 0.15, 0.08, 0.692, 0.03, 0.03, 0.004)]


def recycling_bin():
    """A square green recycling bin: the body, a lid with a paper slot, the recycling label."""
    return [box("body", "recycle_green", 0, 0, 0.36, 0.4, 0.4, 0.72),
            box("lid", "recycle_green", 0, 0, 0.74, 0.42, 0.42, 0.04),
            box("slot", "black", 0, 0.05, 0.761, 0.28, 0.06, 0.002),
            box("label", "paper", 0, 0.201, 0.5, 0.18, 0.002, 0.14)]


def waste_bin():
    """A round stainless pedal bin with its lid and pedal."""
    return [cyl("body", "bin_steel", 0, 0, 0.31, 0.17, 0.58),
            cyl("lid", "bin_steel", 0, 0, 0.615, 0.175, 0.03),
            box("pedal", "black", 0, 0.19, 0.04, 0.1, 0.06, 0.02),
            cyl("base_ring", "black", 0, 0, 0.01, 0.175, 0.02)]


# ---- the meeting rooms ----
def meeting_table(w=2.4, d=1.1):
    """An oval meeting table: a veneered top with rounded ends on two pedestals with feet, a power
    box in the middle."""
    r = d / 2
    return [box("top", "walnut", 0, 0, 0.735, w - d, d, 0.03),
            cyl("end_l", "walnut", -(w - d) / 2, 0, 0.735, r, 0.03),
            cyl("end_r", "walnut", (w - d) / 2, 0, 0.735, r, 0.03),
            box("pedestal_l", "charcoal", -w / 4, 0, 0.36, 0.12, 0.5, 0.72),
            box("pedestal_r", "charcoal", w / 4, 0, 0.36, 0.12, 0.5, 0.72),
            box("foot_l", "charcoal", -w / 4, 0, 0.015, 0.2, 0.8, 0.03),
            box("foot_r", "charcoal", w / 4, 0, 0.015, 0.2, 0.8, 0.03),
            box("power_box", "aluminium", 0.35, 0, 0.752, 0.3, 0.1, 0.004)]


def meeting_chair():
    """A meeting-room chair on a chrome sled base: an upholstered seat and back (at -y), no castors,
    the user facing +y."""
    return [box("seat", "fabric_grey", 0, 0.02, 0.46, 0.48, 0.46, 0.07),
            box("back", "fabric_grey", 0, -0.22, 0.8, 0.46, 0.05, 0.5),
            along_y(cyl("runner_l", "chrome", -0.22, 0, 0.015, 0.012, 0.5)),
            along_y(cyl("runner_r", "chrome", 0.22, 0, 0.015, 0.012, 0.5)),
            cyl("post_fl", "chrome", -0.22, 0.22, 0.22, 0.012, 0.42),
            cyl("post_fr", "chrome", 0.22, 0.22, 0.22, 0.012, 0.42),
            cyl("post_bl", "chrome", -0.22, -0.22, 0.5, 0.012, 0.98),
            cyl("post_br", "chrome", 0.22, -0.22, 0.5, 0.012, 0.98)]


def display_screen():
    """A large wall-mounted display for video calls and presentations (the wall behind at -y),
    centred on the model's height, a camera bar under it."""
    return [box("bracket", "charcoal", 0, -0.05, 0, 0.4, 0.04, 0.3),
            box("panel", "black", 0, 0, 0, 1.68, 0.05, 0.97),
            box("screen", "screen_lit", 0, 0.026, 0.005, 1.64, 0.004, 0.92),
            box("camera_bar", "black", 0, 0.01, -0.54, 0.7, 0.07, 0.06),
            box("camera_lens", "glass", 0, 0.046, -0.54, 0.06, 0.002, 0.03)]


def speakerphone():
    """A conference speakerphone lying on the table: a three-legged body with a display and mute
    lights around a round centre."""
    v = [cyl("centre", "charcoal", 0, 0, 0.018, 0.08, 0.036),
         box("display", "screen_lit", 0, 0.04, 0.037, 0.06, 0.025, 0.002)]
    for i in range(3):
        a = math.pi / 2 + i * 2 * math.pi / 3
        v += [turned(box(f"leg{i}", "charcoal", 0.1 * math.cos(a), 0.1 * math.sin(a), 0.012, 0.16, 0.06, 0.024),
                     f"0 0 {a:.4f}"),
              cyl(f"mic{i}", "led_red", 0.16 * math.cos(a), 0.16 * math.sin(a), 0.025, 0.008, 0.003)]
    return v


def whiteboard(w=1.8, h=1.2):
    """A wall-mounted whiteboard (the wall behind at -y), centred on the model's height: the
    aluminium frame, the board with a few lines of marker on it, a pen tray with markers and an
    eraser."""
    v = [box("frame", "aluminium", 0, 0, 0, w, 0.03, h),
         box("board", "desk_white", 0, 0.016, 0, w - 0.05, 0.002, h - 0.05),
         box("tray", "aluminium", 0, 0.04, -h / 2 + 0.01, w - 0.4, 0.06, 0.02),
         box("eraser", "charcoal", -0.3, 0.04, -h / 2 + 0.04, 0.13, 0.05, 0.04),
         cyl("marker_b", "marker_blue", 0.1, 0.04, -h / 2 + 0.035, 0.01, 0.03),
         cyl("marker_r", "marker_red", 0.2, 0.04, -h / 2 + 0.035, 0.01, 0.03)]
    return v + [box(f"writing{i}", "marker_blue", -0.3 + 0.1 * (i % 2), 0.018, 0.35 - 0.15 * i, 0.9 - 0.15 * i,
                    0.001, 0.03) for i in range(4)]


# ---- the phone booths and the breakout area ----
def phone_booth(w=1.1, d=1.1, h=2.25):
    """A single-person acoustic phone booth (quiet pod): felt-lined walls, a roof with a light and
    a fan, a glass door at the front (+y) with a long handle, a bench seat at the back, a small
    shelf for a laptop on the side wall."""
    return [box("floor", "charcoal", 0, 0, 0.025, w, d, 0.05),
            box("back", "felt_green", 0, -d / 2 + 0.03, h / 2, w, 0.06, h),
            box("side_l", "felt_green", -w / 2 + 0.03, 0, h / 2, 0.06, d, h),
            box("side_r", "felt_green", w / 2 - 0.03, 0, h / 2, 0.06, d, h),
            box("roof", "felt_grey", 0, 0, h - 0.04, w, d, 0.08),
            box("door", "glass_door", 0, d / 2 - 0.02, 1.12, w - 0.14, 0.02, 2.1),
            box("handle", "aluminium", w / 2 - 0.16, d / 2 + 0.02, 1.05, 0.03, 0.03, 0.6),
            box("seat", "cushion_blue", 0, -d / 2 + 0.26, 0.45, w - 0.2, 0.36, 0.08),
            box("seat_base", "felt_grey", 0, -d / 2 + 0.26, 0.2, w - 0.2, 0.36, 0.4),
            box("shelf", "birch", w / 2 - 0.2, 0.05, 0.95, 0.28, 0.5, 0.03),
            box("lamp", "paper", 0, 0, h - 0.085, 0.4, 0.4, 0.01)]


def bean_bag(c="cushion_yellow"):
    """A fabric bean bag: a squat body and a slumped back rest behind it (at -y)."""
    return [cyl("bottom", c, 0, 0, 0.1, 0.38, 0.2),
            sph("body", c, 0, 0.03, 0.32, 0.3),
            sph("back", c, 0, -0.15, 0.5, 0.25)]


def foosball_table(w=1.4, d=0.75):
    """A table football (foosball) table: the cabinet on four legs, the green playfield, eight rods
    across it with handles out of both sides and players on the rods, a goal at each end."""
    v = [box("cabinet_s", "walnut", 0, -d / 2 + 0.02, 0.8, w, 0.04, 0.2),
         box("cabinet_n", "walnut", 0, d / 2 - 0.02, 0.8, w, 0.04, 0.2),
         box("cabinet_w", "walnut", -w / 2 + 0.02, 0, 0.8, 0.04, d - 0.08, 0.2),
         box("cabinet_e", "walnut", w / 2 - 0.02, 0, 0.8, 0.04, d - 0.08, 0.2),
         box("field", "field_green", 0, 0, 0.71, w - 0.08, d - 0.08, 0.02),
         box("goal_w", "black", -w / 2 + 0.045, 0, 0.76, 0.01, 0.22, 0.08),
         box("goal_e", "black", w / 2 - 0.045, 0, 0.76, 0.01, 0.22, 0.08)]
    v += legs("walnut", w / 2 - 0.06, d / 2 - 0.06, 0.7, 0.08)
    for i in range(8):
        x = -w / 2 + 0.18 + i * (w - 0.36) / 7
        team = "player_red" if i in (0, 1, 3, 5) else "player_blue"
        v += [along_y(cyl(f"rod{i}", "chrome", x, 0, 0.82, 0.008, d + 0.5)),
              along_y(cyl(f"grip{i}", "black", x, -d / 2 - 0.2, 0.82, 0.018, 0.1)) if team == "player_red"
              else along_y(cyl(f"grip{i}", "black", x, d / 2 + 0.2, 0.82, 0.018, 0.1))]
        for k in range(3):
            v.append(box(f"player{i}_{k}", team, x, -0.22 + 0.22 * k, 0.79, 0.03, 0.05, 0.1))
    return v


# ---- the kitchen ----
def kitchen_counter(w=2.4, d=0.65):
    """A run of white base cabinets with a dark worktop, a recessed plinth, a cupboard door every
    0.6 m with its bar handle at the front (+y)."""
    v = [box("cabinets", "cabinet_white", 0, 0, 0.5, w, d - 0.03, 0.76),
         box("plinth", "charcoal", 0, -0.04, 0.06, w, d - 0.1, 0.12),
         box("worktop", "worktop", 0, 0, 0.9, w, d, 0.04)]
    n = int(round(w / 0.6))
    for i in range(n):
        x = -w / 2 + w / n * (i + 0.5)
        v += [box(f"door_seam{i}", "charcoal", x - w / n / 2 + 0.002, d / 2 - 0.014, 0.5, 0.004, 0.002, 0.74),
              box(f"handle{i}", "chrome", x, d / 2 - 0.005, 0.82, 0.3, 0.02, 0.015)]
    return v


def kitchen_sink(w=0.9, d=0.65):
    """The sink unit in the counter run: a base cabinet, the worktop with a stainless bowl and
    drainer set in it, a tall swan-neck mixer tap at the back (-y)."""
    return [box("cabinet", "cabinet_white", 0, 0, 0.5, w, d - 0.03, 0.76),
            box("plinth", "charcoal", 0, -0.04, 0.06, w, d - 0.1, 0.12),
            box("worktop", "worktop", 0, 0, 0.9, w, d, 0.04),
            box("bowl", "steel", -0.12, 0.03, 0.921, 0.45, 0.4, 0.002),
            box("drainer", "steel", 0.3, 0.03, 0.921, 0.24, 0.4, 0.002),
            cyl("tap", "chrome", -0.12, -d / 2 + 0.08, 1.07, 0.018, 0.3),
            box("spout", "chrome", -0.12, -d / 2 + 0.16, 1.21, 0.025, 0.16, 0.025),
            box("door_seam", "charcoal", 0, d / 2 - 0.014, 0.5, 0.004, 0.002, 0.74),
            box("handle", "chrome", 0.2, d / 2 - 0.005, 0.82, 0.2, 0.02, 0.015)]


def dishwasher(w=0.6, d=0.65):
    """An integrated dishwasher under the worktop: the stainless front with its handle and the
    control strip at the top (+y)."""
    return [box("body", "steel", 0, -0.01, 0.45, w - 0.01, d - 0.05, 0.84),
            box("worktop", "worktop", 0, 0, 0.9, w, d, 0.04),
            box("control_strip", "charcoal", 0, d / 2 - 0.035, 0.83, w - 0.04, 0.01, 0.05),
            box("led", "led_blue", 0.2, d / 2 - 0.029, 0.83, 0.03, 0.002, 0.01),
            box("handle", "chrome", 0, d / 2 - 0.02, 0.76, 0.4, 0.02, 0.015)]


def fridge(w=0.7, d=0.7, h=1.85):
    """A tall white fridge freezer: the fridge door above and the freezer door below, long
    vertical handles at the front (+y)."""
    return [box("body", "fridge_white", 0, -0.02, h / 2, w, d - 0.04, h),
            box("fridge_door", "fridge_white", 0, d / 2 - 0.025, 1.22, w - 0.01, 0.05, 1.24),
            box("freezer_door", "fridge_white", 0, d / 2 - 0.025, 0.3, w - 0.01, 0.05, 0.58),
            box("fridge_handle", "aluminium", w / 2 - 0.07, d / 2 + 0.015, 1.2, 0.025, 0.03, 0.6),
            box("freezer_handle", "aluminium", w / 2 - 0.07, d / 2 + 0.015, 0.42, 0.025, 0.03, 0.3)]


def microwave():
    """A countertop microwave oven: the body, the dark glass door with a handle and the control
    panel on the right, toward the user (+y)."""
    return [box("body", "charcoal", 0, 0, 0.15, 0.5, 0.38, 0.3),
            box("door", "glass", -0.07, 0.191, 0.15, 0.33, 0.003, 0.24),
            box("handle", "aluminium", 0.11, 0.2, 0.15, 0.02, 0.02, 0.22),
            box("panel", "black", 0.18, 0.191, 0.15, 0.1, 0.003, 0.24),
            box("clock", "led_green", 0.18, 0.194, 0.24, 0.06, 0.002, 0.02)]


def coffee_machine():
    """A bean-to-cup coffee machine on the counter: the body with a bean hopper on top, the display
    and the spout over the drip tray at the front (+y), a cup under the spout."""
    return [box("body", "black", 0, -0.03, 0.28, 0.34, 0.42, 0.56),
            box("hopper", "charcoal", 0.06, -0.12, 0.59, 0.16, 0.16, 0.06),
            box("display", "screen_lit", 0, 0.181, 0.46, 0.14, 0.002, 0.06),
            box("spout", "chrome", 0, 0.21, 0.33, 0.08, 0.06, 0.05),
            box("drip_tray", "chrome", 0, 0.205, 0.02, 0.24, 0.05, 0.04),
            cyl("cup", "mug", 0, 0.205, 0.09, 0.035, 0.08)]


def water_dispenser():
    """A floor-standing water dispenser: the cabinet with a hot and a cold tap over the drip tray at
    the front (+y), the blue water bottle upside down on top."""
    return [box("body", "desk_white", 0, 0, 0.5, 0.32, 0.32, 1.0),
            box("recess", "charcoal", 0, 0.15, 0.82, 0.2, 0.02, 0.2),
            box("tap_hot", "led_red", -0.05, 0.17, 0.88, 0.03, 0.03, 0.04),
            box("tap_cold", "led_blue", 0.05, 0.17, 0.88, 0.03, 0.03, 0.04),
            box("drip_tray", "charcoal", 0, 0.17, 0.72, 0.18, 0.04, 0.02),
            cyl("bottle", "water_blue", 0, 0, 1.22, 0.13, 0.42),
            cyl("bottle_neck", "water_blue", 0, 0, 1.0, 0.04, 0.04)]


def kitchen_table(w=1.8, d=0.8):
    """A high kitchen table (a poseur table) of oak on four steel legs with a footrest frame."""
    return [box("top", "oak", 0, 0, 0.9, w, d, 0.04),
            box("foot_rail_s", "steel", 0, -d / 2 + 0.06, 0.25, w - 0.12, 0.025, 0.025),
            box("foot_rail_n", "steel", 0, d / 2 - 0.06, 0.25, w - 0.12, 0.025, 0.025)] + \
        legs("steel", w / 2 - 0.06, d / 2 - 0.06, 0.88, 0.05)


def stool():
    """A tall backless kitchen stool: a round oak seat on four splayed steel legs with a footring."""
    return [cyl("seat", "oak", 0, 0, 0.65, 0.18, 0.04),
            box("footring_x", "steel", 0, 0, 0.28, 0.3, 0.02, 0.02),
            box("footring_y", "steel", 0, 0, 0.28, 0.02, 0.3, 0.02)] + legs("steel", 0.12, 0.12, 0.63, 0.03)


# ---- the comms cupboard and the store ----
def server_rack(w=0.6, d=1.0, h=2.0):
    """A 42U server rack cabinet: the black frame, a perforated front door (+y) through which the
    servers and the switch with their lights show, vents on the roof."""
    v = [box("frame", "black", 0, 0, h / 2, w, d, h),
         box("door", "mesh_black", 0, d / 2 + 0.006, h / 2, w - 0.04, 0.012, h - 0.06),
         box("door_handle", "chrome", w / 2 - 0.06, d / 2 + 0.025, 1.1, 0.02, 0.025, 0.2),
         box("roof_vent", "charcoal", 0, 0, h + 0.005, w - 0.1, d - 0.2, 0.01)]
    for i in range(8):
        z = 0.3 + 0.2 * i
        v += [box(f"server{i}", "server_grey", 0, d / 2 + 0.0135, z, w - 0.12, 0.003, 0.15),
              box(f"led{i}", "led_green" if i % 3 else "led_blue", -w / 2 + 0.12, d / 2 + 0.016, z, 0.02, 0.002, 0.01)]
    return v + [box("switch", "charcoal", 0, d / 2 + 0.0135, 1.95 - 0.1, w - 0.12, 0.003, 0.05)]


def ups():
    """A tower uninterruptible power supply: the black box with its display and status lights at
    the front (+y), a vent grille."""
    return [box("body", "black", 0, 0, 0.45, 0.35, 0.65, 0.9),
            box("display", "screen_lit", 0, 0.326, 0.75, 0.12, 0.003, 0.06),
            box("power_button", "led_green", 0, 0.327, 0.65, 0.03, 0.003, 0.03),
            box("grille", "charcoal", 0, 0.326, 0.3, 0.25, 0.003, 0.35)]


def air_conditioning_unit():
    """A wall-mounted split air conditioning unit (the wall behind at -y), centred on the model's
    height: the white casing, the air outlet louvre underneath at the front, the display."""
    return [box("casing", "desk_white", 0, 0, 0, 0.9, 0.24, 0.3),
            box("louvre", "charcoal", 0, 0.08, -0.15, 0.7, 0.06, 0.01),
            box("display", "led_blue", 0.35, 0.121, -0.06, 0.05, 0.002, 0.02),
            box("pipe", "desk_white", -0.4, -0.08, 0.25, 0.06, 0.06, 0.2)]


def shelving_unit(w=1.8, d=0.45, fill=0):
    """A grey steel shelving unit against a wall (behind it at -y): five shelves on angle posts,
    stocked with reams of paper, archive boxes and cartons."""
    v = [box(f"post{i}", "steel", sx * (w / 2 - 0.02), sy * (d / 2 - 0.02), 0.95, 0.035, 0.035, 1.9)
         for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    for i, z in enumerate((0.1, 0.5, 0.9, 1.3, 1.7)):
        v.append(box(f"shelf{i}", "steel", 0, 0, z, w - 0.01, d - 0.01, 0.02))
        kind = (i + fill) % 3
        if kind == 0:  # reams of paper
            v += [box(f"ream{i}_{k}", "paper", -w / 2 + 0.2 + 0.3 * k, 0, z + 0.04, 0.3, 0.21, 0.06)
                  for k in range(int((w - 0.1) / 0.3))]
        elif kind == 1:  # archive boxes
            v += [box(f"archive{i}_{k}", "carton", -w / 2 + 0.25 + 0.42 * k, 0, z + 0.14, 0.38, 0.36, 0.26)
                  for k in range(int((w - 0.1) / 0.42))]
        elif i < 4:  # cartons of stationery
            v += [box(f"carton{i}_{k}", "desk_white", -w / 2 + 0.3 + 0.55 * k, 0, z + 0.12, 0.5, 0.38, 0.22)
                  for k in range(int((w - 0.1) / 0.55))]
    return v


def cardboard_box(w=0.6, d=0.4, h=0.4):
    """A taped brown cardboard box on the floor with a shipping label."""
    return [box("body", "carton", 0, 0, h / 2, w, d, h),
            box("tape", "tape", 0, 0, h + 0.001, 0.06, d, 0.002),
            box("label", "paper", w / 4, 0, h + 0.001, 0.12, 0.1, 0.002)]


# ---- the toilets ----
def toilet():
    """A toilet: the cistern against the wall (-y) with its flush button, the bowl, seat and lid."""
    return [box("cistern", "porcelain", 0, -0.22, 0.62, 0.42, 0.18, 0.4),
            box("flush", "chrome", 0, -0.22, 0.826, 0.1, 0.06, 0.012),
            cyl("bowl", "porcelain", 0, 0.06, 0.2, 0.19, 0.4),
            cyl("seat", "desk_white", 0, 0.07, 0.415, 0.21, 0.03),
            box("pan_back", "porcelain", 0, -0.11, 0.2, 0.3, 0.1, 0.4)]


def wash_basin():
    """A wall-hung wash basin (the wall behind at -y) with a mixer tap and a soap dispenser."""
    return [box("basin", "porcelain", 0, 0.22, 0.8, 0.55, 0.42, 0.14),
            box("bowl", "white_tile", 0, 0.24, 0.865, 0.42, 0.3, 0.01),
            cyl("tap", "chrome", 0, 0.06, 0.94, 0.02, 0.14),
            box("spout", "chrome", 0, 0.11, 1.0, 0.03, 0.1, 0.02),
            cyl("trap", "chrome", 0, 0.1, 0.55, 0.03, 0.36),
            box("soap", "desk_white", 0.33, 0.045, 1.15, 0.1, 0.08, 0.18)]


def mirror(w=0.6, h=0.8):
    """A frameless washroom mirror on the wall (behind at -y), centred on the model's height."""
    return [box("backing", "steel", 0, 0, 0, w, 0.01, h), box("glass", "mirror", 0, 0.006, 0, w - 0.02, 0.002, h - 0.02)]


def hand_dryer():
    """A wall-mounted jet hand dryer (the wall behind at -y): a tall slim body with the hand slot."""
    return [box("body", "aluminium", 0, 0.1, 1.2, 0.3, 0.2, 0.66),
            box("slot", "black", 0, 0.1, 1.36, 0.24, 0.21, 0.05),
            box("badge", "charcoal", 0, 0.201, 1.05, 0.1, 0.002, 0.03)]


# ---- safety and the bike store ----
def first_aid_kit():
    """The first aid point: a green wall cabinet with a white cross (the wall behind at -y),
    centred on the model's height, its sign above it."""
    return [box("cabinet", "first_aid_green", 0, 0, 0, 0.4, 0.14, 0.32),
            box("cross_v", "desk_white", 0, 0.071, 0, 0.06, 0.002, 0.18),
            box("cross_h", "desk_white", 0, 0.071, 0, 0.18, 0.002, 0.06),
            box("handle", "desk_white", 0.17, 0.075, 0, 0.02, 0.01, 0.08),
            box("sign", "first_aid_green", 0, -0.065, 0.32, 0.3, 0.01, 0.15),
            box("sign_cross", "desk_white", 0, -0.059, 0.32, 0.08, 0.002, 0.08)]


def fire_extinguisher():
    """A red extinguisher on its wall bracket (the wall behind at -y) with its sign above."""
    return [box("bracket", "charcoal", 0, -0.085, 0.85, 0.1, 0.02, 0.3),
            cyl("body", "extinguisher_red", 0, 0, 0.75, 0.075, 0.5),
            sph("shoulder", "extinguisher_red", 0, 0, 1.0, 0.075),
            cyl("valve", "black", 0, 0, 1.1, 0.022, 0.08),
            box("lever", "black", 0, 0.04, 1.15, 0.03, 0.12, 0.02),
            turned(cyl("hose", "black", 0.07, 0.03, 0.95, 0.012, 0.3), "0 0.3 0"),
            box("sign", "extinguisher_red", 0, -0.09, 1.45, 0.2, 0.01, 0.2)]


def bike_rack(n=4, pitch=1.0):
    """A row of galvanised Sheffield stands (inverted U hoops, their length along y) on a floor rail
    along x, one bike each side of a hoop."""
    v = [box("rail", "galvanised", 0, 0, 0.01, (n - 1) * pitch + 0.1, 0.06, 0.02)]
    for i in range(n):
        x = -(n - 1) * pitch / 2 + i * pitch
        v += [cyl(f"post_s{i}", "galvanised", x, -0.35, 0.39, 0.03, 0.74),
              cyl(f"post_n{i}", "galvanised", x, 0.35, 0.39, 0.03, 0.74),
              along_y(cyl(f"top{i}", "galvanised", x, 0, 0.76, 0.03, 0.76)),
              box(f"foot_s{i}", "galvanised", x, -0.35, 0.01, 0.12, 0.12, 0.02),
              box(f"foot_n{i}", "galvanised", x, 0.35, 0.01, 0.12, 0.12, 0.02)]
    return v


# ---- the building ----
BIKE_OUT = (1.0, 2.0)       # x, south wall: the bike store's outside door
ENTRANCE = (6.0, 7.8)       # x, south wall: the main entrance (two leaves)
BIKE_IN = (3.9, 4.9)        # y, wall x = 3.5: bike store | reception
RECEPTION_GAP = (6.2, 8.2)  # x, wall y = 6: reception | workspace
MEETING1_DOOR = (13.8, 14.8)  # x, wall y = 6
MEETING2_DOOR = (16.2, 17.2)  # x, wall y = 6
TOILET_DOOR = (4.2, 5.2)    # x, wall y = 13
COMMS_DOOR = (6.3, 7.3)     # x, wall y = 15
STORE_DOOR = (9.0, 10.0)    # x, wall y = 15
KITCHEN_S = (14.0, 16.0)    # x, wall y = 13: kitchen | workspace (an opening)
KITCHEN_E = (15.2, 17.0)    # y, wall x = 19: kitchen | breakout (an opening)


def walls():
    """The outer walls (the main entrance and the bike store's outside door in the south wall);
    the partitions of the bike store, the reception, the meeting rooms, the toilets (with the cubicle
    walls), the comms and store cupboards and the kitchen."""
    v, wall = base.wall_builder(H, T)

    def run(along, fixed, lo, hi, openings=(), c="partition", top=LINTEL):
        """A wall along x (y = fixed) or along y (x = fixed) from lo to hi with openings in it."""
        cut = lo
        for a, b in openings:
            if along == "x":
                wall(cut, fixed, a, fixed, c=c); wall(a, fixed, b, fixed, top, H, c=c)
            else:
                wall(fixed, cut, fixed, a, c=c); wall(fixed, a, fixed, b, top, H, c=c)
            cut = b
        if along == "x": wall(cut, fixed, hi, fixed, c=c)
        else: wall(fixed, cut, fixed, hi, c=c)

    run("x", 0, 0, W, (BIKE_OUT, ENTRANCE), "plaster", 2.3)
    run("x", D, 0, W, (), "plaster")
    run("y", 0, 0, D, (), "plaster")
    run("y", W, 0, D, (), "plaster")
    # the bike store and the reception
    run("x", 5.0, 0, 3.5)
    run("y", 3.5, 0, 5.0, (BIKE_IN,))
    run("y", 3.5, 5.0, 6.0)
    run("x", 6.0, 3.5, 11.0, (RECEPTION_GAP,))
    # the meeting rooms
    run("y", 11.0, 0, 6.0)
    run("y", 15.5, 0, 6.0)
    run("y", 20.0, 0, 6.0)
    run("x", 6.0, 11.0, 20.0, (MEETING1_DOOR, MEETING2_DOOR))
    # the toilets, their cubicle walls, the cupboards, the kitchen
    run("x", 13.0, 0, 5.5, (TOILET_DOOR,), "white_tile")
    run("y", 5.5, 13.0, D, (), "white_tile")
    for x in (1.5, 3.0, 4.5):
        wall(x, 16.4, x, D - F, 0, 2.0, c="partition")
    run("x", 15.0, 5.5, 8.0, (COMMS_DOOR,))
    run("y", 8.0, 15.0, D)
    run("x", 15.0, 8.0, 11.0, (STORE_DOOR,))
    run("y", 11.0, 13.0, D)
    run("x", 13.0, 11.0, 19.0, (KITCHEN_S,))
    run("y", 19.0, 13.0, D, (KITCHEN_E,))
    return v


def floor():
    """Grey carpet tiles everywhere; white tiles in the kitchen and the toilets, bare concrete in
    the bike store and the comms cupboard (thin layers over the slab)."""
    v = base.floor_slab("floor_office", "carpet_tile", W, D)
    v += [box("kitchen", "tile", 15.0, 15.5, 0.0005, 8.0, 5.0, 0.001),
          box("toilets", "white_tile", 2.75, 15.5, 0.0005, 5.5, 5.0, 0.001),
          box("bike_store", "concrete", 1.75, 2.5, 0.0005, 3.5, 5.0, 0.001),
          box("comms", "concrete", 6.75, 16.5, 0.0005, 2.5, 3.0, 0.001)]
    return v


class World:
    def __init__(self):
        self.out = [base.model("walls", (0, 0, 0, 0), walls()),
                    base.model("floor", (0, 0, 0, 0), floor()),
                    base.model("ceiling", (0, 0, 0, 0), base.ceiling_slab(W, D, H))]
        self.count = {}

    def add(self, cls, pose, vis, numbered=True):
        """Adds a model named cls_<n> (n counting up per class), or cls when numbered is False."""
        self.count[cls] = self.count.get(cls, 0) + 1
        name = f"{cls}_{self.count[cls]}" if numbered else cls
        self.out.append(base.model(name, pose, vis))

    def at(self, pose, dx, dy, dz=0.0, dyaw=0.0):
        """The pose dx, dy, dz off a model's pose in its own frame, turned by dyaw more."""
        x, y, z, yaw = pose
        c, s = math.cos(yaw), math.sin(yaw)
        return (round(x + c * dx - s * dy, 4), round(y + s * dx + c * dy, 4), z + dz, round(yaw + dyaw, 4))

    def door_x(self, hinge_x, wall_y, side, w=0.92):
        """A leaf standing open beside an opening in a wall along x, hinged at hinge_x, swung into
        the side (+1 north, -1 south) and lying along y."""
        self.add("door", (hinge_x, wall_y + side * (F + 0.01 + w / 2), 0, WEST), door(w))

    def door_y(self, wall_x, hinge_y, side, w=0.92):
        """A leaf standing open beside an opening in a wall along y, swung into the side (+1 east,
        -1 west) and lying along x."""
        self.add("door", (wall_x + side * (F + 0.01 + w / 2), hinge_y, 0, N), door(w))

    def window_s(self, x): self.add("window", (x, F + 0.02, 1.55, N), base.window())
    def window_n(self, x): self.add("window", (x, D - F - 0.02, 1.55, S), base.window())
    def window_w(self, y): self.add("window", (F + 0.02, y, 1.55, E), base.window())
    def window_e(self, y): self.add("window", (W - F - 0.02, y, 1.55, WEST), base.window())

    def workstation(self, pose, pedestal_side=-1):
        """A desk with its monitor, docking station, the pedestal under it and the task chair."""
        self.add("desk", pose, desk())
        self.add("monitor", self.at(pose, 0, 0.2, 0.75, math.pi), monitor())
        self.add("docking_station", self.at(pose, 0.45, 0.12, 0.75), docking_station())
        self.add("pedestal", self.at(pose, pedestal_side * 0.52, -0.1, 0, math.pi), pedestal())
        self.add("task_chair", self.at(pose, -pedestal_side * 0.15, -0.78), task_chair())

    def standing(self, pose):
        self.add("standing_desk", pose, standing_desk())
        self.add("monitor", self.at(pose, 0, 0.17, 1.065, math.pi), monitor())


def bike_store(w):
    w.add("door", ((BIKE_OUT[0] + BIKE_OUT[1]) / 2, 0, 0, N), door(0.98))  # the outside door, shut
    w.door_y(3.5, BIKE_IN[1] - 0.04, +1)  # into the reception, hinged at its north side
    w.add("bike_rack", (1.0, 2.5, 0, E), bike_rack(), numbered=False)
    w.window_w(2.5)


def reception(w):
    e0, e1 = ENTRANCE
    w.add("door", (e0 + 0.04, F + 0.01 + 0.46, 0, WEST), door())  # two leaves swung in
    w.add("door", (e1 - 0.04, F + 0.01 + 0.46, 0, WEST), door())
    desk_pose = (9.4, 3.2, 0, S)  # visitors to the south
    w.add("reception_desk", desk_pose, reception_desk(), numbered=False)
    w.add("monitor", w.at(desk_pose, 0.4, -0.15, 0.75, math.pi), monitor())
    w.add("task_chair", (9.4, 4.25, 0, S), task_chair("fabric_grey"))
    w.add("sign_in_kiosk", (10.3, 1.5, 0, S), sign_in_kiosk(), numbered=False)
    w.add("sofa", (3.5 + F + 0.45, 2.2, 0, E), sofa("sofa_grey"))
    w.add("coffee_table", (5.1, 2.2, 0, E), coffee_table())
    w.add("coat_stand", (4.9, 0.65, 0, N), coat_stand(), numbered=False)
    w.add("fire_extinguisher", (5.5, F + 0.1, 0, N), fire_extinguisher())
    w.add("potted_plant", (4.0, 5.5, 0, N), base.plant())
    w.add("potted_plant", (10.55, 5.5, 0, N), base.plant())
    w.window_s(4.6)
    w.window_s(9.3)


def meeting_rooms(w):
    for k, (x0, x1, door_xs, hinge, screen_west) in enumerate(((11.0, 15.5, MEETING1_DOOR, MEETING1_DOOR[1] - 0.04, True),
                                                               (15.5, 20.0, MEETING2_DOOR, MEETING2_DOOR[0] + 0.04, False))):
        cx, cy = (x0 + x1) / 2, 3.0
        w.door_x(hinge, 6.0, -1)
        w.add("meeting_table", (cx, cy, 0, N), meeting_table())
        for dx in (-0.8, 0, 0.8):
            w.add("meeting_chair", (cx + dx, cy - 0.9, 0, N), meeting_chair())
            w.add("meeting_chair", (cx + dx, cy + 0.9, 0, S), meeting_chair())
        w.add("speakerphone", (cx, cy, 0.75, N), speakerphone())
        if screen_west:
            w.add("display_screen", (x0 + F + 0.075, cy, 1.45, E), display_screen())
            w.add("whiteboard", (x1 - F - 0.02, cy, 1.4, WEST), whiteboard())
        else:
            w.add("whiteboard", (x0 + F + 0.02, cy, 1.4, E), whiteboard())
            w.add("display_screen", (x1 - F - 0.075, cy, 1.45, WEST), display_screen())
        w.window_s(cx)


def quiet_corner(w):
    for y in (1.0, 2.3):
        w.add("phone_booth", (20.0 + F + 0.56, y, 0, E), phone_booth())
    for x in (23.0, 24.7, 26.4):
        w.standing((x, F + 0.4, 0, S))
    for y in (3.9, 4.82):
        w.add("locker", (W - F - 0.235, y, 0, WEST), locker())
    w.add("potted_plant", (27.5, 2.2, 0, N), base.plant())
    w.add("fire_extinguisher", (W - F - 0.1, 6.6, 0, WEST), fire_extinguisher())
    w.window_s(23.0)
    w.window_s(26.4)
    w.window_e(1.9)


def workspace(w):
    for bx in (6.2, 10.6, 15.0, 19.4, 23.8):
        for dx in (-0.8, 0.8):
            w.workstation((bx + dx, 9.08, 0, N), -1 if dx < 0 else 1)
            w.workstation((bx + dx, 9.92, 0, S), 1 if dx < 0 else -1)
            w.add("desk_divider", (bx + dx, 9.5, 0, N), desk_divider())
    # the west column: lockers on the bike store's wall, standing desks under the windows
    for x in (0.5, 1.42, 2.34):
        w.add("locker", (x, 5.0 + F + 0.235, 0, N), locker())
    for y in (8.0, 11.0):
        w.standing((F + 0.4, y, 0, WEST))
        w.window_w(y)
    w.add("potted_plant", (3.0, 12.5, 0, N), base.plant())
    w.window_e(8.5)
    w.window_e(11.2)


def toilets(w):
    w.door_x(TOILET_DOOR[1] - 0.04, 13.0, +1)
    for x in (0.75, 2.25, 3.75):
        w.add("toilet", (x, D - F - 0.32, 0, S), toilet())
    for y in (14.0, 15.2):
        w.add("wash_basin", (F + 0.01, y, 0, E), wash_basin())
        w.add("mirror", (F + 0.01, y, 1.55, E), mirror(0.55, 0.75))
    w.add("hand_dryer", (F + 0.01, 16.0, 0, E), hand_dryer())
    w.add("hand_dryer", (5.5 - F - 0.01, 14.4, 0, WEST), hand_dryer())
    w.add("waste_bin", (5.1, 15.3, 0, WEST), waste_bin())


def alcove_and_cupboards(w):
    # the print alcove
    w.add("printer", (11.0 - F - 0.31, 14.2, 0, WEST), printer(), numbered=False)
    w.add("shredder", (11.0 - F - 0.16, 13.45, 0, WEST), shredder(), numbered=False)
    w.add("recycling_bin", (8.2, 15.0 - F - 0.21, 0, S), recycling_bin())
    w.add("first_aid_kit", (5.5 + F + 0.08, 14.2, 1.45, E), first_aid_kit(), numbered=False)
    w.add("fire_extinguisher", (5.5 + F + 0.1, 13.5, 0, E), fire_extinguisher())
    # the comms cupboard
    w.door_x(COMMS_DOOR[1] - 0.04, 15.0, +1)
    w.add("server_rack", (6.4, D - F - 0.51, 0, S), server_rack(), numbered=False)
    w.add("ups", (7.5, D - F - 0.335, 0, S), ups(), numbered=False)
    w.add("air_conditioning_unit", (5.5 + F + 0.13, 16.3, 2.3, E), air_conditioning_unit(), numbered=False)
    # the store cupboard
    w.door_x(STORE_DOOR[0] + 0.04, 15.0, +1)
    w.add("shelving_unit", (9.5, D - F - 0.235, 0, S), shelving_unit(1.8, 0.45, 0))
    w.add("shelving_unit", (11.0 - F - 0.235, 15.95, 0, WEST), shelving_unit(1.4, 0.45, 1))
    w.add("cardboard_box", (8.0 + F + 0.31, 15.9, 0, N), cardboard_box())
    w.add("cardboard_box", (8.0 + F + 0.31, 15.9, 0.4, N), cardboard_box(0.5, 0.36, 0.3))
    w.add("cardboard_box", (8.0 + F + 0.26, 16.6, 0, N), cardboard_box(0.5, 0.5, 0.45))


def kitchen(w):
    y = D - F - 0.33  # the counter run along the north wall
    w.add("kitchen_counter", (12.25, y, 0, S), kitchen_counter(2.4))
    w.add("kitchen_sink", (13.91, y, 0, S), kitchen_sink(), numbered=False)
    w.add("dishwasher", (14.67, y, 0, S), dishwasher(), numbered=False)
    w.add("kitchen_counter", (15.98, y, 0, S), kitchen_counter(2.0))
    w.add("fridge", (17.42, D - F - 0.36, 0, S), fridge(), numbered=False)
    w.add("water_dispenser", (18.45, D - F - 0.18, 0, S), water_dispenser(), numbered=False)
    w.add("coffee_machine", (12.0, D - F - 0.38, 0.92, S), coffee_machine(), numbered=False)
    w.add("microwave", (16.4, D - F - 0.3, 0.92, S), microwave(), numbered=False)
    w.add("kitchen_table", (15.0, 15.4, 0, N), kitchen_table(), numbered=False)
    for sx, sy, yaw in ((14.5, 14.65, N), (15.5, 14.65, N), (14.5, 16.15, S), (15.5, 16.15, S)):
        w.add("stool", (sx, sy, 0, yaw), stool())
    w.add("waste_bin", (11.0 + F + 0.2, 16.95, 0, E), waste_bin())
    w.add("recycling_bin", (11.0 + F + 0.21, 16.3, 0, E), recycling_bin())
    w.add("fire_extinguisher", (12.0, 13.0 + F + 0.1, 0, N), fire_extinguisher())
    w.window_n(12.4)
    w.window_n(16.0)


def breakout(w):
    w.add("sofa", (22.5, D - F - 0.45, 0, S), sofa("sofa_orange"))
    w.add("coffee_table", (22.5, 16.3, 0, N), coffee_table())
    for (x, y, yaw, c) in ((21.1, 16.1, E, "cushion_red"), (23.9, 16.1, WEST, "cushion_blue"),
                           (22.5, 15.2, N, "cushion_yellow")):
        w.add("bean_bag", (x, y, 0, yaw), bean_bag(c))
    w.add("foosball_table", (26.0, 15.5, 0, N), foosball_table(), numbered=False)
    w.add("potted_plant", (27.5, 17.5, 0, N), base.plant())
    w.add("potted_plant", (19.5, 13.5, 0, N), base.plant())
    w.window_n(22.5)
    w.window_n(26.0)
    w.window_e(14.6)
    w.window_e(16.8)


def main():
    w = World()
    bike_store(w)
    reception(w)
    meeting_rooms(w)
    quiet_corner(w)
    workspace(w)
    toilets(w)
    alcove_and_cupboards(w)
    kitchen(w)
    breakout(w)
    cool, warm = "0.8 0.8 0.78", "0.85 0.8 0.7"
    spots = [("light_bike_store", 1.8, 2.5, cool), ("light_reception_w", 5.5, 3.0, warm),
             ("light_reception_e", 9.0, 3.0, warm), ("light_meeting_1", 13.25, 3.0, cool),
             ("light_meeting_2", 17.75, 3.0, cool), ("light_quiet_corner", 24.0, 3.0, cool),
             ("light_west_column", 1.8, 9.0, cool), ("light_toilets", 2.75, 15.0, cool),
             ("light_alcove", 8.2, 14.0, cool), ("light_comms", 6.75, 16.5, cool),
             ("light_store", 9.5, 16.5, cool), ("light_kitchen_w", 13.0, 15.5, warm),
             ("light_kitchen_e", 17.0, 15.5, warm), ("light_breakout_w", 21.5, 15.5, warm),
             ("light_breakout_e", 25.5, 15.5, warm)]
    spots += [(f"light_workspace_{i + 1}", x, 9.5, cool) for i, x in enumerate((6.2, 10.6, 15.0, 19.4, 23.8))]
    lights = [base.point_light(name, x, y, H - 0.25, rgb) for name, x, y, rgb in spots]
    print(base.world_sdf("semsplat_openoffice", """The semsplat open office: a modern open-plan tech office of 28 m x 18 m on one floor
     (the bike store, the reception and two meeting rooms along the street front; the open-plan
     workspace with five banks of desks, standing desks, lockers and two phone booths; the
     toilets, the print alcove, the comms and the store cupboards, the office kitchen and the
     breakout area along the north) for measuring on a world nobody tuned on. Generated by
     openoffice_models/make_openoffice.py; all models are inline.""", lights, w.out))


if __name__ == "__main__":
    main()
