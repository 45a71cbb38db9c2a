#!/usr/bin/env python3
"""Writes data/worlds/station.world: a small railway station of 24 m x 14 m on one floor, for
measuring the semantic stack on a world nobody tuned on.

The station building (y < 10.5), the street front in the south wall, west to east:
the ticket office (x < 6: the ticket counter behind two ticket windows in its east wall, which give
onto the concourse, two office chairs and two computers for the clerks, the safe, a filing cabinet,
a window onto the street) and behind it the staff office (x < 6, y > 5.5: a desk with an office
chair and a computer, a filing cabinet, the notice board, a heater, a fire extinguisher, a window
onto the platform), the staff office entered from the concourse, the ticket office from the staff
office;
the concourse (6 < x < 16: the entrance, a double door, in the south wall with the exit sign and
the station clock above it, a cash machine, two ticket machines and a recycling bin along the south
wall, a third ticket machine and the information board (a map of the area) on the west wall, two
benches back to back in the middle, litter bins, the main departure board above the ticket
barriers, a second departure board on the east wall, a help point and a fire extinguisher; the
newsagent and coffee kiosk in the south-east corner: the kiosk counter with the till on it, the
coffee machine behind it, the drinks fridge and the magazine rack outside its north partition);
the ticket barriers stand in the wide opening in the north wall, six barrier cabinets with five
gates: four narrow ones with their paddles shut and the wide accessible gate, open, at the east end;
the east wing, off the concourse through a corridor (y 4.5..6): the gents (two toilets in cubicles,
two urinals, a sink with a mirror, a hand dryer) and the ladies (three toilets in cubicles, two
sinks with mirrors, a hand dryer, a baby changing table) south of the corridor; left luggage (seven
banks of luggage lockers, an open archway) and the waiting room (chairs in two rows, two vending
machines, two heaters, a departure board, a clock, a litter bin, windows and a door onto the
platform) north of it.
The platform (y 10.5..14) along the north side, its edge at y = 14 (the floor ends there; the
tracks are not modelled), under a canopy on four pillars: three benches, a shelter with a bench in
it at the west end, the hanging departure board and clock, a help point, an information board,
litter and recycling bins, two luggage trolleys, two cycle racks at the east end, planters, a fire
extinguisher and the way-out sign over the barriers.

Every model is inline (boxes, cylinders, spheres), so the world needs no model path. Model names
are what a world author would type; the class is the name less its _<number> ("ticket_barrier_3"
-> "ticket barrier", "luggage_locker_5" -> "luggage locker"). The primitives and the SDF writing
are the office generator's.
Run: python3 data/worlds/station_models/make_station.py > data/worlds/station.world"""

import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document, window, desk, chairs)
sys.path.insert(0, os.path.join(HERE, "..", "restaurant_models"))
import make_restaurant as rest  # noqa: E402  (washroom fittings, extinguisher, exit sign)

W, D, H = 24.0, 14.0, 4.0  # world width (x), depth (y), the building's wall height
T = 0.1                    # wall thickness
YB = 10.5                  # the building's north wall; the platform north of it
XT = 6.0                   # the ticket office / staff office | the concourse
YT = 5.5                   # the ticket office (south) | the staff office (north)
XE = 16.0                  # the concourse | the east wing
YC0, YC1 = 4.5, 6.0        # the east wing's corridor
XG = 20.0                  # the gents | the ladies
XL = 19.5                  # left luggage | the waiting room
CANOPY = (2.8, 21.0, 13.5, 3.5)  # the platform canopy: x0, x1, its north edge, its height
LINTEL = 2.1

ENTRANCE = (10.8, 13.2)       # x, south wall (two leaves)
BARRIERS = (9.0, 14.0)        # x, north wall: the opening the ticket barriers stand in
TICKET_SCREEN = (1.0, 4.6)    # y, wall x = XT: the two ticket windows over the counter
STAFF_DOOR = (8.9, 9.9)       # y, wall x = XT: concourse -> staff office
OFFICE_DOOR = (4.0, 5.0)      # x, wall y = YT: staff office -> ticket office
CORRIDOR = (YC0, YC1)         # y, wall x = XE: concourse -> corridor (no door)
GENTS_DOOR = (17.2, 18.2)     # x, wall y = YC0
LADIES_DOOR = (21.0, 22.0)    # x, wall y = YC0
LUGGAGE_ARCH = (16.8, 18.6)   # x, wall y = YC1 (no door)
WAITING_DOOR = (20.0, 21.0)   # x, wall y = YC1
PLATFORM_DOOR = (21.5, 22.5)  # x, wall y = YB: the waiting room onto the platform

N, S, E, WEST = 0.0, 3.1416, -1.5708, 1.5708  # yaw that turns a model's front (+y) north/south/east/west

