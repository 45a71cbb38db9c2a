#!/usr/bin/env python3
"""Writes data/worlds/cinema.world: a small two-screen multiplex cinema of 26 m x 18 m on one floor,
for measuring the semantic stack on a world nobody tuned on. x runs east, y north; the street front
with the entrance is the south wall.

The foyer (x < 16, y < 8): the entrance (a double door, its exit sign over it) in the middle of the
south wall, glazed windows either side of it; the box office on the west wall (a long ticket counter
with a glass screen, two tills and two ticket printers on it, two staff office chairs behind it, a
queue line of stanchions with belts in front of it); two self-service ticket kiosks against the
south wall by the entrance; the concession stand across the north wall (the serving counter with two
tills, the hot dog roller and the nacho warmer with its cheese pump on it; behind the staff aisle
the back counter with the popcorn machine and the soda fountain on it, a glass-door display fridge
of drinks at its east end); a seating area of four round cafe tables with two chairs each in the
south-east under the windows; film posters in lit cases on the north and east walls; two bins and a
fire extinguisher by the entrance.
The two auditoriums (screen 1: x 0..8, screen 2: x 8..16, y 8..15), entered from the foyer through a
door in the corner beside the screen (the exit sign over it inside): the cinema screen on the front
(south) wall, a loudspeaker either side of it and one on each side wall, four wall lights, a side
aisle along the outer wall, five rows of red cinema seats facing the screen (three on the flat floor,
two on the raised tier at the back, reached by three steps in the aisle), the marked wheelchair space
at the aisle end of the front row, a fire extinguisher and a bin by the screen.
The projection booth (x < 16, y > 15) behind both auditoriums, entered from the staff room: a
digital projector on its pedestal at each projection port window, a server rack behind each, two film
platters, a workbench with a chair in the middle, a fire extinguisher and a bin.
The east block (x > 16): the toilets in the south-east (gents' with two toilets in cubicles, two
sinks with mirrors and a hand dryer; ladies' with three toilets in cubicles, two sinks with mirrors,
a hand dryer; a bin in each), their doors off the corridor that opens from the foyer at x = 16
(a fire extinguisher on its east wall); off the corridor to the north the store room (four wire
shelving units stocked with boxes of cups, popcorn bags, syrup and napkins, a mop bucket, a fire
extinguisher), the staff passage and the manager's office (a desk with a computer and an office
chair, a safe, a filing cabinet, a bin, a window); the staff passage leads to the staff room across
the north-east (staff lockers, a table with four chairs, a side table with the kettle and the
microwave, a fridge, a bin, a fire extinguisher, a window), whose west wall has the booth door.

Every model is inline (boxes, cylinders, spheres), so the world needs no model path. Model names
are what a world author would type; the class is the name less its _<number> ("cinema_seat_12" ->
"cinema seat", "hot_dog_roller" -> "hot dog roller"). The primitives and the SDF writing are the
office generator's.
Run: python3 data/worlds/cinema_models/make_cinema.py > data/worlds/cinema.world"""

import math
import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document, door, desk, chairs)
sys.path.insert(0, os.path.join(HERE, "..", "restaurant_models"))
import make_restaurant as rest  # noqa: E402  (washroom fittings, extinguisher, exit sign)

W, D, H = 26.0, 18.0, 3.5  # floor width (x), depth (y), wall height
T = 0.1                    # wall thickness
YA = 8.0                   # foyer (south) | auditoriums; corridor | store room, passage, office
YP = 15.0                  # auditoriums | projection booth
XA = 8.0                   # screen 1 | screen 2
XE = 16.0                  # the cinema | the east block (toilets, back rooms)
YT = 5.5                   # toilets | corridor
XT = 21.0                  # gents' | ladies'
XS, XO = 20.0, 21.5        # store room | staff passage | manager's office
YS = 12.5                  # store room, passage, office | staff room
LINTEL = 2.1               # the top of the inner doorways
TIER_Y, TIER_H = 12.8, 0.6 # the raised back tier of each auditorium

ENTRANCE = (6.6, 8.6)        # x, south wall (two leaves)
AUD1_DOOR = (0.15, 1.25)     # x, wall y = YA
AUD2_DOOR = (14.75, 15.85)   # x, wall y = YA
STORE_DOOR = (16.1, 17.2)    # x, wall y = YA
PASSAGE = (XS, XO)           # x, wall y = YA (an open doorway)
OFFICE_DOOR = (21.65, 22.75) # x, wall y = YA
GENTS_DOOR = (19.85, 20.95)  # x, wall y = YT
LADIES_DOOR = (21.15, 22.25) # x, wall y = YT
STAFF_DOOR = (20.2, 21.3)    # x, wall y = YS
BOOTH_DOOR = (16.2, 17.3)    # y, wall x = XE

N, S, E, WEST = 0.0, 3.1416, -1.5708, 1.5708  # yaw that turns a model's front (+y) north/south/east/west

