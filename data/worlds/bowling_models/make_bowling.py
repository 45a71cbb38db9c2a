#!/usr/bin/env python3
"""Writes data/worlds/bowling.world: a small bowling centre of 30 m x 20 m on one floor, for
measuring the semantic stack on a world nobody tuned on. x runs west to east, y south to north;
the street front with the entrance is the south wall.

The lanes hall (the north part, y > 8.5): six bowling lanes in three pairs running west to east,
the bowlers at the west end. Each lane is a long low box (the approach with its dots and the foul
line, the lane bed with the target arrows, the gutters, the pin deck), ten bowling pins stand on
its pin deck, and the pinsetter housing with its painted masking unit closes its east end. A
scoring monitor hangs from the ceiling over the start of each approach, facing the bowlers. At
each pair of lanes, in the settee area behind the approaches: the ball return (its hood and the
rails with the balls), a curved bench facing the lanes and a small round side table; a trash can
between each two benches.
The concourse behind the settee areas (the west end): four ball racks of house balls along the
back (west) wall, lockers for the league bowlers in the north-west corner, a fire extinguisher
between them.
The mechanic's room behind the pinsetters (the east strip, x > 27.1, y > 8.5), entered from the
corridor: a workbench with a vice and a pegboard of tools, a rolling tool cabinet, shelving units
of spare parts, a trash can, a fire extinguisher.

The south part (y < 8.5), west to east:
- the arcade corner (open to the concourse and the lobby): six arcade machines along the west
  wall, two claw machines in the south-west corner, an air hockey table, the prize counter (a
  glass display counter with the prize shelves behind it) on the south wall, a trash can;
- the lobby: the entrance (a double door in the south wall) with an exit sign over it, two
  street windows, the front desk / shoe counter (the counter with a till on it, the rental shoe
  shelves (cubbies) behind it, the shoe sanitizer at its south end), a trash can, a fire
  extinguisher;
- the bar and snack counter: the bar counter with six bar stools, the beer tap and a second till
  on it; behind it on the north wall a glass-door drinks fridge, a deep fryer and the lit menu
  board above them; two street windows, a trash can, a fire extinguisher;
- the east block, off a corridor (y 4..5.5) that opens from the bar: the party room (two party
  tables end to end with ten chairs, a TV on the east wall, two windows, a trash can) and the
  manager's office (a desk, an office chair, a computer, a safe, a window, a trash can) south of
  the corridor; the men's toilets (a toilet in a cubicle, two urinals, a sink with a mirror, a
  hand dryer, a trash can) and the women's toilets (two toilets in cubicles, two sinks with
  mirrors, a hand dryer, a trash can) north of it; at the corridor's east end the door to the
  mechanic's room (north) and the fire exit (east wall) with an exit sign and a fire extinguisher.

Every model is inline (boxes, cylinders, spheres), so the world needs no model path. Model names
are what a world author would type; the class is the name less its _<number> ("ball_rack_3" ->
"ball rack", "air_hockey_table" -> "air hockey table"). The primitives and the SDF writing are
the office generator's.
Run: python3 data/worlds/bowling_models/make_bowling.py > data/worlds/bowling.world"""

import math
import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document, door, window, desk)
sys.path.insert(0, os.path.join(HERE, "..", "restaurant_models"))
import make_restaurant as rest  # noqa: E402  (washroom fittings, extinguisher, exit sign)

W, D, H = 30.0, 20.0, 3.5  # floor width (x), depth (y), wall height
T = 0.1                    # wall thickness
YL = 8.5                   # the lanes hall's south wall (x > XA) / the open front of the concourse
XA = 9.0                   # the start of the approaches (west end of the lanes)
LANE_LEN = 15.6            # approach (4.6) + lane bed to the end of the pin deck
XP = XA + LANE_LEN         # the pinsetters' front (24.6)
XM = 27.1                  # the wall between the pinsetters and the mechanic's room
XB = 20.5                  # the east block's west wall (party room, men's toilets)
YC0, YC1 = 4.0, 5.5        # the corridor of the east block
XPO = 26.0                 # party room | office
XWM = 23.8                 # men's | women's
LINTEL = 2.1               # the top of the inner doorways
LANE_W = 1.5               # a lane with its gutters

ENTRANCE = (8.6, 10.4)     # x, south wall (two leaves)
FIRE_EXIT = (6.5, 7.5)     # y, east wall (shut)
MECH_DOOR = (28.2, 29.2)   # x, wall y = YL
PARTY_DOOR = (24.8, 25.8)  # x, wall y = YC0
OFFICE_DOOR = (28.3, 29.3) # x, wall y = YC0
MENS_DOOR = (22.7, 23.7)   # x, wall y = YC1
WOMENS_DOOR = (23.95, 24.95)  # x, wall y = YC1

N, S, E, WEST = 0.0, 3.1416, -1.5708, 1.5708  # yaw that turns a model's front (+y) north/south/east/west