base.COL.update({
    "terrazzo_tile": "0.78 0.76 0.72", "white_tile": "0.92 0.93 0.93", "platform_paving": "0.55 0.55 0.53",
    "coping": "0.85 0.84 0.8", "tactile_buff": "0.8 0.7 0.45", "yellow_line": "0.95 0.8 0.05",
    "woodfloor": "0.55 0.4 0.26", "plaster": "0.92 0.9 0.84", "partition": "0.86 0.86 0.84",
    "brick": "0.62 0.32 0.24", "cream": "0.93 0.89 0.76",
    "steel": "0.78 0.79 0.8", "dark_steel": "0.45 0.46 0.48", "heritage_green": "0.1 0.3 0.2",
    "oak": "0.6 0.45 0.28", "porcelain": "0.97 0.97 0.97", "mirror": "0.8 0.85 0.88",
    "rubber": "0.1 0.1 0.1", "screen": "0.05 0.06 0.08", "screen_lit": "0.25 0.45 0.6",
    "led_amber": "1.0 0.65 0.1", "led_white": "0.9 0.9 0.85", "station_blue": "0.1 0.2 0.5",
    "station_red": "0.75 0.1 0.12", "reader_yellow": "0.95 0.8 0.1", "go_green": "0.1 0.75 0.3",
    "stop_red": "0.85 0.1 0.1", "paddle_glass": "0.7 0.8 0.85", "clock_face": "0.97 0.97 0.95",
    "bin_black": "0.1 0.1 0.11", "bin_gold": "0.8 0.65 0.3", "recycle_green": "0.15 0.5 0.25",
    "map_paper": "0.95 0.94 0.88", "map_green": "0.5 0.7 0.4", "map_blue": "0.4 0.6 0.85",
    "map_line": "0.8 0.2 0.2", "help_green": "0.05 0.45 0.3", "button_red": "0.9 0.1 0.1",
    "atm_grey": "0.6 0.62 0.65", "seat_blue": "0.15 0.3 0.6", "heater_white": "0.94 0.94 0.92",
    "vend_red": "0.7 0.1 0.1", "vend_black": "0.12 0.12 0.14", "snack_a": "0.9 0.5 0.1",
    "snack_b": "0.2 0.5 0.8", "snack_c": "0.85 0.2 0.3", "snack_d": "0.3 0.7 0.3",
    "bottle_clear": "0.85 0.9 0.9", "bottle_red": "0.8 0.1 0.1", "bottle_orange": "0.95 0.55 0.1",
    "kiosk_wood": "0.45 0.3 0.18", "kiosk_top": "0.2 0.2 0.22", "chair_black": "0.1 0.1 0.1",
    "grey_plastic": "0.75 0.75 0.73", "fridge_white": "0.93 0.93 0.93", "magazine_a": "0.85 0.2 0.2",
    "magazine_b": "0.2 0.4 0.8", "magazine_c": "0.95 0.85 0.2", "magazine_d": "0.9 0.9 0.9",
    "coffee_brown": "0.35 0.2 0.1", "cup_white": "0.96 0.96 0.95", "locker_steel": "0.7 0.72 0.74",
    "locker_door": "0.2 0.45 0.65", "changing_grey": "0.75 0.77 0.78", "safe_grey": "0.35 0.37 0.4",
    "cork": "0.7 0.52 0.32", "paper": "0.96 0.96 0.94", "shelter_glass": "0.65 0.78 0.85",
    "trolley_steel": "0.7 0.72 0.75", "flower_red": "0.85 0.15 0.2", "flower_yellow": "0.95 0.8 0.15",
    "planter_wood": "0.45 0.3 0.18", "soil": "0.3 0.2 0.12", "extinguisher_red": "0.8 0.08 0.06",
    "exit_green": "0.05 0.6 0.25", "door_wood": "0.5 0.35 0.22", "glass_door": "0.6 0.75 0.85",
    "toilet_door": "0.5 0.6 0.7", "tile": "0.86 0.88 0.88",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
toilet, urinal, sink, mirror = rest.toilet, rest.urinal, rest.sink, rest.mirror
hand_dryer, fire_extinguisher, exit_sign = rest.hand_dryer, rest.fire_extinguisher, rest.exit_sign
turned, along_x, along_y = base.turned, base.along_x, base.along_y


def wheels(hx, hy, r=0.06):
    return [along_x(cyl(f"wheel{i}", "rubber", sx * hx, sy * hy, r, r, 0.04))
            for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]


# ---- doors and windows (local frames: x right, y forward = the side a person uses, z up) ----
def door(width=0.9, c="door_wood"):
    """An open door leaf, swung 90 degrees beside its opening (the office generator's door, any
    width): the leaf, a push plate and the handle."""
    return [box("leaf", c, 0, 0, 1.02, width, 0.04, 2.04),
            box("kick_plate", "steel", 0, 0.021, 0.12, width - 0.06, 0.004, 0.2),
            cyl("handle", "steel", width / 2 - 0.1, 0.04, 1.0, 0.015, 0.06)]


# ---- the ticket office and its counter ----
def ticket_window(w=1.8, h=1.35):
    """A ticket office window standing on the counter in the wall between the office and the
    concourse (the customer side at +y): the glazed screen in a steel frame, the round speech
    grille, the deal tray under the glass, a number sign above."""
    return [box("frame_l", "steel", -w / 2 + 0.03, 0, h / 2, 0.06, 0.1, h),
            box("frame_r", "steel", w / 2 - 0.03, 0, h / 2, 0.06, 0.1, h),
            box("frame_top", "steel", 0, 0, h - 0.03, w, 0.1, 0.06),
            box("pane", "glass", 0, 0, h / 2 + 0.05, w - 0.12, 0.012, h - 0.16),
            along_y(cyl("speech_grille", "dark_steel", 0, 0.01, 0.6, 0.08, 0.02)),
            box("deal_tray", "dark_steel", 0, 0, 0.03, 0.45, 0.4, 0.06),
            box("sign", "station_blue", 0, 0.055, h - 0.15, 0.4, 0.005, 0.16),
            box("sign_number", "white", 0, 0.058, h - 0.15, 0.1, 0.002, 0.1)]


def ticket_counter(length=3.6):
    """The ticket office counter running through the wall under the ticket windows: the top with
    the customers' ledge on the concourse side (+y) and the clerks' desk on the office side (-y),
    two drawer pedestals under the clerks' side, a brass nosing on the customer side."""
    v = [box("top", "kiosk_top", 0, -0.12, 0.925, length, 1.15, 0.05),
         box("nosing", "bin_gold", 0, 0.46, 0.925, length, 0.02, 0.06)]
    for i, x in enumerate((-length / 2 + 0.3, length / 2 - 0.3)):
        v += [box(f"pedestal{i}", "kiosk_wood", x, -0.4, 0.45, 0.45, 0.55, 0.9),
              box(f"drawer{i}", "dark_steel", x, -0.68, 0.7, 0.3, 0.01, 0.02)]
    return v


def safe():
    """A heavy steel safe on the floor: the body, the door with its dial and handle (+y)."""
    return [box("body", "safe_grey", 0, 0, 0.38, 0.55, 0.55, 0.76),
            box("door", "dark_steel", 0, 0.28, 0.38, 0.47, 0.01, 0.66),
            along_y(cyl("dial", "steel", 0.05, 0.295, 0.48, 0.05, 0.02)),
            box("handle", "steel", 0.05, 0.3, 0.3, 0.14, 0.02, 0.025),
            box("hinge", "dark_steel", -0.24, 0.29, 0.38, 0.03, 0.02, 0.5)]


def computer():
    """A desktop computer: the monitor facing the user (+y) on its stand, the keyboard, the mouse,
    the tower beside it."""
    return [box("monitor", "black", 0, 0, 0.3, 0.56, 0.04, 0.34),
            box("display", "screen_lit", 0, 0.021, 0.3, 0.52, 0.002, 0.3),
            box("neck", "dark_metal", 0, -0.04, 0.1, 0.05, 0.04, 0.16),
            box("foot", "dark_metal", 0, -0.02, 0.01, 0.22, 0.16, 0.02),
            box("keyboard", "black", 0, 0.3, 0.012, 0.44, 0.14, 0.025),
            box("mouse", "black", 0.3, 0.3, 0.015, 0.06, 0.1, 0.03),
            box("tower", "black", 0.48, 0, 0.21, 0.18, 0.42, 0.42)]


def notice_board(w=1.2, h=0.9):
    """A cork notice board on the wall (behind it at -y), centred on the model's height, with
    rosters and notices pinned to it."""
    v = [box("frame", "oak", 0, 0, 0, w, 0.03, h),
         box("cork", "cork", 0, 0.016, 0, w - 0.06, 0.004, h - 0.06)]
    spots = ((-0.35, 0.2, 0.21, 0.3), (0.0, 0.22, 0.21, 0.3), (0.35, 0.15, 0.21, 0.3),
             (-0.3, -0.2, 0.3, 0.21), (0.15, -0.2, 0.21, 0.3))
    return v + [box(f"notice{i}", "paper", x, 0.02, z, sx, 0.002, sz) for i, (x, z, sx, sz) in enumerate(spots)]


def heater(w=1.0):
    """A white electric panel heater on the wall (behind it at -y), low down, with its grille."""
    v = [box("panel", "heater_white", 0, 0.05, 0.45, w, 0.08, 0.5),
         box("control", "grey_plastic", w / 2 - 0.08, 0.092, 0.64, 0.08, 0.004, 0.05),
         box("outlet", "dark_steel", 0, 0.06, 0.7, w - 0.1, 0.06, 0.005)]
    return v + [box(f"fin{i}", "grey_plastic", -w / 2 + 0.1 + i * (w - 0.2) / 7, 0.092, 0.42, 0.02, 0.004, 0.36)
                for i in range(8)]


# ---- the concourse ----
def ticket_machine():
    """A self-service ticket machine against a wall (behind it at -y): the dark blue cabinet, the
    touch screen under a hood, the card reader and the keypad, the ticket and change slots, the
    lit header sign."""
    return [box("body", "station_blue", 0, 0, 0.88, 0.7, 0.55, 1.76),
            box("fascia", "dark_steel", 0, 0.276, 1.15, 0.6, 0.01, 0.7),
            turned(box("screen", "screen_lit", 0, 0.285, 1.3, 0.42, 0.01, 0.32), "-0.2 0 0"),
            box("hood", "station_blue", 0, 0.33, 1.5, 0.62, 0.12, 0.03),
            box("card_reader", "black", -0.18, 0.3, 0.98, 0.12, 0.05, 0.1),
            box("keypad", "steel", 0.15, 0.3, 0.98, 0.16, 0.05, 0.12),
            box("ticket_slot", "black", 0, 0.28, 0.8, 0.3, 0.02, 0.04),
            box("coin_slot", "steel", 0.22, 0.28, 1.08, 0.05, 0.02, 0.06),
            box("change_tray", "dark_steel", 0, 0.3, 0.55, 0.3, 0.06, 0.12),
            box("header", "led_white", 0, 0.2, 1.82, 0.7, 0.15, 0.12),
            box("header_text", "station_red", 0, 0.276, 1.82, 0.5, 0.004, 0.06)]


def cash_machine():
    """A cash machine set in a steel fascia against the wall (behind it at -y): the screen under
    its privacy hood, the keypad, the card slot, the cash slot, the bank's sign above."""
    return [box("fascia", "atm_grey", 0, 0, 1.0, 0.8, 0.3, 2.0),
            box("body", "dark_steel", 0, 0.16, 1.1, 0.62, 0.04, 0.6),
            turned(box("screen", "screen_lit", 0, 0.19, 1.3, 0.3, 0.01, 0.22), "-0.3 0 0"),
            box("privacy_hood", "dark_steel", 0, 0.24, 1.44, 0.4, 0.12, 0.02),
            turned(box("keypad", "steel", 0, 0.24, 1.05, 0.22, 0.16, 0.02), "-1.2 0 0"),
            box("card_slot", "go_green", 0.22, 0.185, 1.15, 0.08, 0.02, 0.03),
            box("cash_slot", "black", 0, 0.185, 0.9, 0.3, 0.02, 0.04),
            box("sign", "station_red", 0, 0.152, 1.85, 0.7, 0.004, 0.2)]


def bench(length=1.8, frame="steel", slats="steel", back=True):
    """A station bench with armrests: a frame of two end supports, seat and back slats (the back at
    -y), the sitter facing +y."""
    v = []
    for i, x in enumerate((-length / 2 + 0.08, length / 2 - 0.08)):
        v += [box(f"end{i}", frame, x, 0, 0.22, 0.06, 0.5, 0.44),
              box(f"arm{i}", frame, x, 0.02, 0.64, 0.06, 0.45, 0.04),
              box(f"arm_post{i}", frame, x, 0.2, 0.54, 0.04, 0.04, 0.2)]
        if back:
            v.append(box(f"back_post{i}", frame, x, -0.24, 0.66, 0.06, 0.04, 0.45))
    v += [box(f"seat_slat{i}", slats, 0, -0.18 + 0.09 * i, 0.45, length - 0.2, 0.07, 0.03) for i in range(5)]
    if back:
        v += [box(f"back_slat{i}", slats, 0, -0.25, 0.58 + 0.12 * i, length - 0.2, 0.03, 0.08) for i in range(3)]
    if length > 2.0:
        v.append(box("end_mid", frame, 0, 0, 0.22, 0.06, 0.5, 0.44))
    return v


def departure_board(w=2.4, h=0.8, rows=6, hang=0.0, double=False):
    """A departures display: a black frame with rows of amber times and destinations and a white
    header row, centred on the model's height; on a wall (behind it at -y) on a bracket, or hanging
    on two rods (hang = their length above the board), showing both ways when double."""
    v = [box("frame", "vend_black", 0, 0, 0, w, 0.12, h)]
    sides = (1, -1) if double else (1,)
    for s in sides:
        y = s * 0.062
        v.append(box(f"screen{s + 1}", "screen", 0, y, 0, w - 0.08, 0.004, h - 0.08))
        v.append(box(f"header{s + 1}", "led_white", -w / 4, y * 1.02, h / 2 - 0.1, w / 3, 0.004, 0.05))
        dz = (h - 0.24) / rows
        for r in range(rows):
            z = h / 2 - 0.2 - r * dz
            v += [box(f"time{s + 1}_{r}", "led_amber", -w / 2 + 0.18, y * 1.02, z, 0.2, 0.004, dz * 0.5),
                  box(f"dest{s + 1}_{r}", "led_amber", -0.1 - 0.04 * (r % 3), y * 1.02, z, w * 0.45 - 0.08 * (r % 2),
                      0.004, dz * 0.5),
                  box(f"plat{s + 1}_{r}", "led_amber", w / 2 - 0.35, y * 1.02, z, 0.08, 0.004, dz * 0.5),
                  box(f"status{s + 1}_{r}", "led_amber", w / 2 - 0.18, y * 1.02, z, 0.14 - 0.04 * (r % 2), 0.004,
                      dz * 0.5)]
    if hang > 0:
        v += [cyl(f"rod{i}", "dark_steel", x, 0, h / 2 + hang / 2, 0.015, hang)
              for i, x in enumerate((-w / 3, w / 3))]
    else:
        v.append(box("bracket", "dark_steel", 0, -0.1, 0, w / 2, 0.08, 0.15))
    return v


def clock(r=0.3, double=False, hang=0.0, bracket=0.0):
    """A station clock, centred on the model's height: a white face in a black case with the hour
    and minute hands, toward +y (and -y when double); on the wall behind it (at -y) or hanging on a
    rod (hang) or standing out from the wall on a bracket (bracket = its reach)."""
    def up(v):
        return turned(v, "1.5708 0 0")
    depth = 0.12 if double else 0.06
    v = [up(cyl("case", "black", 0, 0, 0, r + 0.03, depth))]
    for s in ((1, -1) if double else (1,)):
        y = s * (depth / 2 + 0.002)
        v += [up(cyl(f"face{s + 1}", "clock_face", 0, y, 0, r, 0.004)),
              box(f"hour_hand{s + 1}", "black", 0.07, y * 1.05, 0.05, 0.16, 0.004, 0.025),
              box(f"minute_hand{s + 1}", "black", 0, y * 1.05, 0.12, 0.02, 0.004, 0.24)]
        v += [box(f"mark{s + 1}_{k}", "black", (r - 0.04) * dx, y * 1.03, (r - 0.04) * dz, 0.03, 0.004, 0.03)
              for k, (dx, dz) in enumerate(((0, 1), (1, 0), (0, -1), (-1, 0)))]
    if hang > 0:
        v.append(cyl("rod", "dark_steel", 0, 0, r + 0.03 + hang / 2, 0.02, hang))
    if bracket > 0:
        v += [box("bracket", "heritage_green", -r - 0.03 - bracket / 2, 0, 0, bracket, 0.05, 0.06),
              box("wall_plate", "heritage_green", -r - 0.03 - bracket, 0, 0, 0.02, 0.2, 0.3)]
    return v


def litter_bin():
    """A round black station litter bin with a gold band, a domed lid and the slot under it."""
    return [cyl("body", "bin_black", 0, 0, 0.45, 0.24, 0.9),
            cyl("band", "bin_gold", 0, 0, 0.75, 0.245, 0.05),
            cyl("slot_ring", "vend_black", 0, 0, 0.96, 0.2, 0.12),
            sph("lid", "bin_black", 0, 0, 1.02, 0.24),
            cyl("foot", "bin_black", 0, 0, 0.02, 0.26, 0.04)]


def recycling_bin():
    """A green recycling bin: a square body with two round openings (cans, paper) and the
    recycling label on its front (+y)."""
    return [box("body", "recycle_green", 0, 0, 0.5, 0.7, 0.45, 1.0),
            box("lid", "recycle_green", 0, 0, 1.02, 0.74, 0.49, 0.04),
            cyl("opening0", "black", -0.17, 0.05, 1.045, 0.09, 0.01),
            cyl("opening1", "black", 0.17, 0.05, 1.045, 0.09, 0.01),
            box("label", "white", 0, 0.226, 0.7, 0.3, 0.004, 0.3),
            box("arrows", "recycle_green", 0, 0.229, 0.7, 0.16, 0.002, 0.16)]


def information_board(w=1.2, h=1.0):
    """A wall-mounted information board (the wall behind at -y), centred on the model's height: a
    map of the area behind glass in a frame, the station's name on a header, a list of bus stops."""
    v = [box("frame", "heritage_green", 0, 0, 0, w, 0.05, h),
         box("header", "station_blue", 0, 0.026, h / 2 - 0.08, w - 0.06, 0.004, 0.12),
         box("map", "map_paper", -0.1, 0.026, -0.06, w - 0.35, 0.004, h - 0.28),
         box("park", "map_green", -0.3, 0.028, 0.1, 0.25, 0.002, 0.2),
         box("river", "map_blue", -0.1, 0.028, -0.25, w - 0.4, 0.002, 0.05),
         box("railway", "map_line", -0.1, 0.029, 0.0, w - 0.4, 0.002, 0.02),
         box("you_are_here", "station_red", 0.05, 0.03, 0.0, 0.04, 0.002, 0.04),
         box("list", "paper", w / 2 - 0.12, 0.026, -0.06, 0.18, 0.004, h - 0.3),
         box("pane", "glass", 0, 0.03, -0.04, w - 0.06, 0.002, h - 0.2)]
    return v


def help_point():
    """A help point on the wall (behind it at -y): the green unit with a speaker grille, the
    information and emergency buttons, the sign on top."""
    return [box("body", "help_green", 0, 0.06, 1.3, 0.3, 0.12, 0.5),
            box("sign", "white", 0, 0.121, 1.48, 0.24, 0.004, 0.08),
            along_y(cyl("speaker", "dark_steel", 0, 0.12, 1.32, 0.06, 0.01)),
            along_y(cyl("info_button", "go_green", -0.07, 0.125, 1.17, 0.03, 0.02)),
            along_y(cyl("emergency_button", "button_red", 0.07, 0.125, 1.17, 0.03, 0.02)),
            box("camera", "black", 0, 0.1, 1.58, 0.06, 0.05, 0.04)]


def ticket_barrier(paddle_l=0.0, paddle_r=0.0):
    """A ticket barrier cabinet in the gate line, passengers walking along y: the steel cabinet
    with the yellow smartcard reader and the ticket slot on its sloped top, green and red lights at
    both ends, and the glass paddles (paddle_l, paddle_r: their reach into the gate on each side, 0
    for none) shut across the gates."""
    v = [box("cabinet", "steel", 0, 0, 0.5, 0.25, 1.3, 1.0),
         turned(box("top", "dark_steel", 0, 0.35, 1.02, 0.25, 0.45, 0.03), "0.15 0 0"),
         box("reader", "reader_yellow", 0, 0.4, 1.06, 0.16, 0.16, 0.01),
         box("ticket_slot", "black", 0, 0.15, 1.015, 0.12, 0.05, 0.01),
         box("plinth", "dark_steel", 0, 0, 0.03, 0.27, 1.32, 0.06)]
    for s, name in ((1, "n"), (-1, "s")):
        v += [box(f"light_go_{name}", "go_green", 0, s * 0.651, 0.9, 0.12, 0.004, 0.08),
              box(f"light_stop_{name}", "stop_red", 0, s * 0.651, 0.78, 0.12, 0.004, 0.08)]
    if paddle_l > 0:
        v.append(box("paddle_l", "paddle_glass", -0.125 - paddle_l / 2, 0.05, 0.72, paddle_l, 0.02, 0.6))
    if paddle_r > 0:
        v.append(box("paddle_r", "paddle_glass", 0.125 + paddle_r / 2, 0.05, 0.72, paddle_r, 0.02, 0.6))
    return v


# ---- the kiosk ----
def kiosk_counter(length=2.5):
    """The kiosk's serving counter, the customers at +y: a wooden front with a snack display
    shelf, the dark top, the staff side open with an undershelf."""
    v = [box("front", "kiosk_wood", 0, 0.26, 0.5, length, 0.06, 1.0),
         box("top", "kiosk_top", 0, 0.02, 1.02, length + 0.06, 0.64, 0.04),
         box("side_l", "kiosk_wood", -length / 2 + 0.03, 0, 0.5, 0.06, 0.55, 1.0),
         box("side_r", "kiosk_wood", length / 2 - 0.03, 0, 0.5, 0.06, 0.55, 1.0),
         box("undershelf", "kiosk_wood", 0, -0.02, 0.3, length - 0.1, 0.5, 0.03),
         box("display_shelf", "kiosk_top", 0, 0.34, 0.65, length - 0.2, 0.12, 0.02)]
    colours = ("snack_a", "snack_b", "snack_c", "snack_d")
    v += [box(f"snack{i}", colours[i % 4], -length / 2 + 0.2 + 0.16 * i, 0.34, 0.72, 0.12, 0.06, 0.12)
          for i in range(int((length - 0.3) / 0.16))]
    return v


def cash_register():
    """A till on a counter: the cash drawer, the keypad and the touch screen facing the cashier
    (-y), the small customer display facing +y, a card terminal."""
    return [box("drawer", "chair_black", 0, 0, 0.05, 0.42, 0.4, 0.1),
            box("keypad", "grey_plastic", 0, -0.09, 0.12, 0.3, 0.16, 0.04),
            turned(box("screen", "screen_lit", 0, 0.06, 0.25, 0.32, 0.02, 0.22), "0.3 0 0"),
            box("stand", "chair_black", 0, 0.08, 0.15, 0.06, 0.04, 0.1),
            box("customer_display", "screen", 0, 0.17, 0.2, 0.16, 0.02, 0.06),
            box("card_terminal", "black", 0.3, 0.1, 0.04, 0.08, 0.16, 0.06)]


def drinks_fridge():
    """An upright chiller for cold drinks: a glass door toward the customer (+y), four shelves of
    bottles behind it, a lit header panel, the handle."""
    colours = ("bottle_clear", "bottle_red", "bottle_orange", "snack_b")
    v = [box("body", "fridge_white", 0, 0, 0.98, 0.65, 0.65, 1.96),
         box("header", "station_red", 0, 0.33, 1.85, 0.62, 0.01, 0.2),
         box("door", "glass_door", 0, 0.33, 0.95, 0.56, 0.01, 1.6),
         cyl("handle", "steel", 0.24, 0.37, 0.95, 0.012, 0.6),
         box("base_grille", "black", 0, 0.33, 0.07, 0.56, 0.01, 0.1)]
    for i in range(4):
        z = 0.3 + 0.38 * i
        v.append(box(f"shelf{i}", "steel", 0, 0.05, z, 0.56, 0.5, 0.015))
        v += [cyl(f"bottle{i}_{k}", colours[(i + k) % 4], -0.22 + 0.088 * k, 0.2, z + 0.12, 0.03, 0.22)
              for k in range(6)]
    return v


def magazine_rack(w=1.0):
    """A newsagent's magazine rack against the wall (behind it at -y): three sloped tiers of
    magazines and a bottom shelf of newspapers."""
    colours = ("magazine_a", "magazine_b", "magazine_c", "magazine_d")
    v = [box("side_l", "kiosk_wood", -w / 2 + 0.02, 0, 0.75, 0.04, 0.4, 1.5),
         box("side_r", "kiosk_wood", w / 2 - 0.02, 0, 0.75, 0.04, 0.4, 1.5),
         box("back", "kiosk_wood", 0, -0.18, 0.75, w, 0.03, 1.5),
         box("bottom", "kiosk_wood", 0, 0, 0.15, w - 0.04, 0.38, 0.03)]
    v += [box(f"newspaper{k}", "magazine_d", -w / 2 + 0.15 + 0.24 * k, 0, 0.2, 0.22, 0.32, 0.06) for k in range(4)]
    for i in range(3):
        z = 0.55 + 0.32 * i
        y = 0.12 - 0.08 * i
        v.append(turned(box(f"tier{i}", "kiosk_wood", 0, y, z, w - 0.04, 0.02, 0.28), "-0.25 0 0"))
        v += [turned(box(f"magazine{i}_{k}", colours[(i + k) % 4], -w / 2 + 0.14 + 0.18 * k, y + 0.015, z + 0.02,
                         0.16, 0.01, 0.22), "-0.25 0 0") for k in range(int((w - 0.1) / 0.18))]
    return v


def coffee_machine():
    """A floor-standing bean-to-cup coffee machine: the black body, the lit menu panel, the cup
    bay with a cup in it and the drip tray, a stack of cups on top (+y is its front)."""
    return [box("body", "black", 0, 0, 0.85, 0.6, 0.6, 1.7),
            box("panel", "screen_lit", 0, 0.302, 1.35, 0.4, 0.005, 0.3),
            box("brand", "coffee_brown", 0, 0.302, 1.6, 0.5, 0.005, 0.12),
            box("cup_bay", "dark_steel", 0, 0.28, 0.95, 0.28, 0.06, 0.3),
            cyl("cup", "cup_white", 0, 0.26, 0.88, 0.04, 0.1),
            box("drip_tray", "steel", 0, 0.3, 0.82, 0.28, 0.08, 0.02),
            cyl("cup_stack", "cup_white", -0.18, 0, 1.85, 0.045, 0.3)]


# ---- the waiting room ----
def chair():
    """A waiting room chair: a chrome frame, a blue moulded seat and back (the back at -y)."""
    return [box("seat", "seat_blue", 0, 0, 0.46, 0.48, 0.46, 0.05),
            turned(box("back", "seat_blue", 0, -0.23, 0.74, 0.48, 0.04, 0.5), "-0.1 0 0"),
            box("rail_l", "steel", -0.22, 0, 0.43, 0.03, 0.44, 0.03),
            box("rail_r", "steel", 0.22, 0, 0.43, 0.03, 0.44, 0.03)] + legs("steel", 0.21, 0.19, 0.43, 0.03)


def vending_machine(drinks=False):
    """A vending machine (the wall behind at -y): the glass window on the left of its front (+y)
    with rows of snacks (or bottles), the keypad and the coin and card panel on the right, the
    collection flap at the bottom."""
    colours = ("snack_a", "snack_b", "snack_c", "snack_d")
    v = [box("body", "vend_red" if drinks else "vend_black", 0, 0, 0.93, 0.9, 0.8, 1.86),
         box("window", "glass", -0.1, 0.402, 1.1, 0.6, 0.005, 1.3),
         box("panel", "dark_steel", 0.33, 0.402, 1.1, 0.18, 0.005, 1.1),
         box("keypad", "steel", 0.33, 0.41, 1.25, 0.12, 0.01, 0.16),
         box("card_reader", "black", 0.33, 0.41, 1.0, 0.1, 0.01, 0.08),
         box("flap", "black", -0.1, 0.405, 0.25, 0.5, 0.01, 0.16)]
    for i in range(5):
        z = 0.6 + 0.24 * i
        v.append(box(f"shelf{i}", "steel", -0.1, 0.2, z, 0.56, 0.35, 0.01))
        for k in range(4):
            x, c = -0.33 + 0.15 * k, colours[(i + k) % 4]
            if drinks:
                v.append(cyl(f"bottle{i}_{k}", c, x, 0.3, z + 0.1, 0.03, 0.19))
            else:
                v.append(box(f"snack{i}_{k}", c, x, 0.3, z + 0.08, 0.11, 0.03, 0.15))
    return v


# ---- left luggage ----
def luggage_locker(cols=2, rows=4):
    """A bank of left-luggage lockers against the wall (behind it at -y): a steel cabinet, its
    front divided into blue locker doors, each with a number plate and a keypad lock."""
    w, h = 0.9, 1.9
    v = [box("cabinet", "locker_steel", 0, 0, h / 2, w, 0.5, h),
         box("plinth", "dark_steel", 0, 0.02, 0.05, w, 0.46, 0.1)]
    dw, dh = w / cols, (h - 0.15) / rows
    for c in range(cols):
        for r in range(rows):
            x, z = -w / 2 + dw * (c + 0.5), 0.12 + dh * (r + 0.5)
            v += [box(f"door{c}_{r}", "locker_door", x, 0.251, z, dw - 0.03, 0.004, dh - 0.03),
                  box(f"number{c}_{r}", "white", x - dw / 4, 0.254, z + dh / 3, 0.06, 0.002, 0.04),
                  box(f"lock{c}_{r}", "black", x + dw / 3, 0.256, z, 0.05, 0.008, 0.08)]
    return v


# ---- the toilets ----
def baby_changing_table():
    """A fold-down baby changing unit on the wall (behind it at -y), folded open: the wall plate,
    the bed with its padded hollow and safety strap, the hinge brackets."""
    return [box("wall_plate", "changing_grey", 0, 0.03, 1.05, 0.9, 0.06, 0.6),
            box("bed", "changing_grey", 0, 0.33, 0.85, 0.86, 0.56, 0.08),
            box("pad", "seat_blue", 0, 0.35, 0.895, 0.7, 0.42, 0.01),
            box("strap", "black", 0, 0.35, 0.9, 0.05, 0.44, 0.005),
            box("bracket_l", "steel", -0.4, 0.2, 0.75, 0.03, 0.3, 0.12),
            box("bracket_r", "steel", 0.4, 0.2, 0.75, 0.03, 0.3, 0.12)]


# ---- the platform ----
def shelter(w=2.4, d=1.3, h=2.3):
    """A platform waiting shelter, open at the front (+y): a dark green steel frame with glass back
    and side panels, the flat roof, a timetable poster on the back panel."""
    v = [box("roof", "heritage_green", 0, 0, h + 0.04, w + 0.1, d + 0.1, 0.08),
         box("back", "shelter_glass", 0, -d / 2 + 0.02, h / 2 + 0.05, w - 0.08, 0.012, h - 0.2),
         box("side_l", "shelter_glass", -w / 2 + 0.02, 0, h / 2 + 0.05, 0.012, d - 0.08, h - 0.2),
         box("side_r", "shelter_glass", w / 2 - 0.02, 0, h / 2 + 0.05, 0.012, d - 0.08, h - 0.2),
         box("poster", "paper", w / 4, -d / 2 + 0.03, 1.4, 0.6, 0.004, 0.85)]
    v += [box(f"post{i}", "heritage_green", sx * (w / 2 - 0.03), sy * (d / 2 - 0.03), h / 2, 0.06, 0.06, h)
          for i, (sx, sy) in enumerate(((-1, -1), (1, -1), (-1, 1), (1, 1)))]
    v += [box("rail_back", "heritage_green", 0, -d / 2 + 0.03, 0.08, w, 0.05, 0.05),
          box("rail_top", "heritage_green", 0, -d / 2 + 0.03, h - 0.05, w, 0.05, 0.05)]
    return v


def pillar(h=CANOPY[3]):
    """A cast-iron canopy column in heritage green: a square plinth, the fluted shaft, the capital
    and two spandrel brackets up to the canopy."""
    return [box("plinth", "heritage_green", 0, 0, 0.2, 0.4, 0.4, 0.4),
            cyl("shaft", "heritage_green", 0, 0, h / 2, 0.12, h),
            cyl("collar", "cream", 0, 0, 1.2, 0.13, 0.05),
            cyl("capital", "heritage_green", 0, 0, h - 0.3, 0.2, 0.2),
            box("bracket_n", "heritage_green", 0, 0.35, h - 0.2, 0.06, 0.6, 0.25),
            box("bracket_s", "heritage_green", 0, -0.35, h - 0.2, 0.06, 0.6, 0.25)]


def cycle_rack(n=3, gap=0.9):
    """A row of Sheffield stands bolted to the platform: inverted U hoops of steel tube, the bikes
    parked along y beside them, on a rail."""
    v = [box("rail", "dark_steel", 0, 0, 0.02, gap * (n - 1) + 0.1, 0.08, 0.04)]
    for i in range(n):
        x = -gap * (n - 1) / 2 + gap * i
        v += [cyl(f"post{i}_a", "steel", x, -0.33, 0.42, 0.025, 0.84),
              cyl(f"post{i}_b", "steel", x, 0.33, 0.42, 0.025, 0.84),
              along_y(cyl(f"top{i}", "steel", x, 0, 0.84, 0.025, 0.7)),
              along_y(cyl(f"bar{i}", "steel", x, 0, 0.35, 0.02, 0.66))]
    return v


def luggage_trolley():
    """A luggage trolley: a tubular steel frame on four wheels, the base deck, the inclined back
    frame with the handle bar (at -y), a small basket at the handle."""
    v = [box("deck", "trolley_steel", 0, 0.1, 0.17, 0.55, 0.8, 0.03),
         box("frame_l", "trolley_steel", -0.28, 0, 0.15, 0.03, 1.0, 0.03),
         box("frame_r", "trolley_steel", 0.28, 0, 0.15, 0.03, 1.0, 0.03),
         turned(box("back_l", "trolley_steel", -0.28, -0.42, 0.6, 0.03, 0.03, 0.9), "-0.2 0 0"),
         turned(box("back_r", "trolley_steel", 0.28, -0.42, 0.6, 0.03, 0.03, 0.9), "-0.2 0 0"),
         turned(box("back_mesh", "grey_plastic", 0, -0.42, 0.55, 0.53, 0.01, 0.6), "-0.2 0 0"),
         along_x(cyl("handle", "black", 0, -0.52, 1.04, 0.02, 0.64)),
         box("basket", "trolley_steel", 0, -0.3, 0.88, 0.45, 0.25, 0.1)]
    return v + wheels(0.25, 0.4, 0.07)


def planter():
    """A square wooden planter of flowers: the tub, the soil, foliage and red and yellow blooms."""
    v = [box("tub", "planter_wood", 0, 0, 0.25, 0.8, 0.5, 0.5),
         box("rim", "planter_wood", 0, 0, 0.51, 0.86, 0.56, 0.03),
         box("soil", "soil", 0, 0, 0.5, 0.76, 0.46, 0.02),
         sph("foliage0", "leaf", -0.2, 0, 0.62, 0.18), sph("foliage1", "leaf", 0.18, 0.02, 0.63, 0.2)]
    return v + [sph(f"bloom{i}", ("flower_red", "flower_yellow")[i % 2], -0.3 + 0.12 * i, 0.08 * (i % 3 - 1),
                    0.78 - 0.02 * (i % 2), 0.05) for i in range(6)]


# ---- structure ----
def walls():
    """The building's outer walls with the entrance (south), the opening of the gate line and the
    waiting room's platform door (north); the walls of the ticket office (the ticket screen in its
    east wall) and the staff office, the east wing with its corridor, the toilets and their cubicle
    partitions, left luggage and the waiting room, the kiosk's partition."""
    v, wall = base.wall_builder(H, T)

    def with_openings(fixed, along, lo, hi, openings, c="plaster", top=LINTEL):
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

    with_openings(0, "x", 0, W, (ENTRANCE,), "brick", 2.6)
    # the north wall: the gate line's opening (its lintel carries the departure board) and the
    # waiting room's door
    wall(0, YB, BARRIERS[0], YB, c="brick")
    wall(BARRIERS[0], YB, BARRIERS[1], YB, 2.6, H, c="brick")
    with_openings(YB, "x", BARRIERS[1], W, (PLATFORM_DOOR,), "brick")
    wall(0, 0, 0, YB, c="brick"); wall(W, 0, W, YB, c="brick")
    # the ticket office's east wall: the counter wall under the ticket windows, the staff door
    t0, t1 = TICKET_SCREEN
    wall(XT, 0, XT, t0); wall(XT, t0, XT, t1, 0, 0.9); wall(XT, t0, XT, t1, 2.3, H)
    with_openings(XT, "y", t1, YB, (STAFF_DOOR,))
    with_openings(YT, "x", 0, XT, (OFFICE_DOOR,), "partition")
    # the east wing: the corridor off the concourse, the toilets south of it, left luggage and the
    # waiting room north of it
    with_openings(XE, "y", 0, YB, (CORRIDOR,), top=2.6)
    with_openings(YC0, "x", XE, W, (GENTS_DOOR, LADIES_DOOR), "white_tile")
    with_openings(YC1, "x", XE, W, (LUGGAGE_ARCH, WAITING_DOOR), "partition")
    wall(XG, 0, XG, YC0, c="white_tile")
    wall(XL, YC1, XL, YB, c="partition")
    # cubicle partitions: two in the gents, three in the ladies
    for x in (18.0, 19.0, 21.0, 22.0, 23.0):
        wall(x, T / 2, x, 1.6, 0, 2.0, c="partition")
    # the kiosk's north partition
    wall(13.0, 3.6, XE, 3.6, 0, 2.6, c="partition")
    return v


def floor():
    """The floor: terrazzo tiles in the building, white tiles in the toilets, carpet in the offices,
    oak boards in the waiting room (thin layers over the slab); the platform's paving with the
    yellow line, the tactile strip and the white coping along its edge."""
    v = base.floor_slab("floor_station", "terrazzo_tile", W, D)
    v.append(box("platform", "platform_paving", W / 2, (YB + D) / 2, 0.0005, W, D - YB, 0.001))
    v.append(box("yellow_line", "yellow_line", W / 2, 12.95, 0.0012, W, 0.1, 0.001))
    v.append(box("tactile_strip", "tactile_buff", W / 2, 13.4, 0.0012, W, 0.4, 0.001))
    v.append(box("coping", "coping", W / 2, 13.8, 0.0012, W, 0.4, 0.001))
    v.append(box("toilets", "white_tile", (XE + W) / 2, YC0 / 2, 0.0005, W - XE, YC0, 0.001))
    v.append(box("offices", "carpet", XT / 2, YB / 2, 0.0005, XT, YB, 0.001))
    v.append(box("waiting_room", "woodfloor", (XL + W) / 2, (YC1 + YB) / 2, 0.0005, W - XL, YB - YC1, 0.001))
    return v


def ceiling():
    """The building's ceiling and the platform canopy on its pillars (a lower slab with a valance
    along its edge)."""
    x0, x1, y1, h = CANOPY
    return base.ceiling_slab(W, YB, H) + [
        box("canopy", "heritage_green", (x0 + x1) / 2, (YB + y1) / 2, h + 0.05, x1 - x0, y1 - YB, 0.1),
        box("canopy_valance", "cream", (x0 + x1) / 2, y1 - 0.02, h - 0.15, x1 - x0, 0.04, 0.3)]


# ---- the rooms ----
def ticket_office(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    t0, t1 = TICKET_SCREEN
    add("ticket_counter", (XT, (t0 + t1) / 2, 0, E), ticket_counter(t1 - t0))  # the customer ledge east
    for i, y in enumerate(((3 * t0 + t1) / 4, (t0 + 3 * t1) / 4), 1):
        add(f"ticket_window_{i}", (XT, y, 0.95, E), ticket_window((t1 - t0) / 2, 1.35))
        add(f"computer_{i}", (XT - 0.35, y, 0.95, WEST), computer())  # its screen toward the clerk
        add(f"office_chair_{i}", (XT - 1.15, y, 0, E), base.office_chair())
    add("safe", (0.4, 0.4, 0, N), safe())
    add("filing_cabinet_1", (0.38, 4.4, 0, E), base.filing_cabinet())
    add("window_1", (3.0, T / 2 + 0.02, 1.6, N), base.window())
    add("litter_bin_1", (3.6, 0.35, 0, N), litter_bin())


def staff_office(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    o0, o1 = OFFICE_DOOR
    s0, s1 = STAFF_DOOR
    add("door_1", (XT - T / 2 - 0.47, s1 - 0.04, 0, 0), door(0.9))  # from the concourse, hinged at its north side
    add("door_2", (o1 - 0.04, YT - T / 2 - 0.47, 0, WEST), door(0.9))  # into the ticket office, hinged at its east side
    add("desk", (1.3, YB - T / 2 - 0.38, 0, N), base.desk())
    add("office_chair_3", (1.3, YB - 1.1, 0, N), base.office_chair())
    add("computer_3", (1.3, YB - T / 2 - 0.32, 0.75, S), computer())
    add("filing_cabinet_2", (3.0, YB - T / 2 - 0.33, 0, S), base.filing_cabinet())
    add("notice_board", (2.5, YT + T / 2 + 0.02, 1.5, N), notice_board())
    add("heater_1", (T / 2, 7.5, 0, E), heater(1.0))
    add("window_2", (4.4, YB - T / 2 - 0.02, 1.6, S), base.window())
    add("fire_extinguisher_1", (XT - T / 2 - 0.1, 7.9, 0, WEST), fire_extinguisher())


def concourse(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    e0, e1 = ENTRANCE
    ws = T / 2  # the south wall's inner face
    add("door_3", (e0 + 0.04, 0.62, 0, WEST), door(1.2, "glass_door"))  # two glazed leaves swung in
    add("door_4", (e1 - 0.04, 0.62, 0, WEST), door(1.2, "glass_door"))
    add("exit_sign_1", ((e0 + e1) / 2, ws + 0.03, 2.8, N), exit_sign())
    add("clock_1", ((e0 + e1) / 2, ws + 0.04, 3.35, N), clock(0.35))
    add("cash_machine", (6.9, ws + 0.15, 0, N), cash_machine())
    add("ticket_machine_1", (8.0, ws + 0.28, 0, N), ticket_machine())
    add("ticket_machine_2", (8.9, ws + 0.28, 0, N), ticket_machine())
    add("recycling_bin_1", (9.75, ws + 0.25, 0, N), recycling_bin())
    add("litter_bin_2", (10.4, 0.4, 0, N), litter_bin())
    add("window_3", (8.4, ws + 0.02, 2.9, N), base.window())
    add("window_4", (15.0, ws + 0.02, 2.9, N), base.window())
    # the west wall: a ticket machine and the information board between the ticket windows and
    # the staff door
    add("information_board_1", (XT + T / 2 + 0.03, 5.3, 1.55, E), information_board())
    add("ticket_machine_3", (XT + T / 2 + 0.28, 6.7, 0, E), ticket_machine())
    add("litter_bin_3", (XT + 0.4, 7.6, 0, N), litter_bin())
    # benches back to back in the middle, a bin beside them
    add("bench_1", (11.2, 4.85, 0, S), bench(2.0))
    add("bench_2", (11.2, 5.45, 0, N), bench(2.0))
    add("litter_bin_4", (12.7, 5.15, 0, N), litter_bin())
    # the gate line: the departure board over it, a help point and a bin beside it
    b0, b1 = BARRIERS
    add("departure_board_1", ((b0 + b1) / 2, YB - T / 2 - 0.1, 3.2, S), departure_board(2.8, 0.9, 7))
    gates = (0.55, 0.55, 0.55, 0.55, 1.3)  # four narrow gates and the wide one, west to east
    x = b0 + 0.125
    for i in range(6):
        pl = gates[i - 1] / 2 - 0.01 if i > 0 and gates[i - 1] < 1 else 0.0
        pr = gates[i] / 2 - 0.01 if i < 5 and gates[i] < 1 else 0.0
        add(f"ticket_barrier_{i + 1}", (x, YB, 0, N), ticket_barrier(pl, pr))
        if i < 5:
            x += 0.25 + gates[i]
    add("help_point_1", (14.9, YB - T / 2, 0, S), help_point())
    add("litter_bin_5", (8.5, 9.95, 0, N), litter_bin())
    add("departure_board_2", (XE - T / 2 - 0.1, 8.2, 2.4, WEST), departure_board(1.6, 0.6, 5))
    add("fire_extinguisher_2", (XE - T / 2 - 0.1, 9.6, 0, WEST), fire_extinguisher())


def kiosk(out):
    """The newsagent and coffee kiosk in the concourse's south-east corner: the counter faces west,
    its south end against the front wall, the staff get behind it by the gap at its north end."""
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    add("kiosk_counter", (13.6, T / 2 + 1.26, 0, WEST), kiosk_counter(2.5))
    add("cash_register", (13.62, 1.0, 1.04, WEST), cash_register())  # the cashier east of it
    add("coffee_machine", (XE - T / 2 - 0.32, 2.0, 0, WEST), coffee_machine())
    add("litter_bin_6", (15.6, 0.45, 0, N), litter_bin())
    add("drinks_fridge", (13.55, 3.6 + T / 2 + 0.34, 0, N), drinks_fridge())
    add("magazine_rack_1", (14.8, 3.6 + T / 2 + 0.2, 0, N), magazine_rack(1.0))
    add("magazine_rack_2", (15.68, 3.6 + T / 2 + 0.2, 0, N), magazine_rack(0.5))


def toilets(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    g0, g1 = GENTS_DOOR
    l0, l1 = LADIES_DOOR
    wn = YC0 - T / 2  # the corridor wall's toilet face
    add("door_5", (g0 + 0.04, wn - 0.47, 0, WEST), door(0.9, "toilet_door"))  # gents, hinged at its west side
    add("door_6", (l1 - 0.04, wn - 0.47, 0, WEST), door(0.9, "toilet_door"))  # ladies, hinged at its east side
    # the gents: two toilets in cubicles on the south wall, two urinals on the west wall, the sink,
    # mirror and hand dryer on the east wall
    add("toilet_1", (18.5, T / 2 + 0.31, 0, N), toilet())
    add("toilet_2", (19.48, T / 2 + 0.31, 0, N), toilet())
    add("urinal_1", (XE + T / 2 + 0.02, 1.2, 0, E), urinal())
    add("urinal_2", (XE + T / 2 + 0.02, 2.0, 0, E), urinal())
    add("sink_1", (XG - T / 2 - 0.01, 3.3, 0, WEST), sink())
    add("mirror_1", (XG - T / 2 - 0.02, 3.3, 1.55, WEST), mirror(0.5, 0.7))
    add("hand_dryer_1", (XG - T / 2 - 0.01, 2.3, 0, WEST), hand_dryer())
    # the ladies: three toilets in cubicles, two sinks with mirrors and the hand dryer on the east
    # wall, the baby changing table on the west wall
    for i, x in enumerate((21.5, 22.5, 23.48), 3):
        add(f"toilet_{i}", (x, T / 2 + 0.31, 0, N), toilet())
    for i, y in enumerate((2.8, 3.7), 2):
        add(f"sink_{i}", (W - T / 2 - 0.01, y, 0, WEST), sink())
        add(f"mirror_{i}", (W - T / 2 - 0.02, y, 1.55, WEST), mirror(0.5, 0.7))
    add("hand_dryer_2", (W - T / 2 - 0.01, 2.0, 0, WEST), hand_dryer())
    add("baby_changing_table", (XG + T / 2 + 0.01, 2.7, 0, E), baby_changing_table())


def left_luggage(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    k = [0]

    def locker(x, y, yaw):
        k[0] += 1
        add(f"luggage_locker_{k[0]}", (x, y, 0, yaw), luggage_locker())
    wn = YB - T / 2 - 0.25
    for x in (16.65, 17.6, 18.55):
        locker(x, wn, S)
    for y in (7.4, 8.35):
        locker(XE + T / 2 + 0.25, y, E)
    for y in (7.4, 8.35):
        locker(XL - T / 2 - 0.25, y, WEST)


def waiting_room(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    w0, w1 = WAITING_DOOR
    p0, p1 = PLATFORM_DOOR
    add("door_7", (w0 + 0.04, YC1 + T / 2 + 0.47, 0, WEST), door(0.9, "glass_door"))  # from the corridor
    add("door_8", (p1 - 0.04, YB - T / 2 - 0.47, 0, WEST), door(0.9, "glass_door"))  # onto the platform
    c = [0]

    def seat(x, y, yaw):
        c[0] += 1
        add(f"chair_{c[0]}", (x, y, 0, yaw), chair())
    for y in (7.4, 7.95, 8.5, 9.05, 9.6):  # along the west wall, facing east
        seat(XL + T / 2 + 0.3, y, E)
    for y in (7.3, 7.85, 8.4, 8.95):  # a row in the middle facing west
        seat(21.9, y, WEST)
    add("vending_machine_1", (W - T / 2 - 0.42, 8.5, 0, WEST), vending_machine(False))
    add("vending_machine_2", (W - T / 2 - 0.42, 9.5, 0, WEST), vending_machine(True))
    add("heater_2", (22.8, YC1 + T / 2, 0, N), heater(1.0))
    add("heater_3", (20.5, YB - T / 2, 0, S), heater(1.0))
    add("departure_board_3", (22.8, YC1 + T / 2 + 0.1, 2.3, N), departure_board(1.2, 0.5, 4))
    add("clock_2", (XL + T / 2 + 0.04, 8.5, 2.4, E), clock(0.2))
    add("litter_bin_7", (23.6, 6.45, 0, N), litter_bin())
    add("window_5", (20.5, YB - T / 2 - 0.02, 1.7, S), base.window())
    add("window_6", (23.3, YB - T / 2 - 0.02, 1.7, S), base.window())


def platform(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    wf = YB + T / 2  # the building's platform face; nothing stands beyond the yellow line (y 12.95)
    for i, x in enumerate((4.5, 8.5, 15.5, 19.0), 1):
        add(f"pillar_{i}", (x, 12.2, 0, N), pillar())
    add("bench_3", (2.0 + 1.3, wf + 0.3, 0, N), bench(1.8, "heritage_green", "oak"))
    add("bench_4", (6.5, wf + 0.3, 0, N), bench(1.8, "heritage_green", "oak"))
    add("bench_5", (17.5, wf + 0.3, 0, N), bench(1.8, "heritage_green", "oak"))
    add("shelter", (1.4, 12.3, 0, N), shelter())
    add("bench_6", (1.4, 11.95, 0, N), bench(1.8, "heritage_green", "oak", back=False))  # in the shelter
    b0, b1 = BARRIERS
    add("departure_board_4", ((b0 + b1) / 2, 12.2, 2.75, N), departure_board(2.0, 0.6, 5, 0.45, True))
    add("clock_3", (8.5, 12.2 - 0.12 - 0.48, 2.9, E), clock(0.3, True, 0, 0.15))  # on a bracket off the pillar
    add("help_point_2", (8.0, wf, 0, N), help_point())
    add("information_board_2", (15.0, wf + 0.03, 1.55, N), information_board())
    add("exit_sign_2", ((b0 + b1) / 2, wf + 0.03, 2.8, N), exit_sign())  # way out, over the gate line
    add("fire_extinguisher_3", (18.9, wf + 0.1, 0, N), fire_extinguisher())
    add("litter_bin_8", (4.8, wf + 0.3, 0, N), litter_bin())
    add("litter_bin_9", (16.2, wf + 0.3, 0, N), litter_bin())
    add("recycling_bin_2", (16.3, 12.2, 0, N), recycling_bin())
    add("luggage_trolley_1", (17.5, 11.9, 0, E), luggage_trolley())
    add("luggage_trolley_2", (17.5, 12.55, 0, E), luggage_trolley())
    add("cycle_rack_1", (20.0, 12.0, 0, N), cycle_rack(2))
    add("cycle_rack_2", (22.9, 12.0, 0, N), cycle_rack(3))
    add("planter_1", (0.6, wf + 0.3, 0, N), planter())
    add("planter_2", (23.4, wf + 0.3, 0, N), planter())
    add("planter_3", (6.5, 12.2, 0, N), planter())


def main():
    out = [base.model("walls", (0, 0, 0, 0), walls()),
           base.model("floor", (0, 0, 0, 0), floor()),
           base.model("ceiling", (0, 0, 0, 0), ceiling())]
    ticket_office(out)
    staff_office(out)
    concourse(out)
    kiosk(out)
    toilets(out)
    left_luggage(out)
    waiting_room(out)
    platform(out)
    warm, cool, day = "0.85 0.8 0.7", "0.8 0.8 0.78", "0.8 0.82 0.85"
    lights = [base.point_light(name, x, y, z, rgb)
              for name, x, y, z, rgb in (
                  ("light_concourse_sw", 8.5, 2.5, H - 0.3, cool), ("light_concourse_se", 13.5, 2.5, H - 0.3, cool),
                  ("light_concourse_nw", 8.5, 7.5, H - 0.3, cool), ("light_concourse_ne", 13.5, 7.5, H - 0.3, cool),
                  ("light_ticket_office", 3.0, 2.7, H - 0.3, warm), ("light_staff_office", 3.0, 8.0, H - 0.3, warm),
                  ("light_gents", 18.0, 2.3, H - 0.3, cool), ("light_ladies", 22.0, 2.3, H - 0.3, cool),
                  ("light_corridor", 20.0, 5.25, H - 0.3, cool), ("light_left_luggage", 17.7, 8.3, H - 0.3, cool),
                  ("light_waiting_room", 21.8, 8.3, H - 0.3, warm),
                  ("light_platform_w", 5.0, 12.0, 3.3, day), ("light_platform_m", 11.5, 12.0, 3.3, day),
                  ("light_platform_e", 18.5, 12.0, 3.3, day))]
    print(base.world_sdf("semsplat_station", """The semsplat station: a small railway station of 24 m x 14 m on one floor (the concourse with
     the entrance, ticket machines, a cash machine, benches, the departure boards, the ticket
     barriers onto the platform and the newsagent and coffee kiosk; the ticket office behind its two
     ticket windows and the staff office in the west; the gents, the ladies, left luggage and the
     waiting room off a corridor in the east; the platform along the north side under a canopy on
     pillars, with benches, a shelter, luggage trolleys and cycle racks) for measuring on a world
     nobody tuned on. Generated by station_models/make_station.py; all models are inline.""", lights, out))


if __name__ == "__main__":
    main()