base.COL.update({
    "concrete": "0.62 0.62 0.6", "foyer_carpet": "0.32 0.12 0.16", "aud_carpet": "0.16 0.14 0.2",
    "step_carpet": "0.2 0.17 0.24", "floor_tile": "0.82 0.84 0.84", "office_carpet": "0.35 0.38 0.42",
    "vinyl_tile": "0.7 0.68 0.62", "plaster": "0.93 0.9 0.84", "plaster_wine": "0.45 0.12 0.16",
    "aud_fabric": "0.14 0.14 0.2", "booth_wall": "0.4 0.4 0.42", "white_tile": "0.92 0.93 0.93",
    "partition": "0.7 0.74 0.78", "counter_red": "0.6 0.08 0.1", "counter_top": "0.15 0.13 0.13",
    "brand_gold": "0.9 0.72 0.2", "brand_red": "0.85 0.1 0.12", "steel": "0.78 0.79 0.8",
    "chrome": "0.85 0.86 0.88", "aluminium": "0.72 0.73 0.75", "popcorn_red": "0.8 0.1 0.08",
    "popcorn": "0.98 0.9 0.6", "dispenser_black": "0.1 0.1 0.11", "sausage": "0.7 0.3 0.2",
    "chips": "0.93 0.75 0.3", "cheese": "0.98 0.7 0.1", "fridge_black": "0.08 0.08 0.09",
    "bottle_green": "0.15 0.45 0.2", "bottle_orange": "0.95 0.5 0.1", "can_red": "0.8 0.1 0.1",
    "can_blue": "0.15 0.3 0.7", "bottle_clear": "0.82 0.9 0.92", "table_top": "0.85 0.83 0.78",
    "chair_shell": "0.15 0.15 0.16", "staff_chair": "0.25 0.35 0.5", "red_fabric": "0.62 0.06 0.1",
    "seat_black": "0.07 0.07 0.08", "matte_white": "0.96 0.96 0.95", "masking_black": "0.03 0.03 0.03",
    "speaker_black": "0.09 0.09 0.1", "cone_grey": "0.3 0.3 0.32", "brass": "0.8 0.65 0.3",
    "lamp_glow": "1.0 0.85 0.55", "nosing": "0.75 0.62 0.2", "led_strip": "0.95 0.9 0.7",
    "wheelchair_blue": "0.1 0.3 0.7", "paint_white": "0.97 0.97 0.97", "projector_black": "0.12 0.12 0.13",
    "panel_lit": "0.25 0.5 0.65", "rack_black": "0.06 0.06 0.07", "status_green": "0.1 0.9 0.3",
    "status_amber": "0.95 0.65 0.1", "platter_grey": "0.5 0.5 0.52", "film_brown": "0.3 0.2 0.12",
    "beech": "0.85 0.72 0.5", "pegboard": "0.75 0.65 0.5", "tool_red": "0.75 0.12 0.1",
    "porcelain": "0.97 0.97 0.97", "mirror": "0.8 0.85 0.88", "locker_blue": "0.3 0.42 0.6",
    "kettle_white": "0.95 0.95 0.94", "oven_glass": "0.2 0.22 0.25", "display_green": "0.2 0.85 0.4",
    "fridge_white": "0.94 0.94 0.93", "carton": "0.76 0.6 0.4", "cup_box": "0.93 0.93 0.9",
    "cup_print": "0.8 0.1 0.12", "bag_box": "0.95 0.85 0.55", "bag_stripe": "0.85 0.12 0.1",
    "syrup_box": "0.55 0.42 0.3", "napkin": "0.97 0.97 0.96", "mop_yellow": "0.93 0.78 0.1",
    "mop_head": "0.86 0.85 0.8", "screen_lit": "0.25 0.45 0.6", "screen_dark": "0.05 0.06 0.08",
    "safe_grey": "0.32 0.34 0.36", "bin_grey": "0.3 0.31 0.33", "bin_black": "0.05 0.05 0.05",
    "extinguisher_red": "0.8 0.08 0.06", "exit_green": "0.05 0.6 0.25", "paper": "0.96 0.96 0.94",
    "ticket": "0.98 0.95 0.85", "kiosk_white": "0.92 0.92 0.93", "belt_red": "0.7 0.05 0.08",
    "rubber": "0.1 0.1 0.1", "window_frame": "0.3 0.3 0.32", "credits": "0.85 0.85 0.8",
    "poster_night": "0.08 0.1 0.25", "poster_sky": "0.45 0.65 0.9", "poster_fire": "0.85 0.35 0.1",
    "poster_green": "0.2 0.45 0.25", "poster_pink": "0.9 0.5 0.65", "poster_yellow": "0.95 0.85 0.2",
    "poster_grey": "0.4 0.42 0.45", "poster_white": "0.95 0.95 0.92", "poster_black": "0.05 0.05 0.06",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
toilet, fire_extinguisher, exit_sign = rest.toilet, rest.fire_extinguisher, rest.exit_sign
turned, along_x, along_y = base.turned, base.along_x, base.along_y


# ---- the box office (local frames: x right, y forward = the side a person uses, z up) ----
def ticket_counter(length=3.6, depth=0.7, windows=(-0.8, 0.8)):
    """The box office counter: a red panelled front to the customers (+y) with a gold band, the top
    at 0.95 m, a glass screen along the front edge with a speak-through grille and a ticket slot
    under it at each window, the staff side (-y) open with a shelf under the top, a sign on top."""
    v = [box("front", "counter_red", 0, depth / 2 - 0.03, 0.46, length, 0.06, 0.92),
         box("band", "brand_gold", 0, depth / 2 + 0.002, 0.75, length - 0.2, 0.004, 0.1),
         box("kick", "black", 0, depth / 2 + 0.002, 0.05, length, 0.004, 0.1),
         box("top", "counter_top", 0, 0, 0.93, length + 0.06, depth + 0.06, 0.04),
         box("side_l", "counter_red", -length / 2 + 0.03, 0, 0.46, 0.06, depth, 0.92),
         box("side_r", "counter_red", length / 2 - 0.03, 0, 0.46, 0.06, depth, 0.92),
         box("shelf", "counter_top", 0, -0.05, 0.45, length - 0.12, depth - 0.2, 0.03),
         box("screen_glass", "glass", 0, depth / 2 - 0.04, 1.27, length, 0.012, 0.56),
         box("screen_rail", "aluminium", 0, depth / 2 - 0.04, 1.56, length + 0.02, 0.03, 0.03),
         box("sign", "brand_gold", 0, depth / 2 - 0.04, 1.66, 1.4, 0.03, 0.16)]
    for i, x in enumerate(windows):
        v += [along_y(cyl(f"grille{i}", "dark_metal", x, depth / 2 - 0.04, 1.3, 0.06, 0.02)),
              box(f"slot{i}", "black", x, depth / 2 - 0.04, 0.97, 0.3, 0.016, 0.04)]
    return v


def cash_register():
    """A till on a counter: the cash drawer, the keypad and the touch screen toward the cashier
    (-y), the small customer display toward +y, the receipt printer beside it."""
    return [box("drawer", "black", 0, 0, 0.05, 0.42, 0.4, 0.1),
            box("keypad", "grey_plastic", 0, -0.09, 0.12, 0.3, 0.16, 0.04),
            turned(box("screen", "screen_lit", 0, 0.06, 0.25, 0.32, 0.02, 0.22), "0.3 0 0"),
            box("stand", "black", 0, 0.08, 0.15, 0.06, 0.04, 0.1),
            box("customer_display", "screen_dark", 0, 0.17, 0.2, 0.16, 0.02, 0.06),
            box("receipt_printer", "grey_plastic", 0.28, -0.02, 0.06, 0.14, 0.18, 0.12)]


def ticket_printer():
    """A thermal ticket printer on a counter: the grey box, the ticket slot toward the user (+y)
    with a printed ticket coming out of it, a green status light."""
    return [box("body", "grey_plastic", 0, 0, 0.09, 0.22, 0.3, 0.18),
            box("lid", "dark_metal", 0, -0.04, 0.185, 0.2, 0.2, 0.01),
            box("slot", "black", 0, 0.151, 0.13, 0.12, 0.002, 0.012),
            turned(box("ticket", "ticket", 0, 0.19, 0.12, 0.07, 0.08, 0.003), "-0.5 0 0"),
            box("light", "status_green", 0.08, 0.151, 0.05, 0.015, 0.002, 0.015)]


def stanchion(belt=1.0):
    """A queue barrier post: a weighted round base, the chrome post with its belt cassette and cap,
    and (when belt > 0) the red belt pulled out to the next post along +y."""
    v = [cyl("base", "dark_metal", 0, 0, 0.02, 0.16, 0.04),
         cyl("post", "chrome", 0, 0, 0.5, 0.03, 0.92),
         cyl("cassette", "black", 0, 0, 0.86, 0.04, 0.12),
         cyl("cap", "chrome", 0, 0, 0.975, 0.035, 0.03)]
    if belt:
        v.append(box("belt", "belt_red", 0, belt / 2, 0.9, 0.006, belt - 0.1, 0.05))
    return v


def ticket_kiosk():
    """A self-service ticket machine: a floor plate, the white body with the cinema's logo, the
    touch screen tilted up toward the user (+y), the card reader and the ticket slot under it."""
    return [box("plate", "dark_metal", 0, 0, 0.01, 0.6, 0.5, 0.02),
            box("body", "kiosk_white", 0, -0.05, 0.56, 0.5, 0.36, 1.08),
            box("logo", "brand_red", 0, 0.132, 0.62, 0.36, 0.004, 0.26),
            turned(box("head", "kiosk_white", 0, 0.05, 1.38, 0.56, 0.12, 0.5), "0.3 0 0"),
            turned(box("screen", "screen_lit", 0, 0.109, 1.398, 0.46, 0.01, 0.38), "0.3 0 0"),
            box("card_reader", "black", 0.17, 0.16, 1.02, 0.1, 0.06, 0.05),
            box("ticket_slot", "black", -0.1, 0.133, 0.96, 0.16, 0.004, 0.015),
            box("receipt_cup", "dark_metal", -0.1, 0.16, 0.88, 0.18, 0.05, 0.04)]


# ---- the concession stand ----
def concession_counter(length=5.2, depth=0.8):
    """The concession stand's serving counter: the front to the customers (+y) in red with white
    popcorn stripes and a black kick plate, the top at 1.0 m, the staff side (-y) with a shelf of
    cup stacks under the top."""
    v = [box("front", "counter_red", 0, depth / 2 - 0.03, 0.49, length, 0.06, 0.98),
         box("kick", "black", 0, depth / 2 + 0.002, 0.05, length, 0.004, 0.1),
         box("top", "counter_top", 0, 0, 0.98, length + 0.06, depth + 0.06, 0.04),
         box("side_l", "counter_red", -length / 2 + 0.03, 0, 0.49, 0.06, depth, 0.98),
         box("side_r", "counter_red", length / 2 - 0.03, 0, 0.49, 0.06, depth, 0.98),
         box("shelf", "counter_top", 0, -0.1, 0.5, length - 0.12, depth - 0.3, 0.03)]
    n = int(length / 0.3)
    v += [box(f"stripe{i}", "paint_white", -length / 2 + 0.15 + 0.3 * i, depth / 2 + 0.002, 0.55, 0.14, 0.004, 0.7)
          for i in range(n) if i % 2]
    v += [cyl(f"cups{i}", "paper", -length / 2 + 0.4 + 0.5 * i, -0.1, 0.66, 0.045, 0.3)
          for i in range(int((length - 0.4) / 0.5))]
    return v


def back_counter(length=4.4, depth=0.65):
    """The concession stand's back counter against the wall (behind it at -y): steel-fronted
    cupboards with handles toward the staff (+y), the top at 0.9 m, a backsplash, cup lids and
    straws at the end."""
    v = [box("body", "steel", 0, 0, 0.44, length, depth, 0.88),
         box("top", "counter_top", 0, 0.01, 0.89, length + 0.04, depth + 0.02, 0.02),
         box("backsplash", "steel", 0, -depth / 2 + 0.015, 1.1, length, 0.03, 0.4),
         box("kick", "black", 0, depth / 2 + 0.002, 0.05, length, 0.004, 0.1)]
    n = int(length / 0.55)
    for i in range(n):
        x = -length / 2 + 0.275 + 0.55 * i
        v += [box(f"door{i}", "aluminium", x, depth / 2 + 0.003, 0.5, 0.5, 0.006, 0.7),
              box(f"handle{i}", "dark_metal", x + 0.18, depth / 2 + 0.015, 0.72, 0.02, 0.02, 0.14)]
    v += [cyl("lids", "paper", length / 2 - 0.25, 0.1, 1.0, 0.06, 0.2),
          cyl("straws", "brand_red", length / 2 - 0.12, 0.1, 1.0, 0.04, 0.2)]
    return v


def popcorn_machine(w=0.8, d=0.5):
    """A popcorn machine standing on a counter, toward the user (+y): the red base cabinet with its
    controls, the glass cabinet heaped with popcorn, the steel kettle hanging from the top, the red
    roof with a gold header, a scoop."""
    v = [box("base", "popcorn_red", 0, 0, 0.14, w, d, 0.28),
         box("controls", "black", 0.25, d / 2 + 0.002, 0.15, 0.2, 0.004, 0.12),
         box("popcorn", "popcorn", 0, 0, 0.36, w - 0.04, d - 0.04, 0.16),
         box("glass_front", "glass", 0, d / 2 - 0.008, 0.6, w - 0.04, 0.01, 0.64),
         box("glass_back", "glass", 0, -d / 2 + 0.008, 0.6, w - 0.04, 0.01, 0.64),
         box("glass_l", "glass", -w / 2 + 0.008, 0, 0.6, 0.01, d - 0.04, 0.64),
         box("glass_r", "glass", w / 2 - 0.008, 0, 0.6, 0.01, d - 0.04, 0.64),
         cyl("kettle", "steel", 0, 0, 0.72, 0.16, 0.16),
         cyl("kettle_rod", "steel", 0, 0, 0.85, 0.015, 0.12),
         box("roof", "popcorn_red", 0, 0, 0.96, w + 0.04, d + 0.04, 0.08),
         box("header", "brand_gold", 0, d / 2 + 0.025, 1.08, w, 0.02, 0.16),
         box("scoop", "steel", -0.22, 0.05, 0.47, 0.12, 0.1, 0.05)]
    v += [box(f"post{i}", "popcorn_red", sx * (w / 2 - 0.01), sy * (d / 2 - 0.01), 0.6, 0.03, 0.03, 0.64)
          for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    return v


def soda_fountain(w=0.75, d=0.6, h=0.8):
    """A drinks dispenser on a counter, toward the user (+y): the black tower with the lit brand
    panel over five valves with their push levers and flavour labels, the ice chute at the left,
    the drip tray with its grate, a cup dispenser tube at the right side."""
    labels = ("brand_red", "bottle_orange", "can_blue", "bottle_green", "popcorn")
    v = [box("body", "dispenser_black", 0, 0, h / 2, w, d, h),
         box("merch", "brand_red", 0, d / 2 + 0.002, 0.64, w - 0.06, 0.004, 0.24),
         box("tray", "steel", 0, d / 2 + 0.08, 0.025, w, 0.16, 0.05),
         box("grate", "dark_metal", 0, d / 2 + 0.08, 0.055, w - 0.04, 0.14, 0.01),
         box("ice_chute", "steel", -0.3, d / 2 + 0.04, 0.36, 0.1, 0.08, 0.1),
         cyl("cup_tube", "aluminium", w / 2 + 0.06, 0, 0.3, 0.05, 0.6)]
    for i in range(5):
        x = -0.17 + 0.11 * i
        v += [box(f"valve{i}", "steel", x, d / 2 + 0.04, 0.33, 0.07, 0.08, 0.1),
              box(f"lever{i}", "black", x, d / 2 + 0.09, 0.24, 0.03, 0.02, 0.1),
              box(f"label{i}", labels[i], x, d / 2 + 0.002, 0.44, 0.09, 0.004, 0.08)]
    return v


def hot_dog_roller(w=0.62, d=0.45):
    """A hot dog roller grill on a counter: the steel housing, ten chrome rollers running front to
    back, six sausages turning between them, the tilted glass sneeze guard toward the customers
    (+y) on two posts."""
    v = [box("housing", "steel", 0, 0, 0.06, w, d, 0.12),
         box("panel", "black", 0, d / 2 + 0.002, 0.06, 0.3, 0.004, 0.06),
         box("side_l", "steel", -w / 2 + 0.01, 0, 0.15, 0.02, d, 0.06),
         box("side_r", "steel", w / 2 - 0.01, 0, 0.15, 0.02, d, 0.06)]
    for i in range(10):
        x = -w / 2 + 0.05 + i * (w - 0.1) / 9
        v.append(along_y(cyl(f"roller{i}", "chrome", x, 0, 0.135, 0.013, d - 0.06)))
    v += [along_y(cyl(f"sausage{k}", "sausage", -w / 2 + 0.05 + (2 * k + 0.5) * (w - 0.1) / 11, 0, 0.165, 0.014, 0.17))
          for k in range(6)]
    v += [box(f"guard_post{i}", "chrome", s * (w / 2 - 0.02), d / 2 - 0.02, 0.24, 0.015, 0.015, 0.24)
          for i, s in enumerate((-1, 1))]
    return v + [turned(box("guard", "glass", 0, d / 2 - 0.06, 0.33, w, 0.008, 0.16), "-0.5 0 0")]


def nacho_warmer(w=0.45, d=0.45):
    """A nacho warmer on a counter, toward the user (+y): the heated cabinet with glass sides full of
    tortilla chips, the red roof with a gold header, and beside it (at -x) the cheese sauce
    dispenser with its pump and nozzle."""
    v = [box("base", "popcorn_red", 0, 0, 0.05, w, d, 0.1),
         box("chips", "chips", 0, 0, 0.19, w - 0.04, d - 0.04, 0.18),
         box("glass_front", "glass", 0, d / 2 - 0.006, 0.26, w - 0.02, 0.008, 0.32),
         box("glass_back", "glass", 0, -d / 2 + 0.006, 0.26, w - 0.02, 0.008, 0.32),
         box("glass_l", "glass", -w / 2 + 0.006, 0, 0.26, 0.008, d - 0.02, 0.32),
         box("glass_r", "glass", w / 2 - 0.006, 0, 0.26, 0.008, d - 0.02, 0.32),
         box("roof", "popcorn_red", 0, 0, 0.45, w, d, 0.06),
         box("header", "brand_gold", 0, d / 2 + 0.005, 0.45, w - 0.05, 0.01, 0.05)]
    cx = -w / 2 - 0.13
    return v + [box("cheese_body", "steel", cx, 0, 0.15, 0.2, 0.28, 0.3),
                box("cheese_label", "cheese", cx, 0.141, 0.16, 0.14, 0.002, 0.1),
                cyl("pump", "black", cx, 0.02, 0.35, 0.02, 0.1),
                box("pump_head", "black", cx, 0.05, 0.41, 0.04, 0.1, 0.03),
                box("nozzle", "black", cx, 0.1, 0.375, 0.015, 0.015, 0.05)]


def display_fridge(w=0.7, d=0.7, h=1.95):
    """A glass-door display fridge of cold drinks, toward the user (+y): the black cabinet, the lit
    header with the brand, the full-height glass door with its long handle, four shelves of bottles
    and cans behind the glass."""
    v = [box("plinth", "fridge_black", 0, 0, 0.05, w, d, 0.1),
         box("back", "fridge_black", 0, -d / 2 + 0.03, h / 2, w, 0.06, h),
         box("side_l", "fridge_black", -w / 2 + 0.03, 0, h / 2, 0.06, d, h),
         box("side_r", "fridge_black", w / 2 - 0.03, 0, h / 2, 0.06, d, h),
         box("header", "fridge_black", 0, 0, h - 0.1, w, d, 0.2),
         box("logo", "brand_red", 0, d / 2 + 0.002, h - 0.1, w - 0.1, 0.004, 0.14),
         box("door_glass", "glass", 0, d / 2 - 0.02, 0.97, w - 0.1, 0.01, 1.65),
         box("door_frame_l", "fridge_black", -w / 2 + 0.05, d / 2 - 0.02, 0.97, 0.04, 0.02, 1.65),
         box("door_frame_r", "fridge_black", w / 2 - 0.05, d / 2 - 0.02, 0.97, 0.04, 0.02, 1.65),
         cyl("handle", "aluminium", w / 2 - 0.09, d / 2 + 0.02, 1.0, 0.014, 0.9)]
    drinks = ("can_red", "bottle_orange", "can_blue", "bottle_green", "bottle_clear")
    for i in range(4):
        z = 0.2 + 0.4 * i
        v.append(box(f"shelf{i}", "aluminium", 0, -0.02, z, w - 0.12, d - 0.12, 0.015))
        for k in range(4):
            c = drinks[(i + k) % 5]
            x = -w / 2 + 0.14 + 0.14 * k
            if c.startswith("can"):
                v.append(cyl(f"can{i}_{k}", c, x, 0.1, z + 0.07, 0.033, 0.12))
            else:
                v += [cyl(f"bottle{i}_{k}", c, x, 0.1, z + 0.11, 0.035, 0.2),
                      cyl(f"neck{i}_{k}", c, x, 0.1, z + 0.25, 0.014, 0.08)]
    return v


# ---- the seating area and the staff room ----
def cafe_table(r=0.35):
    """A round cafe table: the laminate top on a steel pedestal with a cross foot."""
    return [cyl("top", "table_top", 0, 0, 0.735, r, 0.03),
            cyl("edge", "dark_metal", 0, 0, 0.715, r - 0.02, 0.01),
            cyl("pedestal", "dark_metal", 0, 0, 0.37, 0.03, 0.7),
            box("foot_x", "dark_metal", 0, 0, 0.02, 0.56, 0.06, 0.04),
            box("foot_y", "dark_metal", 0, 0, 0.02, 0.06, 0.56, 0.04)]


def staff_table(w=1.4, d=0.8, h=0.74):
    """A laminate table on four steel legs, a mug and a newspaper on it."""
    return [box("top", "table_top", 0, 0, h - 0.015, w, d, 0.03),
            cyl("mug", "brand_red", 0.35, 0.1, h + 0.05, 0.04, 0.1),
            box("newspaper", "paper", -0.3, -0.1, h + 0.005, 0.4, 0.3, 0.01)] + \
        legs("dark_metal", w / 2 - 0.05, d / 2 - 0.05, h - 0.03, 0.04)


def side_table(w=1.2, d=0.6, h=0.9):
    """A narrow side table against a wall with an undershelf (tea, coffee and a box of mugs on it)."""
    return [box("top", "table_top", 0, 0, h - 0.015, w, d, 0.03),
            box("undershelf", "table_top", 0, 0, 0.25, w - 0.08, d - 0.08, 0.02),
            box("mug_box", "carton", 0.3, 0, 0.36, 0.4, 0.3, 0.2),
            cyl("tea", "brand_red", -0.3, 0, 0.32, 0.06, 0.12)] + \
        legs("dark_metal", w / 2 - 0.04, d / 2 - 0.04, h - 0.03, 0.04)


def chair(c="chair_shell"):
    """A stacking chair, the sitter facing +y: a moulded seat and back (at -y) on a steel frame."""
    v = [box("seat", c, 0, 0, 0.46, 0.44, 0.42, 0.03),
         box("back", c, 0, -0.2, 0.75, 0.42, 0.03, 0.34),
         box("post_l", "steel", -0.19, -0.2, 0.62, 0.02, 0.02, 0.3),
         box("post_r", "steel", 0.19, -0.2, 0.62, 0.02, 0.02, 0.3)]
    return v + legs("steel", 0.19, 0.18, 0.45, 0.025)


POSTERS = (("poster_night", "poster_fire", "poster_yellow"), ("poster_sky", "poster_white", "poster_black"),
           ("poster_black", "poster_pink", "poster_white"), ("poster_green", "poster_grey", "poster_yellow"),
           ("poster_fire", "poster_black", "poster_white"), ("poster_pink", "poster_night", "poster_black"))


def movie_poster(k=0, w=0.76, h=1.1):
    """A film poster in a lit aluminium poster case on a wall (behind it at -y), centred on the
    model's height: the poster art (the background, a figure, the title) and the credits block."""
    bg, fig, title = POSTERS[k % len(POSTERS)]
    return [box("case", "aluminium", 0, 0, 0, w + 0.08, 0.04, h + 0.08),
            box("art", bg, 0, 0.021, 0, w, 0.004, h),
            box("figure", fig, 0.06 * (1 if k % 2 else -1), 0.024, -0.05, 0.32, 0.002, 0.55),
            box("title", title, 0, 0.024, 0.38, 0.62, 0.002, 0.14),
            box("credits", "credits", 0, 0.024, -0.44, 0.62, 0.002, 0.1)]


# ---- the auditoriums ----
def cinema_seat():
    """A cinema seat, its front toward the screen (+y): the red upholstered seat (down) on a black
    pan, the tall reclined padded back (at -y), black standards with armrests on both sides and a
    cup holder in the right one."""
    v = [box("seat", "red_fabric", 0, 0.04, 0.45, 0.47, 0.46, 0.12),
         box("seat_pan", "seat_black", 0, 0.04, 0.38, 0.46, 0.44, 0.03),
         turned(box("back", "red_fabric", 0, -0.22, 0.8, 0.47, 0.1, 0.66), "0.15 0 0"),
         turned(box("back_shell", "seat_black", 0, -0.28, 0.78, 0.47, 0.02, 0.72), "0.15 0 0")]
    for i, s in enumerate((-1, 1)):
        v += [box(f"standard{i}", "seat_black", s * 0.27, -0.04, 0.33, 0.04, 0.5, 0.66),
              box(f"arm{i}", "seat_black", s * 0.27, 0.02, 0.68, 0.04, 0.46, 0.04)]
    return v + [cyl("cup_holder", "seat_black", 0.27, 0.2, 0.7, 0.028, 0.06)]


def cinema_screen(w=5.0, h=2.3):
    """The cinema screen on the front wall (behind it at -y), centred on the model's height: the
    black masking border around the white screen surface."""
    return [box("masking", "masking_black", 0, 0, 0, w + 0.3, 0.04, h + 0.3),
            box("surface", "matte_white", 0, 0.021, 0, w, 0.004, h)]


def speaker():
    """A wall-mounted loudspeaker (the wall behind at -y), centred on the model's height: the black
    cabinet on its bracket, a woofer and a horn in the grille toward the room (+y)."""
    return [box("bracket", "dark_metal", 0, -0.15, 0, 0.1, 0.02, 0.2),
            box("cabinet", "speaker_black", 0, 0, 0, 0.36, 0.28, 0.56),
            along_y(cyl("woofer", "cone_grey", 0, 0.142, -0.1, 0.12, 0.006)),
            along_y(cyl("dust_cap", "black", 0, 0.146, -0.1, 0.04, 0.004)),
            box("horn", "cone_grey", 0, 0.143, 0.17, 0.22, 0.006, 0.1)]


def wall_light():
    """A wall sconce (the wall behind at -y), centred on the model's height: the brass back plate,
    the round shade, the warm glow it throws up the wall."""
    return [box("plate", "brass", 0, 0.01, 0, 0.12, 0.02, 0.22),
            cyl("shade", "lamp_shade", 0, 0.09, 0, 0.07, 0.2),
            box("glow", "lamp_glow", 0, 0.002, 0.22, 0.18, 0.002, 0.2)]


def steps(width=1.2, n=3, rise=0.15, run=0.3, rail=-1):
    """Carpeted steps up the aisle to the raised tier, climbing toward +y: n treads with gold nosings
    and LED strips in the risers, a handrail on two posts at the wall side (rail = -1: -x)."""
    v = []
    for k in range(n):
        y0, top = k * run, (k + 1) * rise
        v += [box(f"step{k}", "step_carpet", 0, (y0 + n * run) / 2, top / 2, width, n * run - y0, top),
              box(f"nosing{k}", "nosing", 0, y0 + 0.025, top + 0.002, width - 0.02, 0.04, 0.004),
              box(f"led{k}", "led_strip", 0, y0 - 0.002, top - 0.04, width - 0.1, 0.004, 0.015)]
    x = rail * (width / 2 - 0.06)
    y_lo, y_hi = 0.15, n * run - 0.15
    z_lo, z_hi = rise + 0.9, n * rise + 0.9
    v += [cyl("rail_post0", "brass", x, y_lo, (rise + z_lo) / 2, 0.02, z_lo - rise),
          cyl("rail_post1", "brass", x, y_hi, (n * rise + z_hi) / 2, 0.02, z_hi - n * rise)]
    slope = math.atan2(z_hi - z_lo, y_hi - y_lo)
    length = math.hypot(z_hi - z_lo, y_hi - y_lo)
    v.append(turned(cyl("rail", "brass", x, (y_lo + y_hi) / 2, (z_lo + z_hi) / 2, 0.022, length + 0.1),
                    f"{-(math.pi / 2 - slope):.4f} 0 0"))
    return v


def wheelchair_space(w=1.2, d=1.4):
    """The marked wheelchair space at the end of the front row: a blue painted bay on the floor with
    a white border and the white wheelchair symbol (wheel, seat, back and head) in it."""
    z = 0.002
    v = [box("bay", "wheelchair_blue", 0, 0, z, w, d, 0.004)]
    v += [box("border_s", "paint_white", 0, -d / 2 + 0.025, z + 0.001, w, 0.05, 0.004),
          box("border_n", "paint_white", 0, d / 2 - 0.025, z + 0.001, w, 0.05, 0.004),
          box("border_w", "paint_white", -w / 2 + 0.025, 0, z + 0.001, 0.05, d, 0.004),
          box("border_e", "paint_white", w / 2 - 0.025, 0, z + 0.001, 0.05, d, 0.004)]
    return v + [cyl("wheel", "paint_white", 0.0, -0.12, z + 0.001, 0.24, 0.004),
                cyl("wheel_hole", "wheelchair_blue", 0.0, -0.12, z + 0.0015, 0.18, 0.004),
                box("seat", "paint_white", 0.05, 0.05, z + 0.002, 0.3, 0.06, 0.004),
                box("back", "paint_white", -0.1, 0.2, z + 0.002, 0.06, 0.36, 0.004),
                cyl("head", "paint_white", -0.1, 0.46, z + 0.002, 0.07, 0.004)]


# ---- the projection booth ----
def projector(ped_h=1.1):
    """A digital cinema projector on its pedestal, the lens toward the port window (+y): the steel
    pedestal, the black projector body with its lens barrel at the right, a lit control panel on
    the side, the exhaust duct up to the ceiling."""
    top = ped_h + 0.43
    return [box("pedestal", "dark_metal", 0, -0.05, ped_h / 2, 0.6, 0.7, ped_h),
            box("plate", "steel", 0, -0.05, ped_h + 0.01, 0.66, 0.9, 0.02),
            box("body", "projector_black", 0, -0.05, ped_h + 0.22, 0.62, 0.9, 0.42),
            along_y(cyl("lens", "black", 0.12, 0.45, ped_h + 0.2, 0.07, 0.12)),
            along_y(cyl("lens_glass", "glass", 0.12, 0.513, ped_h + 0.2, 0.055, 0.006)),
            box("panel", "panel_lit", 0.312, -0.25, ped_h + 0.26, 0.004, 0.22, 0.12),
            box("vent", "dark_metal", -0.312, -0.1, ped_h + 0.2, 0.004, 0.4, 0.2),
            cyl("duct", "steel", 0, -0.3, (top + H) / 2, 0.1, H - top)]


def server_rack(w=0.6, d=0.8, h=2.0):
    """A server rack (the cinema's media server, the screen's audio processor and the network gear):
    the black cabinet, the perforated front door toward the user (+y) with its handle, servers
    with status lights behind it, the cable tray on top."""
    v = [box("cabinet", "rack_black", 0, 0, h / 2, w, d, h),
         box("door", "dark_metal", 0, d / 2 + 0.005, h / 2, w - 0.04, 0.01, h - 0.1),
         box("handle", "aluminium", w / 2 - 0.06, d / 2 + 0.02, 1.1, 0.02, 0.02, 0.2),
         box("tray", "aluminium", 0, -0.1, h + 0.03, w - 0.1, 0.3, 0.06)]
    for i in range(6):
        z = 0.3 + 0.25 * i
        v += [box(f"server{i}", "aluminium", 0, d / 2 + 0.011, z, w - 0.12, 0.002, 0.12),
              box(f"led{i}", "status_green" if i % 3 else "status_amber", w / 2 - 0.12, d / 2 + 0.013, z, 0.02, 0.002, 0.02)]
    return v


def film_platter(r=0.6):
    """A film platter system: three big horizontal platters on a central column, film wound on the
    top and bottom ones, the brain (payout unit) at the centre of each, the cross feet on castors."""
    v = [box("foot_x", "platter_grey", 0, 0, 0.04, 2 * r - 0.1, 0.1, 0.06),
         box("foot_y", "platter_grey", 0, 0, 0.04, 0.1, 2 * r - 0.1, 0.06),
         cyl("column", "platter_grey", 0, 0, 0.85, 0.05, 1.6)]
    v += [sph(f"castor{i}", "rubber", sx * (r - 0.08), sy * (r - 0.08), 0.03, 0.03)
          for i, (sx, sy) in enumerate(((-1, 0), (1, 0), (0, -1), (0, 1)))]
    for k, z in enumerate((0.55, 1.0, 1.45)):
        v += [cyl(f"platter{k}", "aluminium", 0, 0, z, r, 0.02),
              cyl(f"brain{k}", "steel", 0, 0, z + 0.07, 0.12, 0.12)]
        if k != 1:
            v.append(cyl(f"film{k}", "film_brown", 0, 0, z + 0.035, r * 0.85, 0.05))
    return v


def workbench(w=1.6, d=0.6):
    """A steel workbench against the wall (behind it at -y): the beech top, an undershelf, the
    pegboard on the wall with tools, a film splicer and a spare reel on the top, a vice at the
    right end."""
    v = [box("top", "beech", 0, 0, 0.885, w, d, 0.05),
         box("undershelf", "steel", 0, 0, 0.2, w - 0.08, d - 0.08, 0.02),
         box("pegboard", "pegboard", 0, -d / 2 + 0.01, 1.45, w, 0.02, 0.9),
         box("splicer", "dark_metal", -0.35, 0.05, 0.95, 0.35, 0.12, 0.08),
         along_y(cyl("reel", "aluminium", 0.2, 0.0, 1.07, 0.17, 0.03)),
         box("vice", "tool_red", w / 2 - 0.12, 0.18, 0.96, 0.14, 0.2, 0.1)]
    v += [box(f"tool{i}", "tool_red" if i % 2 else "dark_metal", -0.6 + 0.3 * i, -d / 2 + 0.03, 1.5, 0.04, 0.02, 0.25)
          for i in range(5)]
    return v + legs("steel", w / 2 - 0.04, d / 2 - 0.04, 0.86, 0.05)


# ---- the toilets ----
def sink():
    """A wall-hung wash basin (the wall behind at -y) with its tap and a soap dispenser."""
    return [box("basin", "porcelain", 0, 0.22, 0.8, 0.5, 0.42, 0.15),
            box("bowl", "floor_tile", 0, 0.24, 0.86, 0.38, 0.3, 0.04),
            cyl("tap", "chrome", 0, 0.06, 0.95, 0.02, 0.16),
            box("spout", "chrome", 0, 0.12, 1.02, 0.03, 0.12, 0.02),
            cyl("trap", "chrome", 0, 0.1, 0.55, 0.03, 0.35),
            box("soap", "white", 0.34, 0.045, 1.12, 0.1, 0.08, 0.18)]


def mirror(w=0.6, h=0.8):
    """A washroom mirror on the wall (behind at -y), centred on the model's height."""
    return [box("frame", "aluminium", 0, 0, 0, w + 0.04, 0.02, h + 0.04),
            box("glass", "mirror", 0, 0.011, 0, w, 0.004, h)]


def hand_dryer():
    """A wall-mounted electric hand dryer (the wall behind at -y), its nozzle pointing down."""
    return [box("body", "porcelain", 0, 0.08, 1.2, 0.28, 0.16, 0.3),
            box("nozzle", "chrome", 0, 0.1, 1.03, 0.08, 0.08, 0.05),
            box("badge", "dark_metal", 0, 0.161, 1.26, 0.1, 0.002, 0.04)]


# ---- the staff room ----
def locker(w=0.9, h=1.85, d=0.45):
    """A steel staff locker of four doors (two columns of two) toward the user (+y) on a plinth,
    each door with vents, a number tag and a key lock."""
    v = [box("plinth", "dark_metal", 0, 0, 0.05, w, d, 0.1),
         box("body", "locker_blue", 0, 0, 0.1 + (h - 0.1) / 2, w, d, h - 0.1)]
    for c in range(2):
        for r in range(2):
            x, z = -w / 4 + c * w / 2, 0.1 + (h - 0.1) * (0.25 + 0.5 * r)
            v += [box(f"seam{c}{r}", "dark_metal", x, d / 2 + 0.002, z - (h - 0.1) / 4 + 0.01, w / 2 - 0.02, 0.004, 0.01),
                  box(f"vent{c}{r}", "dark_metal", x, d / 2 + 0.002, z + 0.25, 0.2, 0.004, 0.08),
                  box(f"tag{c}{r}", "paper", x, d / 2 + 0.003, z + 0.12, 0.06, 0.002, 0.03),
                  cyl(f"lock{c}{r}", "chrome", x + w / 4 - 0.06, d / 2 + 0.01, z, 0.012, 0.02)]
    return v + [box("divider", "dark_metal", 0, d / 2 + 0.002, 0.1 + (h - 0.1) / 2, 0.01, 0.004, h - 0.1)]


def kettle():
    """An electric kettle on its base: the white jug, the lid, the handle at -x, the spout at +x."""
    return [cyl("base", "black", 0, 0, 0.01, 0.09, 0.02),
            cyl("jug", "kettle_white", 0, 0, 0.13, 0.08, 0.22),
            cyl("lid", "grey_plastic", 0, 0, 0.245, 0.05, 0.01),
            box("handle", "kettle_white", -0.095, 0, 0.14, 0.03, 0.04, 0.18),
            turned(box("spout", "kettle_white", 0.09, 0, 0.2, 0.05, 0.03, 0.03), "0 -0.5 0")]


def microwave():
    """A microwave oven, its door toward the user (+y): the white body, the dark glass window in the
    door, the control panel with its display at the right, the handle."""
    return [box("body", "fridge_white", 0, 0, 0.15, 0.5, 0.38, 0.3),
            box("door", "black", -0.06, 0.191, 0.15, 0.36, 0.004, 0.26),
            box("window", "oven_glass", -0.06, 0.194, 0.15, 0.26, 0.002, 0.18),
            box("panel", "grey_plastic", 0.18, 0.191, 0.15, 0.12, 0.004, 0.26),
            box("display", "display_green", 0.18, 0.194, 0.24, 0.08, 0.002, 0.03),
            box("handle", "grey_plastic", 0.11, 0.205, 0.15, 0.02, 0.02, 0.2)]


def fridge(w=0.6, d=0.65, h=1.75):
    """A tall fridge freezer, its doors toward the user (+y): the white body, the fridge door above
    and the freezer door below with their handles, a note held by a magnet."""
    return [box("body", "fridge_white", 0, 0, h / 2, w, d, h),
            box("door_top", "fridge_white", 0, d / 2 + 0.015, 1.2, w - 0.01, 0.03, 1.08),
            box("door_bottom", "fridge_white", 0, d / 2 + 0.015, 0.33, w - 0.01, 0.03, 0.6),
            box("handle_top", "grey_plastic", w / 2 - 0.06, d / 2 + 0.045, 1.0, 0.025, 0.03, 0.35),
            box("handle_bottom", "grey_plastic", w / 2 - 0.06, d / 2 + 0.045, 0.5, 0.025, 0.03, 0.2),
            box("note", "paper", -0.1, d / 2 + 0.031, 1.35, 0.15, 0.002, 0.2),
            box("magnet", "brand_red", -0.1, d / 2 + 0.033, 1.44, 0.03, 0.004, 0.03)]


# ---- the store room ----
def storage_shelf(w=1.5, d=0.45, fill=0):
    """A chrome wire shelving unit against a wall (behind it at -y): four shelves on four posts,
    stocked with boxes of paper cups, boxes of popcorn bags, bag-in-box syrup and napkin packs."""
    v = [cyl(f"post{i}", "chrome", sx * (w / 2 - 0.02), sy * (d / 2 - 0.02), 0.93, 0.013, 1.86)
         for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    for i, z in enumerate((0.15, 0.65, 1.15, 1.65)):
        v.append(box(f"shelf{i}", "chrome", 0, 0, z, w, d, 0.02))
        kind = (i + fill) % 4
        n = int((w - 0.1) / 0.36)
        for k in range(n):
            x = -w / 2 + 0.22 + 0.36 * k
            if kind == 0:  # boxes of cups, a cup printed on each
                v += [box(f"cups{i}_{k}", "cup_box", x, 0, z + 0.16, 0.32, 0.38, 0.3),
                      box(f"cup_print{i}_{k}", "cup_print", x, 0.191, z + 0.16, 0.1, 0.002, 0.14)]
            elif kind == 1:  # boxes of popcorn bags, striped
                v += [box(f"bags{i}_{k}", "bag_box", x, 0, z + 0.13, 0.32, 0.38, 0.24),
                      box(f"bag_stripe{i}_{k}", "bag_stripe", x, 0.191, z + 0.13, 0.3, 0.002, 0.06)]
            elif kind == 2:  # bag-in-box syrup for the soda fountain
                v.append(box(f"syrup{i}_{k}", "syrup_box", x, 0, z + 0.14, 0.3, 0.3, 0.26))
            else:  # napkin packs
                v += [box(f"napkins{i}_{k}_{j}", "napkin", x, -0.1 + 0.2 * j, z + 0.07, 0.3, 0.18, 0.12)
                      for j in range(2)]
    return v


def mop_bucket():
    """A yellow mop bucket on castors with its wringer, the mop standing in it."""
    return [box("bucket", "mop_yellow", 0, 0, 0.21, 0.45, 0.35, 0.32),
            box("water", "dark_metal", -0.05, 0, 0.36, 0.3, 0.3, 0.01),
            box("wringer", "mop_yellow", 0.13, 0, 0.47, 0.17, 0.3, 0.22),
            cyl("mop_head", "mop_head", -0.08, 0, 0.3, 0.08, 0.14),
            turned(cyl("mop_handle", "light_wood", -0.14, 0, 0.95, 0.014, 1.3), "0 -0.12 0")] + \
        [sph(f"castor{i}", "rubber", sx * 0.19, sy * 0.14, 0.025, 0.025)
         for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]


# ---- the manager's office ----
def computer():
    """A desktop computer on a desk: the monitor facing the user (+y) on its stand, the keyboard and
    the mouse in front, the tower beside it."""
    return [box("screen", "black", 0, 0, 0.3, 0.56, 0.04, 0.34),
            box("display", "screen_lit", 0, 0.021, 0.3, 0.52, 0.002, 0.3),
            box("neck", "dark_metal", 0, -0.04, 0.1, 0.05, 0.04, 0.16),
            box("foot", "dark_metal", 0, -0.02, 0.01, 0.22, 0.16, 0.02),
            box("keyboard", "black", 0, 0.25, 0.012, 0.44, 0.14, 0.025),
            box("mouse", "black", 0.3, 0.25, 0.015, 0.06, 0.1, 0.03),
            box("tower", "black", -0.48, -0.02, 0.21, 0.18, 0.42, 0.42)]


def safe():
    """A steel floor safe, its door toward the user (+y): the heavy grey body, the door with the
    combination dial, the handle, the keypad and the hinges at -x."""
    return [box("body", "safe_grey", 0, 0, 0.4, 0.55, 0.55, 0.8),
            box("door", "dark_metal", 0, 0.285, 0.42, 0.45, 0.02, 0.64),
            along_y(cyl("dial", "chrome", -0.05, 0.305, 0.52, 0.05, 0.025)),
            box("handle", "chrome", 0.12, 0.305, 0.4, 0.03, 0.03, 0.14),
            box("keypad", "black", 0.1, 0.297, 0.62, 0.1, 0.004, 0.08),
            box("hinge0", "chrome", -0.23, 0.29, 0.65, 0.02, 0.03, 0.08),
            box("hinge1", "chrome", -0.23, 0.29, 0.2, 0.02, 0.03, 0.08)]


# ---- everywhere ----
def trash_can(front_open=True):
    """A bin: a round dark grey body with a rim and a black bag at the top; the foyer's and the
    auditoriums' have a domed lid with a push flap toward +y."""
    v = [cyl("body", "bin_grey", 0, 0, 0.38, 0.22, 0.76),
         cyl("rim", "bin_grey", 0, 0, 0.77, 0.235, 0.03)]
    if front_open:
        return v + [sph("dome", "bin_grey", 0, 0, 0.78, 0.22), box("flap", "bin_black", 0, 0.16, 0.86, 0.2, 0.1, 0.1)]
    return v + [cyl("bag", "bin_black", 0, 0, 0.79, 0.2, 0.02)]


def window(w=1.3, h=1.2):
    """A glazed window in a wall (the wall behind at -y), centred on the model's height: the dark
    frame and the pane."""
    return [box("frame", "window_frame", 0, 0, 0, w, 0.03, h),
            box("pane", "glass", 0, 0.016, 0, w - 0.1, 0.004, h - 0.1)]


# ---- the building ----
def walls():
    """The outer walls with the entrance (south); the wall between the foyer and the auditoriums
    (their doors) running on east as the corridor's north wall (the store room, passage and office
    doorways); the auditoriums' divider and their back wall to the booth; the east block's west
    wall (open to the corridor, the booth door); the toilets (their doors, the divider, the cubicle
    partitions); the store room's and the office's side walls; the staff room's south wall."""
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
    wall(0, D, W, D); wall(0, 0, 0, D); wall(W, 0, W, D)
    with_openings(YA, "x", 0, XE, (AUD1_DOOR, AUD2_DOOR), "plaster_wine")
    with_openings(YA, "x", XE, W, (STORE_DOOR, PASSAGE, OFFICE_DOOR), "plaster")
    wall(XA, YA, XA, YP, c="aud_fabric")
    wall(0, YP, XE, YP, c="aud_fabric")
    wall(XE, 0, XE, YT, c="plaster_wine")
    with_openings(XE, "y", YA, D, (BOOTH_DOOR,), "booth_wall")
    # the toilets: their doors in the corridor wall, the divider, the cubicle partitions
    with_openings(YT, "x", XE, W, (GENTS_DOOR, LADIES_DOOR), "white_tile")
    wall(XT, 0, XT, YT, c="white_tile")
    for x in (17.35, 18.55, 22.35, 23.6, 24.85):
        wall(x, T / 2, x, 1.55, 0, 2.0, c="partition")
    # the back rooms
    wall(XS, YA, XS, YS); wall(XO, YA, XO, YS)
    with_openings(YS, "x", XE, W, (STAFF_DOOR,), "plaster")
    return v


def floor():
    """The floor: a concrete slab; patterned red carpet in the foyer, dark carpet in the
    auditoriums with their raised back tiers, tiles in the toilets and the corridor, vinyl tiles
    in the staff room, carpet in the manager's office (thin layers over the slab)."""
    v = base.floor_slab("floor_cinema", "concrete", W, D)
    layer = lambda name, c, x0, y0, x1, y1: v.append(
        box(name, c, (x0 + x1) / 2, (y0 + y1) / 2, 0.0005, x1 - x0, y1 - y0, 0.001))
    layer("foyer", "foyer_carpet", 0, 0, XE, YA)
    layer("screen1", "aud_carpet", 0, YA, XA, YP)
    layer("screen2", "aud_carpet", XA, YA, XE, YP)
    layer("toilets", "floor_tile", XE, 0, W, YA)
    layer("staff_room", "vinyl_tile", XE, YS, W, D)
    layer("office", "office_carpet", XO, YA, W, YS)
    for k, (x0, x1) in enumerate(((T / 2, XA - T / 2), (XA + T / 2, XE - T / 2)), 1):
        v.append(box(f"tier{k}", "step_carpet", (x0 + x1) / 2, (TIER_Y + YP - T / 2) / 2, TIER_H / 2,
                     x1 - x0, YP - T / 2 - TIER_Y, TIER_H))
        v.append(box(f"tier{k}_nosing", "nosing", (x0 + x1) / 2, TIER_Y + 0.02, TIER_H + 0.002, x1 - x0, 0.04, 0.004))
    return v


class Adder:
    """Numbers the instances of each class over the whole world (door_1, door_2, ...)."""

    def __init__(self, out):
        self.out, self.n = out, {}

    def __call__(self, cls, pose, visuals, numbered=True):
        if numbered:
            self.n[cls] = self.n.get(cls, 0) + 1
            name = f"{cls}_{self.n[cls]}"
        else:
            name = cls
        self.out.append(base.model(name, pose, visuals))


def foyer(add):
    e0, e1 = ENTRANCE
    add("door", (e0 + 0.04, 0.47, 0, WEST), base.door())  # two leaves swung open into the foyer
    add("door", (e1 - 0.04, 0.47, 0, WEST), base.door())
    add("exit_sign", ((e0 + e1) / 2, T / 2 + 0.03, 2.45, N), exit_sign())
    add("fire_extinguisher", (9.2, T / 2 + 0.1, 0, N), fire_extinguisher())
    add("trash_can", (9.75, 0.35, 0, N), trash_can())
    for x in (2.3, 10.6, 12.6, 14.6):
        add("window", (x, T / 2 + 0.02, 1.55, N), window())
    # the box office on the west wall, the customers east of it; the queue line in front
    add("ticket_counter", (1.35, 2.8, 0, E), ticket_counter())
    for y in (2.0, 3.6):
        add("office_chair", (0.5, y, 0, E), base.office_chair())
        add("cash_register", (1.3, y, 0.95, E), cash_register())  # the screen toward the staff (west)
        add("ticket_printer", (1.3, y + 0.55, 0.95, WEST), ticket_printer())  # the slot toward the staff
    for i, y in enumerate((0.9, 1.9, 2.9, 3.9)):
        add("stanchion", (2.9, y, 0, N), stanchion(1.0 if i < 3 else 0))
    # the self-service kiosks by the entrance
    for x in (4.1, 5.2):
        add("ticket_kiosk", (x, 0.4, 0, N), ticket_kiosk())
    # the concession stand on the north wall: the serving counter, the staff aisle, the back counter
    add("concession_counter", (8.0, 6.0, 0, S), concession_counter(5.2, 0.8))
    add("concession_counter", (7.6, YA - T / 2 - 0.325, 0, S), back_counter(4.4, 0.65))
    add("cash_register", (6.4, 6.05, 1.0, S), cash_register())  # the screens toward the staff (north)
    add("cash_register", (9.9, 6.05, 1.0, S), cash_register())
    add("hot_dog_roller", (7.5, 5.95, 1.0, S), hot_dog_roller())
    add("nacho_warmer", (8.55, 5.95, 1.0, S), nacho_warmer())  # the cheese pump at its east side
    add("popcorn_machine", (6.3, 7.62, 0.9, S), popcorn_machine())
    add("soda_fountain", (8.55, 7.6, 0.9, S), soda_fountain())
    add("display_fridge", (10.35, YA - T / 2 - 0.36, 0, S), display_fridge())
    # the seating area under the windows
    for x, y in ((12.2, 2.0), (14.5, 2.0), (12.2, 4.1), (14.5, 4.1)):
        add("table", (x, y, 0, N), cafe_table())
        add("chair", (x - 0.62, y, 0, E), chair())
        add("chair", (x + 0.62, y, 0, WEST), chair())
    add("trash_can", (14.3, YA - T / 2 - 0.3, 0, S), trash_can())
    # posters: the north wall either side of the concession stand, the east wall by the seating
    for k, x in enumerate((2.7, 3.9, 12.0, 13.2)):
        add("movie_poster", (x, YA - T / 2 - 0.02, 1.55, S), movie_poster(k))
    for k, y in enumerate((1.3, 3.0), 4):
        add("movie_poster", (XE - T / 2 - 0.02, y, 1.55, WEST), movie_poster(k))


def auditorium(add, k):
    """Screen k: screen 1 in x 0..8 as laid out; screen 2 in x 8..16 its mirror image (x -> 16 - x),
    so both doors and aisles are on the outer side."""
    m = (lambda x: x) if k == 1 else (lambda x: XE - x)
    side = (lambda yaw: yaw) if k == 1 else (lambda yaw: {E: WEST, WEST: E}.get(yaw, yaw))
    d0, d1 = AUD1_DOOR
    wall_in = T / 2  # the outer side wall's inner face (x), before mirroring
    wall_mid = XA - T / 2
    front = YA + T / 2
    # the door, hinged at the outer wall and swung in along it; the exit sign over it
    add("door", (m(d0 + 0.04), YA + 0.47, 0, WEST), base.door())
    add("exit_sign", (m((d0 + d1) / 2), front + 0.03, 2.35, N), exit_sign())
    add("fire_extinguisher", (m(1.55), front + 0.1, 0, N), fire_extinguisher())
    add("trash_can", (m(7.55), front + 0.3, 0, N), trash_can())
    # the screen and the sound
    add("cinema_screen", (m(4.5), front + 0.02, 2.05, N), cinema_screen(5.0, 2.3))
    add("speaker", (m(0.7), front + 0.16, 2.8, N), speaker())
    add("speaker", (m(7.45), front + 0.16, 2.8, N), speaker())
    add("speaker", (m(wall_in + 0.16), 12.0, 2.75, side(E)), speaker())
    add("speaker", (m(wall_mid - 0.16), 12.0, 2.75, side(WEST)), speaker())
    for y in (10.0, 13.6):
        add("wall_light", (m(wall_in), y, 2.2, side(E)), wall_light())
        add("wall_light", (m(wall_mid), y, 2.2, side(WEST)), wall_light())
    # the seats: three rows on the floor, two on the tier, facing the screen (south)
    for ri, (y, z) in enumerate(((10.2, 0), (11.2, 0), (12.2, 0), (13.5, TIER_H), (14.45, TIER_H))):
        for ci in range(10):
            if ri == 0 and ci < 2:
                continue  # the wheelchair space
            add("cinema_seat", (m(1.85 + 0.6 * ci), y, z, S), cinema_seat())
    add("wheelchair_space", (m(2.15), 10.1, 0, N), wheelchair_space(1.2, 1.4))
    add("steps", (m(0.8), TIER_Y - 0.9, 0, N), steps(1.2, 3, 0.15, 0.3, -1 if k == 1 else 1))


def projection_booth(add):
    for x in (4.5, 11.5):  # behind each screen's centre
        add("window", (x, YP + T / 2 + 0.02, 1.3, N), window(0.5, 0.36))  # the projection port
        add("projector", (x, 15.65, 0, S), projector())
    add("server_rack", (6.3, D - T / 2 - 0.41, 0, S), server_rack())
    add("server_rack", (13.2, D - T / 2 - 0.41, 0, S), server_rack())
    add("film_platter", (1.6, 17.2, 0, N), film_platter())
    add("film_platter", (9.8, 17.2, 0, N), film_platter())
    add("workbench", (7.9, D - T / 2 - 0.31, 0, S), workbench())
    add("chair", (7.9, 16.95, 0, N), chair("staff_chair"))
    add("fire_extinguisher", (15.3, D - T / 2 - 0.1, 0, S), fire_extinguisher())
    add("trash_can", (14.5, D - T / 2 - 0.3, 0, N), trash_can(False))


def toilets(add):
    g0, g1 = GENTS_DOOR
    l0, l1 = LADIES_DOOR
    add("door", (g1 - 0.04, YT - 0.47, 0, WEST), base.door())  # hinged at the divider side
    add("door", (l0 + 0.04, YT - 0.47, 0, WEST), base.door())
    # the gents': two toilets in cubicles, two sinks with mirrors on the west wall, the hand dryer
    for x in (16.75, 17.95):
        add("toilet", (x, T / 2 + 0.31, 0, N), toilet())
    for y in (3.4, 4.4):
        add("sink", (XE + T / 2 + 0.01, y, 0, E), sink())
        add("mirror", (XE + T / 2 + 0.02, y, 1.55, E), mirror(0.5, 0.7))
    add("hand_dryer", (17.7, YT - T / 2 - 0.01, 0, S), hand_dryer())
    add("trash_can", (20.6, 0.4, 0, N), trash_can(False))
    # the ladies': three toilets in cubicles, two sinks with mirrors on the east wall, the hand dryer
    for x in (21.75, 23.0, 24.25):
        add("toilet", (x, T / 2 + 0.31, 0, N), toilet())
    for y in (3.4, 4.4):
        add("sink", (W - T / 2 - 0.01, y, 0, WEST), sink())
        add("mirror", (W - T / 2 - 0.02, y, 1.55, WEST), mirror(0.5, 0.7))
    add("hand_dryer", (24.3, YT - T / 2 - 0.01, 0, S), hand_dryer())
    add("trash_can", (25.6, 2.3, 0, N), trash_can(False))
    # the corridor
    add("fire_extinguisher", (W - T / 2 - 0.1, 6.75, 0, WEST), fire_extinguisher())


def back_rooms(add):
    # the store room
    add("door", (STORE_DOOR[0] + 0.04, YA + 0.47, 0, WEST), base.door())
    add("storage_shelf", (XE + T / 2 + 0.24, 9.8, 0, E), storage_shelf(1.5, 0.45, 0))
    add("storage_shelf", (XE + T / 2 + 0.24, 11.55, 0, E), storage_shelf(1.5, 0.45, 1))
    add("storage_shelf", (18.3, YS - T / 2 - 0.24, 0, S), storage_shelf(1.5, 0.45, 2))
    add("storage_shelf", (XS - T / 2 - 0.24, 10.0, 0, WEST), storage_shelf(1.5, 0.45, 3))
    add("mop_bucket", (19.55, 8.5, 0, N), mop_bucket())
    add("fire_extinguisher", (XS - T / 2 - 0.1, 11.6, 0, WEST), fire_extinguisher())
    # the manager's office
    add("door", (OFFICE_DOOR[0] + 0.04, YA + 0.47, 0, WEST), base.door())
    add("desk", (W - T / 2 - 0.36, 10.4, 0, E), base.desk())
    add("office_chair", (W - T / 2 - 1.05, 10.4, 0, E), base.office_chair())
    add("computer", (W - T / 2 - 0.35, 10.4, 0.75, WEST), computer())
    add("window", (W - T / 2 - 0.02, 10.4, 1.65, WEST), window())
    add("safe", (W - T / 2 - 0.3, YS - T / 2 - 0.31, 0, WEST), safe())
    add("filing_cabinet", (23.2, YS - T / 2 - 0.33, 0, S), base.filing_cabinet())
    add("trash_can", (22.1, 12.0, 0, N), trash_can(False))
    # the staff room
    add("door", (STAFF_DOOR[0] + 0.04, YS + 0.47, 0, WEST), base.door())
    add("door", (XE + 0.5, BOOTH_DOOR[1] - 0.04, 0, N), base.door())  # the booth door, swung into the staff room
    for x in (17.4, 18.35, 19.3, 20.25):
        add("locker", (x, D - T / 2 - 0.23, 0, S), locker())
    add("table", (22.8, 15.2, 0, N), staff_table())
    for x in (22.4, 23.2):
        add("chair", (x, 14.55, 0, N), chair("staff_chair"))
        add("chair", (x, 15.85, 0, S), chair("staff_chair"))
    add("table", (W - T / 2 - 0.31, 14.3, 0, WEST), side_table())
    add("microwave", (W - T / 2 - 0.33, 13.95, 0.9, WEST), microwave())
    add("kettle", (W - T / 2 - 0.3, 14.75, 0.9, WEST), kettle())
    add("fridge", (W - T / 2 - 0.36, 15.6, 0, WEST), fridge())
    add("trash_can", (W - T / 2 - 0.3, 16.45, 0, N), trash_can(False))
    add("window", (23.8, D - T / 2 - 0.02, 1.5, S), window())
    add("fire_extinguisher", (XE + T / 2 + 0.1, 14.0, 0, E), fire_extinguisher())


def main():
    out = [base.model("walls", (0, 0, 0, 0), walls()),
           base.model("floor", (0, 0, 0, 0), floor()),
           base.model("ceiling", (0, 0, 0, 0), base.ceiling_slab(W, D, H))]
    add = Adder(out)
    foyer(add)
    auditorium(add, 1)
    auditorium(add, 2)
    projection_booth(add)
    toilets(add)
    back_rooms(add)
    warm, cool, dim = "0.85 0.78 0.66", "0.8 0.8 0.78", "0.7 0.65 0.6"
    lights = [base.point_light(name, x, y, H - 0.25, rgb)
              for name, x, y, rgb in (("light_box_office", 2.5, 2.8, warm), ("light_entrance", 7.6, 2.2, warm),
                                      ("light_concession", 8.0, 6.8, warm), ("light_seating", 13.3, 3.0, warm),
                                      ("light_foyer_e", 14.5, 6.5, warm), ("light_screen1_front", 4.0, 9.8, dim),
                                      ("light_screen1_back", 4.0, 13.3, dim), ("light_screen2_front", 12.0, 9.8, dim),
                                      ("light_screen2_back", 12.0, 13.3, dim), ("light_booth_w", 4.0, 16.6, cool),
                                      ("light_booth_e", 12.0, 16.6, cool), ("light_gents", 18.5, 2.8, cool),
                                      ("light_ladies", 23.5, 2.8, cool), ("light_corridor", 21.0, 6.75, cool),
                                      ("light_store", 18.0, 10.25, cool), ("light_passage", 20.75, 10.25, cool),
                                      ("light_office", 23.75, 10.25, cool), ("light_staff_w", 18.5, 15.2, cool),
                                      ("light_staff_e", 23.5, 15.2, cool))]
    print(base.world_sdf("semsplat_cinema", """The semsplat cinema: a small two-screen multiplex of 26 m x 18 m on one floor (the foyer
     with the entrance, the box office and its queue line, self-service ticket kiosks, the
     concession stand with the popcorn machine, soda fountain, hot dog roller, nacho warmer and a
     display fridge, a seating area and film posters; two auditoriums with a screen, speakers,
     wall lights, rows of cinema seats on the floor and a raised tier, steps and a wheelchair space;
     the projection booth behind them with projectors, server racks, film platters and a
     workbench; the toilets, the store room, the manager's office and the staff room in the east)
     for measuring on a world nobody tuned on. Generated by cinema_models/make_cinema.py; all
     models are inline.""", lights, out))


if __name__ == "__main__":
    main()