base.COL.update({
    "carpet": "0.2 0.16 0.38", "lobby_tile": "0.78 0.76 0.72", "tile": "0.86 0.88 0.88",
    "concrete": "0.55 0.55 0.53", "plaster": "0.9 0.88 0.84", "partition": "0.86 0.85 0.82",
    "white_tile": "0.92 0.93 0.93", "pit_wall": "0.18 0.18 0.2",
    "approach_wood": "0.86 0.72 0.5", "lane_wood": "0.82 0.66 0.44", "dark_wood": "0.3 0.2 0.12",
    "gutter": "0.12 0.12 0.14", "pin_deck": "0.76 0.6 0.4", "pin_white": "0.96 0.96 0.94",
    "pin_red": "0.8 0.08 0.08", "machine_grey": "0.3 0.31 0.33", "pit_black": "0.04 0.04 0.05",
    "masking_blue": "0.1 0.2 0.55", "masking_orange": "0.95 0.5 0.1", "masking_yellow": "0.95 0.85 0.2",
    "return_body": "0.16 0.17 0.2", "return_hood": "0.75 0.1 0.12", "chrome": "0.82 0.83 0.85",
    "ball_red": "0.75 0.08 0.1", "ball_blue": "0.1 0.25 0.7", "ball_green": "0.1 0.55 0.25",
    "ball_purple": "0.45 0.15 0.6", "ball_orange": "0.9 0.45 0.08", "ball_black": "0.05 0.05 0.06",
    "ball_pink": "0.9 0.4 0.6", "ball_yellow": "0.92 0.8 0.15", "ball_teal": "0.1 0.55 0.6",
    "screen": "0.05 0.06 0.08", "screen_lit": "0.25 0.45 0.6", "score_cell": "0.9 0.92 0.95",
    "score_band": "0.95 0.75 0.15", "settee_vinyl": "0.1 0.35 0.55", "settee_base": "0.2 0.2 0.22",
    "table_top": "0.85 0.85 0.82", "cup_red": "0.8 0.1 0.1",
    "counter_front": "0.15 0.2 0.35", "counter_top": "0.3 0.3 0.32", "stripe_red": "0.8 0.1 0.15",
    "cubby_wood": "0.6 0.45 0.28", "shoe_red": "0.7 0.12 0.1", "shoe_blue": "0.15 0.25 0.55",
    "shoe_tan": "0.7 0.55 0.35", "shoe_sole": "0.85 0.85 0.82", "sanitizer_body": "0.88 0.9 0.92",
    "uv_violet": "0.5 0.3 0.9", "display_red": "0.85 0.1 0.1", "rack_steel": "0.5 0.52 0.55",
    "bar_wood": "0.32 0.2 0.12", "bar_top": "0.15 0.15 0.16", "brass": "0.8 0.65 0.3",
    "steel": "0.78 0.79 0.8", "dark_steel": "0.45 0.46 0.48", "leather": "0.12 0.12 0.13",
    "tap_red": "0.75 0.1 0.1", "tap_gold": "0.85 0.7 0.2", "tap_black": "0.1 0.1 0.1",
    "fridge_black": "0.1 0.1 0.11", "glass": "0.6 0.75 0.85", "bottle_green": "0.15 0.4 0.2",
    "bottle_amber": "0.6 0.35 0.1", "can_red": "0.8 0.1 0.12", "can_silver": "0.75 0.76 0.78",
    "can_blue": "0.15 0.3 0.7", "fridge_logo": "0.85 0.1 0.1", "oil": "0.8 0.65 0.2",
    "filter": "0.42 0.44 0.46", "menu_back": "0.08 0.08 0.1", "menu_light": "0.96 0.93 0.8",
    "food_brown": "0.65 0.4 0.18", "food_yellow": "0.95 0.78 0.25", "food_red": "0.8 0.2 0.1",
    "arcade_red": "0.7 0.08 0.12", "arcade_blue": "0.1 0.2 0.65", "arcade_green": "0.1 0.5 0.2",
    "arcade_black": "0.07 0.07 0.08", "marquee_lit": "0.95 0.9 0.5", "button_red": "0.9 0.1 0.1",
    "button_yellow": "0.95 0.85 0.1", "button_blue": "0.1 0.4 0.9", "claw_pink": "0.9 0.35 0.6",
    "plush_yellow": "0.95 0.82 0.2", "plush_pink": "0.95 0.55 0.7", "plush_blue": "0.35 0.55 0.9",
    "plush_brown": "0.55 0.35 0.2", "plush_green": "0.4 0.75 0.35", "hockey_white": "0.94 0.95 0.96",
    "hockey_blue": "0.15 0.35 0.8", "hockey_red": "0.8 0.12 0.12", "hockey_rail": "0.2 0.2 0.25",
    "prize_wood": "0.55 0.38 0.22", "cloth_party": "0.95 0.55 0.15", "paper_plate": "0.96 0.96 0.94",
    "cup_blue": "0.15 0.4 0.85", "chair_plastic": "0.15 0.35 0.7", "chair_leg": "0.55 0.57 0.6",
    "porcelain": "0.97 0.97 0.97", "mirror": "0.8 0.85 0.88", "workbench_wood": "0.62 0.48 0.3",
    "pegboard": "0.75 0.62 0.42", "tool_red": "0.78 0.1 0.08", "tool_black": "0.1 0.1 0.1",
    "parts_box": "0.2 0.35 0.7", "parts_grey": "0.5 0.5 0.52", "belt_black": "0.08 0.08 0.08",
    "safe_grey": "0.32 0.34 0.36", "locker_orange": "0.85 0.45 0.1", "locker_grey": "0.6 0.62 0.65",
    "grey_bin": "0.42 0.45 0.48", "extinguisher_red": "0.8 0.08 0.06", "exit_green": "0.05 0.6 0.25",
    "paper": "0.96 0.96 0.94", "number_white": "0.95 0.95 0.95",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
hand_dryer, fire_extinguisher, exit_sign = rest.hand_dryer, rest.fire_extinguisher, rest.exit_sign
toilet, urinal, sink, mirror = rest.toilet, rest.urinal, rest.sink, rest.mirror
turned, along_x, along_y = base.turned, base.along_x, base.along_y

PIN_ROW = 0.264    # rows of the pin triangle, one behind the other
PIN_SPACE = 0.3048  # pins 12 in apart within a row


def castors(hx, hy, r=0.04):
    return [sph(f"castor{i}", "tool_black", sx * hx, sy * hy, r, r)
            for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]


# ---- the lanes (lane frame: x along the lane toward the pins, y across it, z up) ----
def bowling_lane(length=LANE_LEN, approach=4.6, w=LANE_W):
    """A lane as a long low box: the maple approach with two rows of locator dots and the black
    foul line, the lane bed with its seven target arrows and the dots ahead of them, a gutter on
    each side, the pin deck with its ten pin spots at the far end."""
    bed, lw = length - approach, 1.06
    v = [box("approach", "approach_wood", approach / 2, 0, 0.04, approach, w, 0.08),
         box("foul_line", "black", approach + 0.01, 0, 0.0805, 0.02, w, 0.001),
         box("lane_bed", "lane_wood", approach + bed / 2, 0, 0.04, bed, lw, 0.08)]
    gw = (w - lw) / 2
    v += [box(f"gutter{k}", "gutter", approach + bed / 2, s * (lw / 2 + gw / 2), 0.015, bed, gw, 0.03)
          for k, s in enumerate((-1, 1))]
    for r, x in enumerate((0.9, 3.7)):
        v += [box(f"approach_dot{r}_{i}", "dark_wood", x, (i - 2) * 0.2, 0.0805, 0.03, 0.03, 0.001) for i in range(5)]
    v += [box(f"arrow{i}", "dark_wood", approach + 4.3 + (3 - abs(i - 3)) * 0.15, (i - 3) * 0.13, 0.0805,
              0.14, 0.03, 0.001) for i in range(7)]
    v += [box(f"lane_dot{i}", "dark_wood", approach + 2.1, (i - 4.5) * 0.1, 0.0805, 0.02, 0.02, 0.001)
          for i in range(10) if i not in (4, 5)]
    deck0 = length - 1.0
    v.append(box("pin_deck", "pin_deck", deck0 + 0.5, 0, 0.0805, 1.0, lw, 0.001))
    for k in range(4):
        v += [box(f"pin_spot{k}_{j}", "black", deck0 + 0.05 + k * PIN_ROW, (j - k / 2) * PIN_SPACE, 0.081,
                  0.03, 0.03, 0.001) for j in range(k + 1)]
    return v


def bowling_pins():
    """The ten pins of a lane in their triangle, the head pin toward the bowler: each a white
    maple pin (the belly, the neck, the head) with two red neck stripes."""
    v = []
    n = 0
    for k in range(4):
        for j in range(k + 1):
            x, y = k * PIN_ROW, (j - k / 2) * PIN_SPACE
            v += [cyl(f"base{n}", "pin_white", x, y, 0.04, 0.04, 0.08),
                  sph(f"belly{n}", "pin_white", x, y, 0.13, 0.06),
                  cyl(f"neck{n}", "pin_white", x, y, 0.25, 0.026, 0.12),
                  cyl(f"stripe_a{n}", "pin_red", x, y, 0.245, 0.028, 0.012),
                  cyl(f"stripe_b{n}", "pin_red", x, y, 0.27, 0.028, 0.012),
                  sph(f"head{n}", "pin_white", x, y, 0.335, 0.034)]
            n += 1
    return v


def pinsetter(w=LANE_W, depth=XM - T / 2 - XP, h=2.6, art=0):
    """The pinsetter at a lane's end: the dark pit below with its black cushion, the machine's
    grey housing over and behind it, and across its front the masking unit, a painted panel
    (blue with orange and yellow stripes, spaced a little differently on each lane) that hides the machine from the bowlers."""
    ww = w - 0.04
    v = [box("pit", "pit_black", 0.3, 0, 0.01, 0.6, ww, 0.02),
         box("pit_cushion", "pit_black", 0.62, 0, 0.45, 0.04, ww - 0.06, 0.8),
         box("housing", "machine_grey", (0.64 + depth) / 2, 0, h / 2, depth - 0.64, ww, h),
         box("upper", "machine_grey", 0.35, 0, 0.9 + (h - 0.9) / 2, 0.58, ww, h - 0.9),
         box("side_l", "machine_grey", 0.32, -ww / 2 + 0.02, 0.45, 0.64, 0.04, 0.9),
         box("side_r", "machine_grey", 0.32, ww / 2 - 0.02, 0.45, 0.64, 0.04, 0.9),
         box("masking_unit", "masking_blue", 0.03, 0, 1.55, 0.06, w, 1.3)]
    for i, (c, z) in enumerate((("masking_orange", 1.25), ("masking_yellow", 1.45), ("masking_orange", 1.9))):
        v.append(box(f"stripe{i}", c, -0.002, 0, z + 0.05 * art * (i - 1), 0.004, w - 0.02, 0.08))
    v.append(box("number_plate", "number_white", -0.002, 0, 2.05, 0.004, 0.3, 0.16))
    v += [cyl(f"turret{i}", "dark_steel", 1.3, (i - 0.5) * 0.5, h + 0.15, 0.18, 0.3) for i in range(2)]
    return v


def ball_return():
    """A ball return between the two lanes of a pair, at the back of their approaches: the base,
    the red hood where the balls come up (its air blower on top) toward the lanes (+x), the twin
    chrome rails toward the bowlers with three balls waiting on them."""
    v = [box("plinth", "return_body", 0, 0, 0.03, 1.3, 0.56, 0.06),
         box("body", "return_body", 0.35, 0, 0.36, 0.6, 0.5, 0.6),
         along_x(cyl("hood", "return_hood", 0.35, 0, 0.66, 0.25, 0.6)),
         box("blower", "filter", 0.35, 0, 0.915, 0.22, 0.14, 0.02),
         box("support", "return_body", -0.55, 0, 0.3, 0.1, 0.3, 0.56)]
    v += [along_x(cyl(f"rail{k}", "chrome", -0.3, s * 0.09, 0.6, 0.02, 0.7)) for k, s in enumerate((-1, 1))]
    v += [sph(f"ball{i}", c, x, 0, 0.68, 0.108)
          for i, (x, c) in enumerate(((-0.56, "ball_purple"), (-0.34, "ball_blue"), (-0.12, "ball_black")))]
    return v


def scoring_monitor():
    """An overhead scoring monitor hung from the ceiling on a pole, its screen toward the bowlers
    (+y): the score sheet of ten frames for the players and the total column, centred on the
    model's height."""
    v = [box("housing", "black", 0, 0, 0, 1.0, 0.08, 0.6),
         box("screen", "screen_lit", 0, 0.041, 0, 0.94, 0.004, 0.54),
         box("band", "score_band", 0, 0.044, 0.23, 0.9, 0.002, 0.05),
         cyl("pole", "dark_metal", 0, -0.02, 0.65, 0.03, 0.7),
         box("ceiling_plate", "dark_metal", 0, -0.02, 0.99, 0.2, 0.2, 0.02)]
    for r in range(4):
        v += [box(f"cell{r}_{c}", "score_cell", -0.4 + 0.082 * c, 0.044, 0.12 - 0.1 * r, 0.07, 0.002, 0.07)
              for c in range(11)]
    return v


def bench(R=1.4, n=5, seg=0.6):
    """A curved bowlers' bench (settee) in the settee area: n upholstered segments on an arc round
    a point R in front of the middle one (+y), each with its dark base, the blue vinyl seat
    cushion and a back."""
    v, step = [], seg / R
    for i in range(n):
        th = (i - (n - 1) / 2) * step
        px, py = R * math.sin(th), R * (1 - math.cos(th))
        c, s = math.cos(th), math.sin(th)

        def at(name, col, dx, dy, z, sx, sy, sz):
            return turned(box(f"{name}{i}", col, px + dx * c - dy * s, py + dx * s + dy * c, z, sx, sy, sz),
                          f"0 0 {th:.4f}")
        v += [at("base", "settee_base", 0, 0, 0.19, seg, 0.5, 0.38),
              at("cushion", "settee_vinyl", 0, 0.01, 0.42, seg, 0.5, 0.08),
              at("back", "settee_vinyl", 0, -0.24, 0.72, seg, 0.1, 0.55)]
    return v


def side_table():
    """A small round table on a pedestal beside the bench, a drink on it."""
    return [cyl("top", "table_top", 0, 0, 0.71, 0.3, 0.03),
            cyl("pedestal", "dark_metal", 0, 0, 0.36, 0.04, 0.68),
            cyl("foot", "dark_metal", 0, 0, 0.015, 0.22, 0.03),
            cyl("cup", "cup_red", 0.1, 0.05, 0.785, 0.04, 0.12)]


# ---- the concourse ----
def ball_rack(length=1.8, d=0.45):
    """A three-tier rack of house balls against the wall (behind it at -y): end frames, two chrome
    rails per tier, seven balls on each tier, their colour by weight."""
    colours = ("ball_red", "ball_blue", "ball_green", "ball_purple", "ball_orange", "ball_pink",
               "ball_yellow", "ball_teal", "ball_black")
    v = [box(f"end{k}", "rack_steel", s * (length / 2 - 0.02), 0, 0.65, 0.04, d, 1.3) for k, s in enumerate((-1, 1))]
    v.append(box("back", "rack_steel", 0, -d / 2 + 0.02, 0.65, length, 0.02, 1.3))
    for t, z in enumerate((0.3, 0.7, 1.1)):
        v += [along_x(cyl(f"rail{t}_{k}", "chrome", 0, s * 0.09, z, 0.015, length - 0.04)) for k, s in enumerate((-1, 1))]
        v += [sph(f"ball{t}_{i}", colours[(3 * t + i) % len(colours)], -length / 2 + 0.17 + 0.243 * i, 0, z + 0.07, 0.108)
              for i in range(7)]
    return v


def locker():
    """A column of four small steel lockers for league bowlers' balls and shoes (front +y): the
    orange doors with their handles, vents and number plates."""
    v = [box("body", "locker_grey", 0, 0, 0.95, 0.45, 0.5, 1.9)]
    for k in range(4):
        z = 0.05 + 0.46 * k + 0.23
        v += [box(f"door{k}", "locker_orange", 0, 0.252, z, 0.42, 0.005, 0.43),
              box(f"handle{k}", "dark_metal", 0.15, 0.26, z, 0.03, 0.015, 0.1),
              box(f"vent{k}", "dark_metal", 0, 0.256, z + 0.12, 0.2, 0.002, 0.06),
              box(f"plate{k}", "number_white", -0.12, 0.256, z + 0.12, 0.08, 0.002, 0.05)]
    return v


# ---- the arcade corner ----
def arcade_machine(theme="arcade_red"):
    """An upright video arcade cabinet (the player at +y): the cabinet with its side art, the lit
    marquee on top, the screen tilted back, the control panel with a joystick and buttons, the
    coin door below."""
    v = [box("cabinet", "arcade_black", 0, -0.05, 0.95, 0.72, 0.75, 1.9),
         box("side_art_l", theme, -0.362, -0.05, 0.95, 0.004, 0.74, 1.8),
         box("side_art_r", theme, 0.362, -0.05, 0.95, 0.004, 0.74, 1.8),
         box("marquee", "marquee_lit", 0, 0.33, 1.78, 0.68, 0.02, 0.2),
         turned(box("screen", "screen_lit", 0, 0.3, 1.38, 0.6, 0.01, 0.48), "-0.25 0 0"),
         turned(box("panel", theme, 0, 0.42, 1.0, 0.72, 0.3, 0.05), "0.2 0 0"),
         cyl("joystick", "arcade_black", -0.18, 0.44, 1.08, 0.01, 0.1),
         sph("knob", "button_red", -0.18, 0.44, 1.14, 0.025),
         box("coin_door", "dark_metal", 0, 0.326, 0.55, 0.3, 0.004, 0.35)]
    v += [cyl(f"button{i}", c, 0.02 + 0.09 * i, 0.44, 1.05, 0.02, 0.02)
          for i, c in enumerate(("button_red", "button_yellow", "button_blue"))]
    return v


def claw_machine():
    """A claw crane machine (the player at +y): the pink base with the prize chute and the
    joystick, the glass cabinet above full of plush toys, the claw hanging from its gantry, the
    lit marquee on top."""
    plush = ("plush_yellow", "plush_pink", "plush_blue", "plush_brown", "plush_green")
    v = [box("base", "claw_pink", 0, 0, 0.45, 0.9, 0.9, 0.9),
         box("chute", "arcade_black", 0.28, 0.451, 0.45, 0.24, 0.004, 0.26),
         box("panel", "arcade_black", -0.1, 0.42, 0.92, 0.5, 0.12, 0.04),
         cyl("joystick", "arcade_black", -0.2, 0.42, 0.99, 0.01, 0.12),
         sph("knob", "button_red", -0.2, 0.42, 1.06, 0.025),
         cyl("button", "button_yellow", 0.05, 0.42, 0.95, 0.025, 0.02)]
    v += [box(f"glass_{n}", "glass", x, y, 1.35, sx, sy, 0.9)
          for n, x, y, sx, sy in (("f", 0, 0.445, 0.9, 0.01), ("b", 0, -0.445, 0.9, 0.01),
                                  ("l", -0.445, 0, 0.01, 0.9), ("r", 0.445, 0, 0.01, 0.9))]
    v += [box(f"post{i}", "claw_pink", sx * 0.43, sy * 0.43, 1.35, 0.04, 0.04, 0.9)
          for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    v += [sph(f"plush{i}_{k}", plush[(i + 2 * k) % 5], -0.3 + 0.15 * i, -0.3 + 0.16 * k, 0.98 + 0.04 * ((i + k) % 2), 0.08)
          for i in range(4) for k in range(4)]
    v += [box("top", "claw_pink", 0, 0, 1.86, 0.9, 0.9, 0.12),
          box("marquee", "marquee_lit", 0, 0.455, 2.02, 0.8, 0.02, 0.22),
          box("gantry", "chrome", 0, 0, 1.77, 0.8, 0.04, 0.04),
          cyl("cable", "chrome", 0.1, 0, 1.6, 0.005, 0.3),
          cyl("claw_head", "chrome", 0.1, 0, 1.43, 0.04, 0.06)]
    v += [turned(box(f"prong{i}", "chrome", 0.1 + 0.04 * math.cos(a), 0.04 * math.sin(a), 1.36, 0.012, 0.012, 0.1),
                 f"{0.3 * math.sin(a):.3f} {-0.3 * math.cos(a):.3f} 0") for i, a in enumerate((0, 2.094, 4.189))]
    return v


def air_hockey_table(w=1.15, length=2.1):
    """An air hockey table, its length along y: the white playing surface with the centre line
    and the circles, the dark rails, a goal slot at each end, the cabinet and legs, two mallets
    (red and blue) and the puck on it."""
    v = [box("cabinet", "hockey_rail", 0, 0, 0.62, w, length, 0.3),
         box("surface", "hockey_white", 0, 0, 0.775, w - 0.1, length - 0.1, 0.01),
         box("centre_line", "hockey_red", 0, 0, 0.781, w - 0.1, 0.02, 0.001),
         box("rail_l", "hockey_rail", -w / 2 + 0.025, 0, 0.81, 0.05, length, 0.08),
         box("rail_r", "hockey_rail", w / 2 - 0.025, 0, 0.81, 0.05, length, 0.08)]
    for k, s in enumerate((-1, 1)):
        v += [box(f"end{k}_l", "hockey_rail", -0.33, s * (length / 2 - 0.025), 0.81, w / 2 - 0.1, 0.05, 0.08),
              box(f"end{k}_r", "hockey_rail", 0.33, s * (length / 2 - 0.025), 0.81, w / 2 - 0.1, 0.05, 0.08),
              box(f"goal{k}", "black", 0, s * (length / 2 - 0.02), 0.79, 0.3, 0.04, 0.03),
              cyl(f"circle{k}", "hockey_blue", 0, s * 0.5, 0.7805, 0.16, 0.001),
              box(f"score{k}", "display_red", 0, s * (length / 2 + 0.003), 0.65, 0.16, 0.004, 0.08)]
    v += legs("hockey_rail", w / 2 - 0.08, length / 2 - 0.1, 0.47, 0.08)
    return v + [cyl("mallet_red", "hockey_red", 0.1, -0.6, 0.81, 0.05, 0.05),
                cyl("mallet_blue", "hockey_blue", -0.15, 0.55, 0.81, 0.05, 0.05),
                cyl("puck", "hockey_red", 0.05, 0.1, 0.785, 0.04, 0.01)]


def prize_counter(length=2.6, gap=0.75):
    """The prize counter against the wall (behind it at -y): the glass display counter toward the
    customers (+y) with small prizes inside, the staff aisle behind it, the wooden prize shelves on
    the wall with plush toys, and a redemption ticket reader on the counter."""
    plush = ("plush_yellow", "plush_pink", "plush_blue", "plush_brown", "plush_green")
    yc = gap + 0.2 + 0.3  # the counter's centre from the shelf's back
    v = [box("shelf_back", "prize_wood", 0, 0.02, 1.05, length, 0.04, 2.1),
         box("shelf_end_l", "prize_wood", -length / 2 + 0.02, 0.2, 1.05, 0.04, 0.4, 2.1),
         box("shelf_end_r", "prize_wood", length / 2 - 0.02, 0.2, 1.05, 0.04, 0.4, 2.1)]
    for t, z in enumerate((0.4, 0.85, 1.3, 1.75)):
        v.append(box(f"shelf{t}", "prize_wood", 0, 0.2, z, length - 0.08, 0.38, 0.03))
        v += [sph(f"toy{t}_{i}", plush[(t + i) % 5], -length / 2 + 0.2 + 0.23 * i, 0.2, z + 0.1, 0.085)
              for i in range(11)]
    v += [box("counter_base", "prize_wood", 0, yc, 0.2, length, 0.6, 0.4),
          box("counter_glass", "glass", 0, yc, 0.7, length, 0.6, 0.6),
          box("counter_top", "glass", 0, yc, 1.01, length + 0.04, 0.64, 0.02)]
    v += [box(f"prize{i}", plush[i % 5], -length / 2 + 0.25 + 0.3 * i, yc, 0.5, 0.12, 0.12, 0.2) for i in range(8)]
    return v + [box("ticket_reader", "arcade_black", length / 2 - 0.3, yc + 0.1, 1.1, 0.25, 0.2, 0.16),
                box("reader_slot", "display_red", length / 2 - 0.3, yc + 0.201, 1.12, 0.16, 0.002, 0.03)]


# ---- the lobby: the front desk / shoe counter ----
def front_desk(length=3.6, d=0.7):
    """The front desk and shoe counter: a high counter with a navy front and a red stripe toward
    the customers (+y), the grey top, the staff's lower worktop behind it (-y)."""
    return [box("front", "counter_front", 0, d / 2 - 0.04, 0.52, length, 0.08, 1.04),
            box("stripe", "stripe_red", 0, d / 2 + 0.002, 0.8, length, 0.004, 0.1),
            box("top", "counter_top", 0, 0.05, 1.06, length + 0.06, d + 0.1, 0.04),
            box("worktop", "counter_top", 0, -0.12, 0.75, length - 0.1, 0.46, 0.04),
            box("cabinets", "counter_front", 0, -0.12, 0.37, length - 0.1, 0.46, 0.73),
            box("end_l", "counter_front", -length / 2 + 0.03, 0, 0.52, 0.06, d, 1.04),
            box("end_r", "counter_front", length / 2 - 0.03, 0, 0.52, 0.06, d, 1.04)]


def till():
    """A till on a counter: the cash drawer, the keypad and the touch screen facing the cashier
    (-y), the small customer display facing +y, a receipt printer."""
    return [box("drawer", "black", 0, 0, 0.05, 0.42, 0.4, 0.1),
            box("keypad", "grey_plastic", 0, -0.09, 0.12, 0.3, 0.16, 0.04),
            turned(box("screen", "screen_lit", 0, 0.06, 0.25, 0.32, 0.02, 0.22), "0.3 0 0"),
            box("stand", "black", 0, 0.08, 0.15, 0.06, 0.04, 0.1),
            box("customer_display", "screen", 0, 0.17, 0.2, 0.16, 0.02, 0.06),
            box("receipt_printer", "grey_plastic", 0.28, -0.02, 0.06, 0.14, 0.18, 0.12)]


def shoe_shelf(w=1.6, d=0.4, h=2.0, cols=6, rows=7, seed=0):
    """The rental shoe shelves: a wooden grid of cubbies (open toward +y), a pair of bowling shoes
    (two-tone, red, blue or tan) in each cubby by size."""
    colours = ("shoe_red", "shoe_blue", "shoe_tan")
    v = [box("back", "cubby_wood", 0, -d / 2 + 0.01, h / 2, w, 0.02, h)]
    v += [box(f"post{i}", "cubby_wood", -w / 2 + 0.01 + i * (w - 0.02) / cols, 0, h / 2, 0.02, d, h) for i in range(cols + 1)]
    v += [box(f"board{i}", "cubby_wood", 0, 0, 0.01 + i * (h - 0.02) / rows, w, d, 0.02) for i in range(rows + 1)]
    cw, ch = (w - 0.02) / cols, (h - 0.02) / rows
    for r in range(rows):
        for c in range(cols):
            x, z = -w / 2 + 0.01 + cw * (c + 0.5), 0.02 + ch * r + 0.06
            col = colours[(r * cols + c + seed) % 3]
            v += [box(f"shoe{r}_{c}_{k}", col, x + s * 0.055, 0.03, z, 0.095, 0.28, 0.09) for k, s in enumerate((-1, 1))]
            v.append(box(f"sole{r}_{c}", "shoe_sole", x, 0.03, z - 0.048, 0.2, 0.28, 0.006))
    return v


def shoe_sanitizer():
    """A free-standing shoe sanitizer cabinet (front +y): the white body, the glass door with two
    pairs of rental shoes on the rack inside, the violet UV lamp strip, the display and the start
    button on the top panel."""
    v = [box("body", "sanitizer_body", 0, 0, 0.6, 0.55, 0.5, 1.2),
         box("door", "glass", 0, 0.252, 0.65, 0.47, 0.005, 0.8),
         box("uv_lamp", "uv_violet", 0, 0.2, 1.0, 0.45, 0.03, 0.03),
         box("rack", "chrome", 0, 0.05, 0.55, 0.46, 0.36, 0.01),
         box("panel", "dark_metal", 0, 0.251, 1.12, 0.4, 0.004, 0.1),
         box("display", "display_red", -0.1, 0.254, 1.12, 0.12, 0.002, 0.05),
         cyl("button", "exit_green", 0.12, 0.254, 1.12, 0.025, 0.004)]
    v += [box(f"shoe{i}", ("shoe_red", "shoe_blue")[i // 2], -0.15 + 0.1 * i, 0.05, 0.61, 0.09, 0.27, 0.1) for i in range(4)]
    return v


# ---- the bar and snack counter ----
def bar_counter(length=5.0, depth=0.7):
    """The bar: a wooden front toward the customers (+y) with a brass foot rail, the black top,
    the bartender's steel underbar on the far side (-y)."""
    v = [box("front", "bar_wood", 0, depth / 2 - 0.04, 0.53, length, 0.08, 1.06),
         box("top", "bar_top", 0, 0.05, 1.085, length + 0.1, depth + 0.1, 0.05),
         box("underbar", "steel", 0, -0.14, 0.45, length - 0.12, 0.4, 0.9),
         box("side_l", "bar_wood", -length / 2 + 0.03, 0, 0.53, 0.06, depth, 1.06),
         box("side_r", "bar_wood", length / 2 - 0.03, 0, 0.53, 0.06, depth, 1.06),
         along_x(cyl("foot_rail", "brass", 0, depth / 2 + 0.15, 0.22, 0.025, length - 0.2))]
    v += [box(f"rail_bracket{i}", "brass", -length / 2 + 0.3 + i * (length - 0.6) / 4, depth / 2 + 0.07, 0.22,
              0.03, 0.16, 0.03) for i in range(5)]
    return v


def bar_stool():
    """A round black bar stool on a chrome pedestal with a foot ring."""
    return [cyl("base", "dark_metal", 0, 0, 0.015, 0.22, 0.03),
            cyl("pedestal", "chrome", 0, 0, 0.39, 0.03, 0.72),
            cyl("foot_ring", "chrome", 0, 0, 0.3, 0.17, 0.02),
            cyl("seat_pan", "dark_metal", 0, 0, 0.75, 0.18, 0.03),
            cyl("cushion", "leather", 0, 0, 0.795, 0.19, 0.06)]


def beer_tap():
    """A beer tap tower on the bar counter: a drip tray, the column, the T head with three faucets
    and their coloured handles toward the bartender (+y)."""
    v = [box("drip_tray", "steel", 0, 0.12, 0.01, 0.48, 0.14, 0.02),
         cyl("column", "steel", 0, 0, 0.2, 0.035, 0.4),
         along_x(cyl("head", "steel", 0, 0, 0.42, 0.04, 0.46))]
    for i, (x, c) in enumerate(((-0.15, "tap_red"), (0, "tap_gold"), (0.15, "tap_black"))):
        v += [box(f"faucet{i}", "steel", x, 0.06, 0.38, 0.025, 0.09, 0.025),
              box(f"spout{i}", "steel", x, 0.09, 0.33, 0.02, 0.02, 0.07),
              cyl(f"handle{i}", c, x, 0.05, 0.52, 0.017, 0.16)]
    return v


def fridge():
    """A glass-door drinks fridge (front +y): the black body with the lit red header, the glass
    door with its handle, four shelves of bottles and cans behind it."""
    drinks = ("bottle_green", "can_red", "bottle_amber", "can_silver", "can_blue")
    v = [box("body", "fridge_black", 0, 0, 0.975, 0.7, 0.7, 1.95),
         box("header", "fridge_logo", 0, 0.352, 1.82, 0.66, 0.004, 0.2),
         box("door", "glass", 0, 0.352, 0.95, 0.62, 0.006, 1.5),
         cyl("handle", "chrome", 0.27, 0.38, 0.95, 0.015, 0.6),
         box("grille", "dark_metal", 0, 0.352, 0.1, 0.6, 0.004, 0.12)]
    for t, z in enumerate((0.28, 0.64, 1.0, 1.36)):
        v.append(box(f"shelf{t}", "chrome", 0, 0.05, z, 0.6, 0.55, 0.01))
        v += [cyl(f"drink{t}_{i}", drinks[(t + i) % 5], -0.24 + 0.08 * i, 0.2, z + 0.11, 0.03, 0.22 if (t + i) % 2 == 0 else 0.12)
              for i in range(7)]
    return v


def fryer():
    """A floor-standing twin-basket deep fryer for the snacks (front +y): the steel cabinet, the
    oil vat with two baskets whose handles stick out toward the cook, the flue at the back."""
    v = [box("cabinet", "steel", 0, 0, 0.52, 0.5, 0.8, 0.8),
         box("door", "dark_steel", 0, 0.405, 0.5, 0.44, 0.01, 0.6),
         box("vat_rim", "dark_steel", 0, 0.03, 0.93, 0.5, 0.62, 0.02),
         box("oil", "oil", 0, 0.03, 0.942, 0.4, 0.5, 0.005),
         box("flue", "steel", 0, -0.36, 1.1, 0.48, 0.08, 0.36)]
    v += legs("steel", 0.21, 0.35, 0.12, 0.04)
    for i, x in enumerate((-0.1, 0.1)):
        v += [box(f"basket{i}", "filter", x, 0.0, 1.01, 0.17, 0.3, 0.12),
              box(f"basket_handle{i}", "black", x, 0.3, 1.05, 0.025, 0.3, 0.025)]
    return v


def menu_board():
    """A back-lit snack menu board on the wall (behind it at -y), centred on the model's height:
    three columns of dishes with their photos and prices."""
    foods = ("food_brown", "food_yellow", "food_red")
    v = [box("frame", "menu_back", 0, 0, 0, 1.8, 0.05, 0.9),
         box("panel", "menu_light", 0, 0.026, 0, 1.7, 0.004, 0.8),
         box("title", "stripe_red", 0, 0.029, 0.32, 1.0, 0.002, 0.1)]
    for c in range(3):
        x = -0.56 + 0.56 * c
        v.append(box(f"photo{c}", foods[c], x, 0.029, 0.12, 0.4, 0.002, 0.2))
        v += [box(f"line{c}_{r}", "menu_back", x - 0.04, 0.029, -0.08 - 0.09 * r, 0.34, 0.002, 0.03) for r in range(3)]
        v += [box(f"price{c}_{r}", "stripe_red", x + 0.19, 0.029, -0.08 - 0.09 * r, 0.07, 0.002, 0.03) for r in range(3)]
    return v


# ---- the party room ----
def party_table(w=1.8, d=0.8):
    """A rectangular party table with an orange plastic cloth, paper plates and cups laid at six
    places."""
    v = [box("top", "table_top", 0, 0, 0.73, w, d, 0.03),
         box("cloth", "cloth_party", 0, 0, 0.7475, w + 0.04, d + 0.04, 0.005),
         box("skirt_n", "cloth_party", 0, d / 2 + 0.02, 0.64, w + 0.04, 0.005, 0.2),
         box("skirt_s", "cloth_party", 0, -d / 2 - 0.02, 0.64, w + 0.04, 0.005, 0.2)]
    v += legs("chair_leg", w / 2 - 0.08, d / 2 - 0.08, 0.715, 0.04)
    for i, (px, py) in enumerate([(x, y) for x in (-0.6, 0, 0.6) for y in (-0.25, 0.25)]):
        v += [cyl(f"plate{i}", "paper_plate", px, py, 0.755, 0.11, 0.008),
              cyl(f"cup{i}", "cup_blue", px + 0.18, py * 0.6, 0.8, 0.035, 0.1)]
    return v


def chair():
    """A stacking chair: a blue plastic seat and back (at -y) on a grey steel frame."""
    v = [box("seat", "chair_plastic", 0, 0, 0.46, 0.44, 0.42, 0.03),
         turned(box("back", "chair_plastic", 0, -0.21, 0.72, 0.42, 0.02, 0.34), "-0.1 0 0"),
         box("back_post_l", "chair_leg", -0.2, -0.2, 0.65, 0.02, 0.02, 0.4),
         box("back_post_r", "chair_leg", 0.2, -0.2, 0.65, 0.02, 0.02, 0.4)]
    return v + legs("chair_leg", 0.19, 0.18, 0.445, 0.025)


def tv():
    """A flat-screen TV on a wall bracket (the wall behind at -y), centred on the model's height."""
    return [box("bracket", "dark_metal", 0, -0.05, 0, 0.3, 0.05, 0.25),
            box("panel", "black", 0, 0, 0, 1.45, 0.05, 0.84),
            box("screen", "screen_lit", 0, 0.026, 0.01, 1.39, 0.004, 0.78)]


# ---- the toilets ----
# ---- the mechanic's room ----
def workbench(length=2.0, d=0.75):
    """A mechanic's workbench against the wall (behind it at -y): a thick wooden top on a steel
    frame with a lower shelf, a vice at its right end, a pegboard on the wall with spanners and
    hammers, a pinsetter part (a gear and a belt) and a toolbox on the top."""
    v = [box("top", "workbench_wood", 0, 0, 0.88, length, d, 0.06),
         box("shelf", "steel", 0, 0, 0.2, length - 0.1, d - 0.1, 0.03),
         box("pegboard", "pegboard", 0, -d / 2 + 0.01, 1.5, length, 0.02, 1.0),
         box("vice_body", "tool_black", length / 2 - 0.2, 0.25, 0.97, 0.16, 0.2, 0.12),
         box("vice_jaw", "dark_steel", length / 2 - 0.2, 0.38, 0.99, 0.18, 0.06, 0.1),
         along_y(cyl("vice_screw", "chrome", length / 2 - 0.2, 0.45, 0.95, 0.012, 0.18)),
         along_y(cyl("gear", "parts_grey", -0.4, 0.05, 1.03, 0.14, 0.04)),
         box("belt", "belt_black", 0.05, 0.05, 0.915, 0.5, 0.06, 0.01),
         box("toolbox", "tool_red", -0.75, -0.1, 0.99, 0.4, 0.2, 0.16)]
    v += legs("steel", length / 2 - 0.04, d / 2 - 0.04, 0.85, 0.05)
    v += [box(f"spanner{i}", "chrome", -0.8 + 0.12 * i, -d / 2 + 0.03, 1.55 - 0.02 * i, 0.03, 0.01, 0.22 + 0.03 * i)
          for i in range(6)]
    v += [box(f"hammer{i}", "tool_black", 0.2 + 0.2 * i, -d / 2 + 0.03, 1.6, 0.03, 0.01, 0.3) for i in range(3)]
    v += [box(f"hammer_head{i}", "dark_steel", 0.2 + 0.2 * i, -d / 2 + 0.035, 1.76, 0.1, 0.02, 0.04) for i in range(3)]
    return v


def tool_cabinet():
    """A red rolling tool cabinet on castors (front +y): the lower cabinet of wide drawers, the top
    chest with its lid, chrome drawer handles."""
    v = [box("cabinet", "tool_red", 0, 0, 0.55, 0.74, 0.48, 0.9),
         box("chest", "tool_red", 0, 0, 1.2, 0.72, 0.44, 0.4),
         box("lid", "tool_black", 0, 0, 1.415, 0.74, 0.46, 0.03)]
    v += [along_x(cyl(f"handle{i}", "chrome", 0, 0.25, 0.24 + 0.14 * i, 0.01, 0.6)) for i in range(6)]
    v += [along_x(cyl(f"chest_handle{i}", "chrome", 0, 0.23, 1.07 + 0.1 * i, 0.008, 0.5)) for i in range(3)]
    return v + castors(0.32, 0.2, 0.05)


def shelving_unit(w=1.6, d=0.5, fill=0):
    """A steel shelving unit of spare parts against the wall (behind it at -y): five shelves on
    four angle posts, blue parts bins, grey pinsetter parts (gears, rollers), belts."""
    v = [box(f"post{i}", "rack_steel", sx * (w / 2 - 0.02), sy * (d / 2 - 0.02), 1.0, 0.04, 0.04, 2.0)
         for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    for i, z in enumerate((0.1, 0.5, 0.9, 1.3, 1.7)):
        v.append(box(f"shelf{i}", "rack_steel", 0, 0, z, w, d, 0.02))
        kind = (i + fill) % 3
        if kind == 0:
            v += [box(f"bin{i}_{k}", "parts_box", -w / 2 + 0.17 + 0.32 * k, 0.02, z + 0.1, 0.28, 0.4, 0.18) for k in range(5)]
        elif kind == 1:
            v += [along_y(cyl(f"gear{i}_{k}", "parts_grey", -w / 2 + 0.2 + 0.3 * k, 0, z + 0.14, 0.12, 0.05)) for k in range(5)]
        else:
            v += [along_x(cyl(f"roller{i}_{k}", "parts_grey", 0, -0.12 + 0.12 * k, z + 0.05, 0.04, w - 0.2)) for k in range(3)]
            v.append(box(f"belt{i}", "belt_black", 0.3, 0.15, z + 0.02, 0.5, 0.12, 0.02))
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


def safe():
    """A grey steel floor safe (front +y): the body, the door with its combination dial and the
    handle, the hinges."""
    return [box("body", "safe_grey", 0, 0, 0.45, 0.6, 0.6, 0.9),
            box("door", "dark_steel", 0, 0.302, 0.45, 0.5, 0.01, 0.78),
            along_y(cyl("dial", "chrome", 0, 0.32, 0.58, 0.05, 0.025)),
            box("handle", "chrome", 0.12, 0.33, 0.42, 0.12, 0.03, 0.03),
            box("hinge_t", "tool_black", -0.26, 0.31, 0.7, 0.03, 0.02, 0.1),
            box("hinge_b", "tool_black", -0.26, 0.31, 0.2, 0.03, 0.02, 0.1)]


# ---- everywhere ----
def trash_can():
    """A round grey trash can with a swing lid."""
    return [cyl("body", "grey_bin", 0, 0, 0.37, 0.22, 0.74),
            cyl("lid", "grey_bin", 0, 0, 0.76, 0.23, 0.04),
            box("flap", "black", 0, 0.12, 0.72, 0.2, 0.01, 0.1)]


# ---- the building ----
def walls():
    """The outer walls with the entrance (south) and the fire exit (east); the lanes hall's south
    wall east of the approaches with the mechanic's door; the wall behind the pinsetters; the east
    block: the party room, the office, the corridor, the toilets with their cubicle partitions."""
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

    with_openings(0, "x", 0, W, (ENTRANCE,), "plaster", 2.3)
    wall(0, D, W, D); wall(0, 0, 0, D)
    with_openings(W, "y", 0, D, (FIRE_EXIT,), "plaster")
    with_openings(YL, "x", XA, W, (MECH_DOOR,), "plaster")
    wall(XM, YC1, XM, D, c="pit_wall")  # behind the pinsetters; south of YL, the women's east wall
    # the east block
    wall(XB, 0, XB, YC0, c="partition")
    wall(XB, YC1, XB, YL, c="white_tile")
    with_openings(YC0, "x", XB, W, (PARTY_DOOR, OFFICE_DOOR), "partition")
    wall(XPO, 0, XPO, YC0, c="partition")
    with_openings(YC1, "x", XB, XM, (MENS_DOOR, WOMENS_DOOR), "white_tile")
    wall(XWM, YC1, XWM, YL, c="white_tile")
    for x in (22.5, 24.9, 26.0):  # cubicle partitions
        wall(x, 7.0, x, YL - T / 2, 0, 2.0, c="partition")
    return v


def floor():
    """The floor: purple patterned carpet in the concourse, the settee areas, the arcade, the party
    room and the office; light vinyl tiles in the lobby, the bar and the corridor; white tiles in
    the toilets; bare concrete in the mechanic's room (thin layers laid over the slab)."""
    v = base.floor_slab("floor_carpet", "carpet", W, D)
    v += [box("lobby", "lobby_tile", (6.5 + XB) / 2, YL / 2, 0.0005, XB - 6.5, YL, 0.001),
          box("corridor", "lobby_tile", (XB + W) / 2, (YC0 + YC1) / 2, 0.0005, W - XB, YC1 - YC0, 0.001),
          box("corridor_end", "lobby_tile", (XM + W) / 2, (YC1 + YL) / 2, 0.0005, W - XM, YL - YC1, 0.001),
          box("toilets", "tile", (XB + XM) / 2, (YC1 + YL) / 2, 0.0005, XM - XB, YL - YC1, 0.001),
          box("mechanics", "concrete", (XM + W) / 2, (YL + D) / 2, 0.0005, W - XM, D - YL, 0.001)]
    return v


def pairs():
    """(pair centre y, (lane centre y, lane centre y)) of the three pairs of lanes."""
    out = []
    for p in range(3):
        y0 = 9.0 + 3.7 * p
        out.append((y0 + 1.55, (y0 + 0.75, y0 + 2.35)))
    return out


def lanes_hall(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    n = 0
    for p, (cy, lanes) in enumerate(pairs(), 1):
        for ly in lanes:
            n += 1
            add(f"bowling_lane_{n}", (XA, ly, 0, 0), bowling_lane())
            add(f"bowling_pins_{n}", (XA + LANE_LEN - 0.95, ly, 0.08, 0), bowling_pins())
            add(f"pinsetter_{n}", (XP, ly, 0, 0), pinsetter(art=(n - 1) % 3))
            add(f"scoring_monitor_{n}", (XA + 1.0, ly, 2.5, WEST), scoring_monitor())
        add(f"ball_return_{p}", (XA - 0.66, cy, 0, 0), ball_return())
        add(f"bench_{p}", (5.6, cy, 0, E), bench())
        add(f"side_table_{p}", (6.85, cy, 0, N), side_table())


def concourse(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    for i, y in enumerate((10.0, 12.05, 14.1, 16.15), 1):
        add(f"ball_rack_{i}", (T / 2 + 0.225, y, 0, E), ball_rack())
    for i in range(5):
        add(f"locker_{i + 1}", (T / 2 + 0.25, 17.8 + 0.45 * i, 0, E), locker())
    add("fire_extinguisher_1", (T / 2 + 0.1, 17.3, 0, E), fire_extinguisher())
    add("trash_can_1", (5.9, 12.4, 0, N), trash_can())
    add("trash_can_2", (5.9, 16.1, 0, N), trash_can())


def mechanics_room(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    m0, m1 = MECH_DOOR
    east = W - T / 2
    add("door_3", (m1 - 0.04, YL + 0.47, 0, WEST), base.door())  # hinged at the doorway's east side
    add("workbench", (east - 0.375, 10.8, 0, WEST), workbench())
    add("tool_cabinet", (east - 0.25, 12.6, 0, WEST), tool_cabinet())
    for i, y in enumerate((14.2, 15.9, 17.6), 1):
        add(f"shelving_unit_{i}", (east - 0.25, y, 0, WEST), shelving_unit(fill=i))
    add("shelving_unit_4", (XM + T / 2 + 0.25, 18.9, 0, E), shelving_unit(fill=0))
    add("fire_extinguisher_2", (XM + T / 2 + 0.1, 10.0, 0, E), fire_extinguisher())
    add("trash_can_3", (XM + 0.4, 9.0, 0, N), trash_can())


def arcade(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    themes = ("arcade_red", "arcade_blue", "arcade_green")
    for k in range(6):
        add(f"arcade_machine_{k + 1}", (T / 2 + 0.43, 2.05 + 0.8 * k, 0, E), arcade_machine(themes[k % 3]))
    add("claw_machine_1", (0.6, 0.6, 0, N), claw_machine())
    add("claw_machine_2", (1.65, 0.6, 0, N), claw_machine())
    add("air_hockey_table", (3.8, 4.4, 0, N), air_hockey_table())
    add("prize_counter", (4.7, T / 2, 0, N), prize_counter())
    add("trash_can_4", (6.1, 3.2, 0, N), trash_can())


def lobby(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    e0, e1 = ENTRANCE
    add("door_1", (e0 + 0.04, 0.47, 0, WEST), base.door())  # two leaves swung open into the lobby
    add("door_2", (e1 - 0.04, 0.47, 0, WEST), base.door())
    add("exit_sign_1", ((e0 + e1) / 2, T / 2 + 0.03, 2.45, N), exit_sign())
    add("window_1", (7.3, T / 2 + 0.02, 1.55, N), base.window())
    add("window_2", (11.8, T / 2 + 0.02, 1.55, N), base.window())
    add("front_desk", (11.3, 4.6, 0, WEST), front_desk())  # the customers on its west side
    add("till_1", (11.38, 4.0, 1.08, WEST), till())  # its screen toward the staff (east)
    add("shoe_shelf_1", (12.75, 3.7, 0, WEST), shoe_shelf(seed=0))
    add("shoe_shelf_2", (12.75, 5.4, 0, WEST), shoe_shelf(seed=1))
    add("shoe_sanitizer", (12.65, 2.3, 0, WEST), shoe_sanitizer())
    add("trash_can_5", (8.0, 0.5, 0, N), trash_can())
    add("fire_extinguisher_3", (9.6, YL - T / 2 - 0.1, 0, S), fire_extinguisher())


def bar(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    back = YL - T / 2
    add("bar_counter", (16.7, 5.6, 0, S), bar_counter())  # the customers south of it
    for i in range(6):
        add(f"bar_stool_{i + 1}", (14.7 + 0.8 * i, 4.75, 0, N), bar_stool())
    add("beer_tap", (15.0, 5.6, 1.11, N), beer_tap())  # the faucets toward the bartender
    add("till_2", (18.6, 5.65, 1.11, S), till())
    add("fridge", (14.6, back - 0.36, 0, S), fridge())
    add("fryer", (17.4, back - 0.41, 0, S), fryer())
    add("menu_board", (16.0, back - 0.03, 2.2, S), menu_board())
    add("window_3", (15.3, T / 2 + 0.02, 1.55, N), base.window())
    add("window_4", (18.4, T / 2 + 0.02, 1.55, N), base.window())
    add("trash_can_6", (20.1, 0.5, 0, N), trash_can())
    add("fire_extinguisher_4", (XB - T / 2 - 0.1, 2.5, 0, WEST), fire_extinguisher())


def party_room(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    p0, p1 = PARTY_DOOR
    add("door_4", (p1 - 0.04, YC0 - 0.47, 0, WEST), base.door())  # hinged at the doorway's east side
    c = 0
    for t, x in enumerate((22.3, 24.2), 1):
        add(f"party_table_{t}", (x, 1.9, 0, N), party_table())
        for dx in (-0.45, 0.45):
            c += 1; add(f"chair_{c}", (x + dx, 1.25, 0, N), chair())
            c += 1; add(f"chair_{c}", (x + dx, 2.55, 0, S), chair())
    add("chair_9", (21.1, 1.9, 0, E), chair())
    add("chair_10", (25.5, 1.9, 0, WEST), chair())
    add("tv", (XPO - T / 2 - 0.08, 1.9, 1.6, WEST), tv())
    add("window_5", (22.3, T / 2 + 0.02, 1.55, N), base.window())
    add("window_6", (24.2, T / 2 + 0.02, 1.55, N), base.window())
    add("trash_can_7", (20.85, 3.6, 0, N), trash_can())


def office(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    o0, o1 = OFFICE_DOOR
    add("door_5", (o1 - 0.04, YC0 - 0.47, 0, WEST), base.door())
    add("desk", (W - T / 2 - 0.36, 1.8, 0, E), base.desk())  # the user west of it
    add("office_chair", (28.7, 1.8, 0, E), base.office_chair())
    add("computer", (29.65, 1.8, 0.75, WEST), computer())
    add("safe", (XPO + T / 2 + 0.35, 0.45, 0, N), safe())
    add("window_7", (27.8, T / 2 + 0.02, 1.55, N), base.window())
    add("trash_can_8", (26.45, 3.5, 0, N), trash_can())


def toilets(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    m0, m1 = MENS_DOOR
    w0, w1 = WOMENS_DOOR
    back = YL - T / 2
    # the men's
    add("door_6", (m1 - 0.04, YC1 + 0.47, 0, WEST), base.door())  # hinged at its east side
    add("sink_1", (XB + T / 2 + 0.01, 6.4, 0, E), sink())
    add("mirror_1", (XB + T / 2 + 0.02, 6.4, 1.65, E), mirror(0.5, 0.7))
    add("hand_dryer_1", (XB + T / 2 + 0.01, 7.3, 0, E), hand_dryer())
    add("urinal_1", (21.3, back - 0.02, 0, S), urinal())
    add("urinal_2", (22.0, back - 0.02, 0, S), urinal())
    add("toilet_1", (23.15, back - 0.31, 0, S), toilet())
    add("trash_can_9", (21.9, 5.9, 0, N), trash_can())
    # the women's
    add("door_7", (w0 + 0.04, YC1 + 0.47, 0, WEST), base.door())  # hinged at its west side
    add("sink_2", (XWM + T / 2 + 0.01, 6.9, 0, E), sink())
    add("mirror_2", (XWM + T / 2 + 0.02, 6.9, 1.65, E), mirror(0.5, 0.7))
    add("sink_3", (XWM + T / 2 + 0.01, 7.7, 0, E), sink())
    add("mirror_3", (XWM + T / 2 + 0.02, 7.7, 1.65, E), mirror(0.5, 0.7))
    add("toilet_2", (25.45, back - 0.31, 0, S), toilet())
    add("toilet_3", (26.55, back - 0.31, 0, S), toilet())
    add("hand_dryer_2", (XM - T / 2 - 0.01, 6.4, 0, WEST), hand_dryer())
    add("trash_can_10", (26.6, 5.9, 0, N), trash_can())


def corridor(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    f0, f1 = FIRE_EXIT
    add("door_8", (W - 0.06, (f0 + f1) / 2, 0, WEST), base.door())  # the fire exit, shut
    add("exit_sign_2", (W - T / 2 - 0.03, (f0 + f1) / 2, 2.45, WEST), exit_sign())
    add("exit_sign_3", ((XB + 21.5) / 2 + 0.2, YC1 - T / 2 - 0.03, 2.45, S), exit_sign())  # points the way east
    add("fire_extinguisher_5", (XM + T / 2 + 0.1, 7.9, 0, E), fire_extinguisher())


def main():
    out = [base.model("walls", (0, 0, 0, 0), walls()),
           base.model("floor", (0, 0, 0, 0), floor()),
           base.model("ceiling", (0, 0, 0, 0), base.ceiling_slab(W, D, H))]
    lanes_hall(out)
    concourse(out)
    mechanics_room(out)
    arcade(out)
    lobby(out)
    bar(out)
    party_room(out)
    office(out)
    toilets(out)
    corridor(out)
    warm, cool, hall = "0.85 0.78 0.66", "0.8 0.8 0.78", "0.78 0.78 0.85"
    lights = [base.point_light(name, x, y, H - 0.25, rgb)
              for name, x, y, rgb in (("light_concourse_s", 3.0, 11.0, warm), ("light_concourse_n", 3.0, 17.0, warm),
                                      ("light_settee_s", 7.0, 10.5, hall), ("light_settee_m", 7.0, 14.2, hall),
                                      ("light_settee_n", 7.0, 18.0, hall), ("light_lanes_w", 13.0, 14.2, hall),
                                      ("light_lanes_m", 18.0, 14.2, hall), ("light_pins", 23.0, 14.2, cool),
                                      ("light_mech_s", 28.5, 11.5, cool), ("light_mech_n", 28.5, 17.0, cool),
                                      ("light_arcade", 3.3, 4.0, warm), ("light_lobby", 9.5, 4.0, warm),
                                      ("light_bar", 16.7, 4.5, warm), ("light_party", 23.2, 2.0, warm),
                                      ("light_office", 28.0, 2.0, cool), ("light_corridor", 25.0, 4.75, cool),
                                      ("light_mens", 22.1, 7.0, cool), ("light_womens", 25.4, 7.0, cool),
                                      ("light_exit", 28.5, 7.0, cool))]
    print(base.world_sdf("semsplat_bowling", """The semsplat bowling centre: a small bowling centre of 30 m x 20 m on one floor (the lanes
     hall with six lanes in three pairs, their pins, pinsetters and overhead scoring monitors, the
     settee areas with ball returns, curved benches and side tables; the concourse with ball racks
     and league lockers; the mechanic's room behind the pinsetters; the arcade corner with arcade
     and claw machines, an air hockey table and the prize counter; the lobby with the front desk,
     the rental shoe shelves and the shoe sanitizer; the bar and snack counter with bar stools, a
     beer tap, a drinks fridge, a fryer and the menu board; the party room, the manager's office
     and the toilets off a corridor) for measuring on a world nobody tuned on. Generated by
     bowling_models/make_bowling.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
