#!/usr/bin/env python3
"""Writes data/worlds/airport.world: the terminal of a small regional airport, 32 m x 20 m on one
floor, for measuring the semantic stack on a world nobody tuned on. x runs west to east, y south
to north; the road and the car park are south of the building (landside), the apron with the
aircraft north and east of it (airside). Ceiling 3.4 m.

Landside (y < 10):
- The check-in hall (x 0..20): the main entrance (two door leaves swung open) in the middle of
  the south wall with windows either side, a cash machine in the south-west corner, a bench and a
  row of luggage trolleys along the south wall west of the entrance, a second bench and a bin
  east of it; a freestanding flight information display facing the entrance; the information
  desk with its "i" sign in the south-east; the self-service check-in kiosks (four) along the west
  wall with a bin and a fire extinguisher beyond them; four check-in desks along the north wall,
  each with its baggage scale beside it, the one baggage conveyor belt behind them running along
  the wall into a curtained hatch; the queue line of stanchions with belts (a two-lane
  serpentine) in front of the desks; the car hire desk against the east wall; the way into the
  security checkpoint is a wide opening in the north wall west of the desks.
- The first aid room (x 16.5..20, y 7..10), in the north-east corner of the hall, its door in
  its south wall: a treatment couch, a medical cabinet, a bin.
- The arrivals baggage reclaim hall (x 20..32), entered from the apron through a door in the east
  wall and left through a wide opening into the check-in hall: the baggage carousel with a few
  suitcases on it and its feed belt coming out of a hatch in the east wall, the lost luggage desk
  in the south-east corner, three luggage trolleys along the north wall, a bench under the south
  windows, a bin, a fire extinguisher.
Airside (y > 10):
- The security checkpoint (x 0..8): one lane along the west wall, south to north: the in-feed
  roller conveyor, the X-ray scanner, the out-feed roller conveyor where bags are collected; two
  divesting tables with stacks of grey trays beside the in-feed; the walk-through metal detector
  and the body scanner side by side in the middle of the room; a bin and a fire extinguisher; the
  way into the departure lounge is a wide opening in the east wall's north end.
- The departure lounge (x 8..24): the duty-free / newsagent shop in the south-west (shop shelves
  on the walls and a freestanding double-sided one, the till); four blocks of airport seating (two
  rows back to back each, two more rows facing the apron windows) with charging points between the
  rows; the cafe in the south-east (the cafe counter with the coffee machine on it, a display
  fridge, three small tables with two chairs each); departure screens on the west and east walls;
  a water fountain by the toilets; bins; a fire extinguisher; big windows onto the apron along
  the north wall.
- The boarding gate (the lounge's north-east, x 19..24, y 17..20): the gate desk, the boarding
  pass reader, the gate door (a shut glazed double door) to the apron with a departure screen
  over it.
- Along the east (x 24..32), each entered by a door from the lounge: the staff room (three
  lockers, a table with four chairs, a microwave on a wall shelf, a fire extinguisher, a bin),
  the men's toilets (two toilets in cubicles, three urinals, two sinks with mirrors, a hand dryer,
  a bin), the women's toilets (two toilets in cubicles, two sinks with mirrors, a hand dryer, a
  baby changing table, a bin).

Every model is inline (boxes, cylinders, spheres), so the world needs no model path. Model names
are what a world author would type; the class is the name less its _<number> ("check_in_desk_3"
-> "check in desk", "x_ray_scanner" -> "x ray scanner"). The primitives and the SDF writing are
the office generator's.
Run: python3 data/worlds/airport_models/make_airport.py > data/worlds/airport.world"""

import os
import sys

sys.dont_write_bytecode = True  # leave no __pycache__ in the repo
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "office_models"))
import make_office as base  # noqa: E402  (primitives, lights, the SDF document, door, window, locker)

W, D, H = 32.0, 20.0, 3.4  # floor width (x), depth (y), wall height
T = 0.1                    # wall thickness
YA = 10.0                  # landside (south) | airside (north)
XC = 20.0                  # landside: check-in hall | baggage reclaim
XS = 8.0                   # airside: security checkpoint | departure lounge
XE = 24.0                  # airside: departure lounge | staff room and toilets
YST, YMW = 13.4, 16.7      # east strip: staff room | men's | women's
XF, YF = 16.5, 7.0         # the first aid room: x > XF, y > YF, in the check-in hall's corner
LINTEL = 2.2               # the top of the inner doorways

MAIN_DOOR = (8.5, 10.5)        # x, south wall (two leaves, open)
ARRIVALS_DOOR = (7.8, 9.6)     # y, east wall of the reclaim hall (shut)
GATE_DOOR = (20.8, 22.6)       # x, north wall (shut glazed double door)
SECURITY_IN = (4.0, 6.0)       # x, wall y = YA (an opening)
SECURITY_OUT = (17.0, 19.0)    # y, wall x = XS (an opening)
ARRIVALS_EXIT = (1.2, 3.2)     # y, wall x = XC (an opening)
FIRST_AID_DOOR = (17.0, 18.0)  # x, wall y = YF
STAFF_DOOR = (11.9, 12.9)      # y, wall x = XE
MENS_DOOR = (14.0, 15.0)       # y, wall x = XE
WOMENS_DOOR = (18.6, 19.6)     # y, wall x = XE

N, S, E, WEST = 0.0, 3.1416, -1.5708, 1.5708  # yaw that turns a model's front (+y) north/south/east/west

base.COL.update({
    "terrazzo": "0.78 0.76 0.72", "carpet_blue": "0.25 0.3 0.42", "white_tile": "0.9 0.91 0.91",
    "vinyl": "0.7 0.74 0.7", "plaster": "0.9 0.9 0.88", "partition": "0.84 0.85 0.86",
    "cubicle": "0.55 0.6 0.68", "steel": "0.78 0.79 0.8", "dark_steel": "0.42 0.43 0.45",
    "chrome": "0.85 0.86 0.88", "rubber": "0.1 0.1 0.1", "belt_rubber": "0.12 0.12 0.13",
    "desk_laminate": "0.86 0.84 0.8", "desk_front": "0.18 0.3 0.55", "airline_blue": "0.1 0.25 0.6",
    "screen": "0.05 0.06 0.08", "screen_lit": "0.2 0.35 0.55", "fids_blue": "0.05 0.1 0.3",
    "fids_text": "0.95 0.85 0.2", "fids_white": "0.9 0.9 0.9", "kiosk_white": "0.93 0.93 0.92",
    "kiosk_accent": "0.0 0.55 0.6", "queue_belt": "0.15 0.2 0.5", "post_chrome": "0.8 0.81 0.83",
    "trolley_grey": "0.55 0.57 0.6", "handle_red": "0.75 0.12 0.1", "info_yellow": "0.95 0.75 0.1",
    "info_wood": "0.6 0.45 0.3", "bench_steel": "0.6 0.62 0.65", "atm_grey": "0.4 0.42 0.45",
    "atm_green": "0.1 0.5 0.3", "hire_orange": "0.9 0.45 0.1", "scanner_white": "0.9 0.9 0.88",
    "scanner_blue": "0.2 0.4 0.7", "lead_curtain": "0.2 0.2 0.22", "tray_grey": "0.5 0.52 0.55",
    "roller": "0.7 0.72 0.74", "detector_grey": "0.72 0.73 0.75", "signal_green": "0.1 0.8 0.3",
    "signal_red": "0.85 0.1 0.1", "foot_yellow": "0.95 0.8 0.1", "acrylic_glass": "0.7 0.8 0.85",
    "seat_black": "0.12 0.12 0.14", "seat_fabric_blue": "0.15 0.25 0.5", "socket_white": "0.95 0.95 0.95",
    "cafe_wood": "0.45 0.3 0.18", "counter_top": "0.2 0.2 0.2", "espresso_red": "0.7 0.1 0.1",
    "cup_white": "0.96 0.96 0.95", "fridge_glass": "0.6 0.75 0.8", "drink_red": "0.8 0.1 0.1",
    "drink_green": "0.1 0.6 0.2", "drink_orange": "0.95 0.55 0.1", "drink_blue": "0.15 0.35 0.75",
    "sandwich": "0.85 0.75 0.5", "table_white": "0.92 0.92 0.9", "chair_red": "0.7 0.15 0.12",
    "shelf_white": "0.94 0.94 0.93", "perfume_box": "0.8 0.7 0.85", "spirit_amber": "0.65 0.38 0.1",
    "chocolate": "0.4 0.22 0.12", "magazine_a": "0.85 0.2 0.3", "magazine_b": "0.2 0.5 0.8",
    "magazine_c": "0.95 0.9 0.3", "candy_pink": "0.95 0.5 0.7", "till_black": "0.1 0.1 0.1",
    "fountain_steel": "0.75 0.76 0.78", "bin_silver": "0.7 0.7 0.72", "recycle_green": "0.1 0.55 0.25",
    "gate_blue": "0.12 0.22 0.45", "door_glass": "0.6 0.75 0.82", "door_frame": "0.35 0.37 0.4",
    "carousel_plate": "0.5 0.52 0.55", "carousel_base": "0.3 0.31 0.33", "case_red": "0.75 0.1 0.12",
    "case_black": "0.1 0.1 0.12", "case_blue": "0.15 0.3 0.65", "case_green": "0.2 0.45 0.25",
    "lost_purple": "0.45 0.2 0.5", "porcelain": "0.97 0.97 0.97", "mirror": "0.8 0.85 0.88",
    "changing_grey": "0.8 0.8 0.82", "changing_pad": "0.4 0.7 0.8", "microwave_white": "0.92 0.92 0.9",
    "couch_blue": "0.2 0.4 0.6", "couch_paper": "0.97 0.97 0.95", "cabinet_white": "0.93 0.94 0.94",
    "cross_green": "0.1 0.6 0.3", "extinguisher_red": "0.8 0.08 0.06", "paper": "0.96 0.96 0.94",
    "locker_grey": "0.55 0.6 0.66", "chair_grey": "0.5 0.5 0.52", "table_oak": "0.7 0.55 0.35",
    "apron_glass": "0.55 0.72 0.85", "window_frame": "0.3 0.32 0.35",
})
box, cyl, sph, legs = base.box, base.cyl, base.sph, base.legs
turned, along_x, along_y = base.turned, base.along_x, base.along_y


# ---- the check-in hall (local frames: x right, y forward = the side a person uses, z up) ----
def check_in_desk(w=1.4, d=0.7):
    """An airline check-in desk: a closed blue front toward the passenger (+y) with a high ledge,
    the agent's lower worktop behind (-y) with a monitor, a keyboard and a bag-tag printer, and a
    small screen on a post at the back corner showing the airline and the flight."""
    return [box("body", "desk_front", 0, 0.05, 0.5, w, d - 0.1, 1.0),
            box("ledge", "desk_laminate", 0, d / 2 - 0.12, 1.04, w, 0.26, 0.04),
            box("worktop", "desk_laminate", 0, -d / 2 + 0.18, 0.76, w, 0.36, 0.03),
            box("kick", "dark_steel", 0, d / 2 - 0.05, 0.05, w, 0.02, 0.1),
            box("monitor", "screen", -0.2, -0.12, 0.98, 0.45, 0.04, 0.3),
            box("monitor_lit", "screen_lit", -0.2, -0.142, 0.98, 0.42, 0.004, 0.27),
            box("keyboard", "rubber", -0.2, -0.28, 0.785, 0.42, 0.14, 0.02),
            box("tag_printer", "kiosk_white", 0.4, -0.2, 0.86, 0.25, 0.3, 0.18),
            cyl("post", "post_chrome", w / 2 - 0.25, -d / 2 + 0.08, 1.55, 0.03, 1.5),
            box("flight_screen", "screen", w / 2 - 0.25, -d / 2 + 0.08, 2.45, 0.5, 0.05, 0.3),
            box("flight_screen_lit", "airline_blue", w / 2 - 0.25, -d / 2 + 0.107, 2.45, 0.46, 0.004, 0.26),
            box("logo", "fids_white", w / 2 - 0.25, -d / 2 + 0.11, 2.5, 0.26, 0.002, 0.07)]


def baggage_scale():
    """The bag drop beside a check-in desk: the low weighing belt where the passenger puts the bag
    (toward +y), the dispatch belt behind it (-y) that carries the bag back to the conveyor, side
    guards, and the weight display on a post facing the passenger."""
    v = [box("weigh_base", "dark_steel", 0, 0.45, 0.13, 0.65, 0.8, 0.26),
         box("weigh_belt", "belt_rubber", 0, 0.45, 0.27, 0.6, 0.78, 0.02),
         box("dispatch_frame", "dark_steel", 0, -0.64, 0.21, 0.65, 1.3, 0.42),
         box("dispatch_belt", "belt_rubber", 0, -0.64, 0.43, 0.58, 1.28, 0.02)]
    for i, s in enumerate((-1, 1)):
        v += [box(f"guard{i}", "steel", s * 0.33, -0.22, 0.55, 0.02, 2.14, 0.22)]
    return v + [cyl("display_post", "steel", 0.27, 0.8, 0.55, 0.02, 0.55),
                turned(box("display", "screen", 0.27, 0.8, 0.86, 0.16, 0.04, 0.1), "-0.3 0 0"),
                turned(box("reading", "signal_red", 0.27, 0.822, 0.865, 0.1, 0.004, 0.04), "-0.3 0 0")]


def conveyor_belt(length):
    """The baggage takeaway conveyor along the wall behind the check-in desks (the wall behind at
    -y): a steel frame on legs with the black belt on top and a guard rail on the wall side; at its
    -x end the belt runs into the wall through a hatch hung with rubber curtain strips."""
    v = [box("frame", "dark_steel", 0, 0, 0.36, length, 0.6, 0.12),
         box("belt", "belt_rubber", 0, 0, 0.43, length - 0.04, 0.56, 0.02),
         box("rail", "steel", 0, -0.31, 0.55, length, 0.03, 0.2),
         box("end_stop", "steel", length / 2 - 0.01, 0, 0.55, 0.03, 0.6, 0.2),
         box("hatch_frame", "dark_steel", -length / 2 + 0.35, -0.31, 0.85, 0.8, 0.04, 0.9),
         box("hatch_hood", "steel", -length / 2 + 0.35, -0.12, 1.32, 0.8, 0.4, 0.06)]
    v += [box(f"curtain{i}", "rubber", -length / 2 + 0.05 + 0.1 * i, -0.29, 0.85, 0.08, 0.005, 0.8)
          for i in range(7)]
    n = int(length / 1.2) + 1
    v += [box(f"leg{i}", "dark_steel", -length / 2 + 0.1 + i * (length - 0.2) / (n - 1), 0, 0.15, 0.05, 0.5, 0.3)
          for i in range(n)]
    return v


def check_in_kiosk():
    """A self-service check-in kiosk: a white pedestal, the tilted touch screen toward the user
    (+y), the passport reader and the boarding-pass printer slot under it, a teal header panel."""
    return [box("plinth", "dark_steel", 0, 0, 0.03, 0.5, 0.45, 0.06),
            box("body", "kiosk_white", 0, -0.02, 0.6, 0.5, 0.4, 1.1),
            turned(box("screen_bezel", "screen", 0, 0.1, 1.25, 0.46, 0.05, 0.36), "-0.45 0 0"),
            turned(box("screen_lit", "screen_lit", 0, 0.127, 1.255, 0.42, 0.004, 0.32), "-0.45 0 0"),
            box("passport_reader", "rubber", -0.12, 0.2, 1.02, 0.16, 0.06, 0.04),
            box("printer_slot", "rubber", 0.12, 0.182, 0.95, 0.14, 0.004, 0.02),
            box("header", "kiosk_accent", 0, -0.15, 1.6, 0.5, 0.1, 0.22),
            box("header_text", "fids_white", 0, -0.099, 1.6, 0.34, 0.002, 0.06)]


def stanchion(belt=0.0):
    """A queue stanchion: a weighted round base, a chrome post, and its retractable blue belt
    pulled out along +x to the next post (belt = the distance to it; 0 = none)."""
    v = [cyl("base", "post_chrome", 0, 0, 0.015, 0.17, 0.03),
         cyl("post", "post_chrome", 0, 0, 0.5, 0.03, 0.96),
         cyl("head", "post_chrome", 0, 0, 0.96, 0.035, 0.06)]
    if belt > 0:
        v.append(box("belt", "queue_belt", (belt - 0.14) / 2, 0, 0.92, belt - 0.21, 0.004, 0.05))  # clipped to the next post
    return v


def luggage_trolley():
    """An airport luggage trolley: the low base frame on four wheels, the back frame rising at the
    handle end (-y) with the red brake handle, a small basket on top, the front bag lip (+y)."""
    v = [box("base", "trolley_grey", 0, 0.05, 0.2, 0.56, 0.85, 0.03),
         box("lip", "trolley_grey", 0, 0.48, 0.26, 0.56, 0.03, 0.12),
         box("post_l", "trolley_grey", -0.25, -0.38, 0.6, 0.03, 0.03, 0.8),
         box("post_r", "trolley_grey", 0.25, -0.38, 0.6, 0.03, 0.03, 0.8),
         box("back_rail", "trolley_grey", 0, -0.36, 0.62, 0.5, 0.02, 0.02),
         box("basket", "trolley_grey", 0, -0.28, 0.82, 0.5, 0.18, 0.02),
         along_x(cyl("handle", "handle_red", 0, -0.44, 1.0, 0.02, 0.56))]
    v += [along_x(cyl(f"wheel{i}", "rubber", sx * 0.24, sy, 0.08, 0.08, 0.04))
          for i, (sx, sy) in enumerate(((-1, 0.4), (1, 0.4), (-1, -0.3), (1, -0.3)))]
    return v


def flight_information_display():
    """A freestanding flight information display: a grey plinth, two steel legs, two big screens
    side by side in one housing facing +y, each listing departures in yellow rows on dark blue."""
    v = [box("plinth", "dark_steel", 0, 0, 0.05, 1.2, 0.4, 0.1),
         box("leg_l", "steel", -0.5, 0, 0.85, 0.1, 0.1, 1.5),
         box("leg_r", "steel", 0.5, 0, 0.85, 0.1, 0.1, 1.5),
         box("housing", "dark_steel", 0, 0, 2.0, 2.0, 0.12, 0.66)]
    for k, x in enumerate((-0.49, 0.49)):
        v.append(box(f"screen{k}", "fids_blue", x, 0.062, 2.0, 0.94, 0.004, 0.58))
        v.append(box(f"title{k}", "fids_white", x - 0.2, 0.065, 2.24, 0.4, 0.002, 0.05))
        v += [box(f"row{k}_{i}", "fids_text", x, 0.065, 2.14 - 0.075 * i, 0.84, 0.002, 0.035) for i in range(5)]
    return v


def information_desk():
    """The information desk: a curved counter (a straight front and two angled wings) with a
    wooden top toward the visitors (+y), the staff side behind (-y) with a monitor, and a tall
    post carrying the yellow "i" sign."""
    v = [box("front", "info_wood", 0, 0.1, 0.5, 1.4, 0.5, 1.0),
         box("top", "counter_top", 0, 0.12, 1.02, 1.5, 0.6, 0.04),
         turned(box("wing_l", "info_wood", -0.95, -0.05, 0.5, 0.6, 0.5, 1.0), "0 0 -0.5"),
         turned(box("wing_r", "info_wood", 0.95, -0.05, 0.5, 0.6, 0.5, 1.0), "0 0 0.5"),
         box("worktop", "desk_laminate", 0, -0.3, 0.75, 1.3, 0.3, 0.03),
         box("monitor", "screen", 0.3, -0.25, 0.95, 0.42, 0.04, 0.28),
         box("leaflets", "magazine_b", -0.4, 0.2, 1.06, 0.3, 0.2, 0.04),
         cyl("sign_post", "steel", -0.6, -0.3, 1.2, 0.03, 2.4),
         box("sign", "info_yellow", -0.6, -0.3, 2.5, 0.5, 0.06, 0.5),
         box("sign_i", "fids_white", -0.6, -0.268, 2.5, 0.08, 0.004, 0.3)]
    return v


def bench(length=2.0):
    """A public bench of perforated steel on two cast legs, a seat and a back (at -y), armrests at
    both ends."""
    v = [box("seat", "bench_steel", 0, 0.02, 0.44, length, 0.42, 0.04),
         box("back", "bench_steel", 0, -0.2, 0.7, length, 0.04, 0.4),
         box("arm_l", "dark_steel", -length / 2 + 0.02, 0, 0.62, 0.05, 0.42, 0.04),
         box("arm_r", "dark_steel", length / 2 - 0.02, 0, 0.62, 0.05, 0.42, 0.04)]
    for i, x in enumerate((-length / 2 + 0.15, length / 2 - 0.15)):
        v += [box(f"leg{i}", "dark_steel", x, 0, 0.21, 0.06, 0.42, 0.42),
              box(f"arm_post{i}", "dark_steel", -length / 2 + 0.02 if i == 0 else length / 2 - 0.02, 0.15,
                  0.53, 0.04, 0.04, 0.18)]
    return v


def cash_machine():
    """A freestanding cash machine (ATM): the grey cabinet against the wall (behind at -y), the
    green lit header, the recessed screen, the keypad, the card slot and the cash dispenser toward
    the user (+y), a small canopy over the screen."""
    return [box("cabinet", "atm_grey", 0, 0, 0.85, 0.75, 0.7, 1.7),
            box("header", "atm_green", 0, 0.2, 1.8, 0.75, 0.3, 0.2),
            box("header_text", "fids_white", 0, 0.352, 1.8, 0.4, 0.002, 0.07),
            box("canopy", "atm_grey", 0, 0.38, 1.62, 0.7, 0.1, 0.04),
            box("screen", "screen_lit", 0, 0.352, 1.38, 0.3, 0.004, 0.22),
            turned(box("keypad", "steel", -0.05, 0.42, 1.08, 0.22, 0.16, 0.03), "0.35 0 0"),
            box("card_slot", "signal_green", 0.2, 0.352, 1.2, 0.08, 0.004, 0.02),
            box("cash_slot", "rubber", 0, 0.352, 0.95, 0.3, 0.004, 0.04),
            box("receipt_slot", "rubber", 0.2, 0.352, 1.12, 0.08, 0.004, 0.01)]


def car_hire_desk(w=1.8, wall=0.93):
    """The car hire desk: a counter with an orange front band toward the customers (+y), a monitor
    and a key box behind it, and the hire company's sign board on the wall behind (wall = its
    distance behind the desk)."""
    return [box("body", "kiosk_white", 0, 0, 0.52, w, 0.6, 1.04),
            box("band", "hire_orange", 0, 0.302, 0.8, w, 0.004, 0.18),
            box("top", "counter_top", 0, 0.03, 1.06, w + 0.04, 0.68, 0.04),
            box("monitor", "screen", 0.4, -0.15, 1.28, 0.45, 0.04, 0.3),
            box("card_terminal", "rubber", -0.3, 0.2, 1.1, 0.08, 0.14, 0.04),
            box("sign", "hire_orange", 0, -wall, 2.3, 1.6, 0.04, 0.5),
            box("sign_text", "fids_white", 0, -wall + 0.022, 2.3, 1.1, 0.002, 0.14),
            box("key_box", "steel", -0.5, -wall + 0.04, 1.5, 0.4, 0.08, 0.5)]


# ---- the security checkpoint ----
def x_ray_scanner(length=2.8):
    """A cabinet X-ray baggage scanner, its tunnel along the model's y: the white housing, the
    lead curtains at both tunnel mouths, the belt running through at table height, the blue
    emergency stop panel, and the operator's monitor on an arm at its east side (+x)."""
    v = [box("housing", "scanner_white", 0, 0, 0.95, 1.0, length - 0.2, 1.3),
         box("base", "dark_steel", 0, 0, 0.15, 1.0, length - 0.2, 0.3),
         box("stripe", "scanner_blue", 0.501, 0, 1.3, 0.004, length - 0.2, 0.12),
         box("stripe_w", "scanner_blue", -0.501, 0, 1.3, 0.004, length - 0.2, 0.12),
         box("belt", "belt_rubber", 0, 0, 0.75, 0.66, length, 0.03),
         box("stop_button", "signal_red", 0.503, length / 2 - 0.3, 0.9, 0.004, 0.06, 0.06)]
    for k, s in enumerate((-1, 1)):
        v += [box(f"mouth{k}", "lead_curtain", 0, s * (length / 2 - 0.1 - 0.005), 1.0, 0.7, 0.01, 0.5),
              box(f"hood{k}", "scanner_white", 0, s * (length / 2 - 0.05), 1.4, 1.0, 0.1, 0.4)]
    return v + [box("monitor_arm", "dark_steel", 0.6, 0.3, 1.3, 0.2, 0.05, 0.05),
                box("monitor", "screen", 0.72, 0.3, 1.45, 0.04, 0.45, 0.32),
                box("monitor_lit", "screen_lit", 0.743, 0.3, 1.45, 0.004, 0.42, 0.28)]


def roller_conveyor(length, trays=0):
    """A gravity roller conveyor along the model's y at table height: two side rails, steel rollers
    every 10 cm, legs, and a few grey security trays on it."""
    v = [box("rail_l", "dark_steel", -0.36, 0, 0.74, 0.04, length, 0.08),
         box("rail_r", "dark_steel", 0.36, 0, 0.74, 0.04, length, 0.08)]
    v += [along_x(cyl(f"roller{i}", "roller", 0, -length / 2 + 0.05 + 0.1 * i, 0.76, 0.025, 0.68))
          for i in range(int(length / 0.1))]
    v += legs("dark_steel", 0.34, length / 2 - 0.08, 0.7, 0.05)
    for i in range(trays):
        y = -length / 2 + 0.4 + 0.7 * i
        v += [box(f"tray{i}", "tray_grey", 0, y, 0.82, 0.52, 0.62, 0.08),
              box(f"tray_in{i}", "dark_steel", 0, y, 0.862, 0.46, 0.56, 0.004)]
    return v


def divesting_table(length=1.2):
    """A divesting table: a steel table along the model's y where passengers put their belongings
    into trays (a lip on its far side, -x), with a stack of grey trays at one end and a tray laid
    out at the other."""
    v = [box("top", "steel", 0, 0, 0.76, 0.6, length, 0.03),
         box("lip", "steel", -0.29, 0, 0.8, 0.02, length, 0.06),
         box("shelf", "steel", 0, 0, 0.2, 0.56, length - 0.06, 0.02)] + legs("dark_steel", 0.27, length / 2 - 0.03, 0.75)
    v += [box(f"stack{i}", "tray_grey", 0, length / 2 - 0.34, 0.815 + 0.04 * i, 0.5, 0.6, 0.035) for i in range(6)]
    v += [box("tray_out", "tray_grey", 0, -length / 2 + 0.33, 0.815, 0.5, 0.6, 0.07),
          box("tray_out_in", "dark_steel", 0, -length / 2 + 0.33, 0.852, 0.44, 0.54, 0.004)]
    return v


def metal_detector():
    """A walk-through metal detector arch, walked through along y: two grey side panels with light
    columns, the header with a green/red signal and a small counter display."""
    v = []
    for k, s in enumerate((-1, 1)):
        v += [box(f"panel{k}", "detector_grey", s * 0.45, 0, 1.05, 0.12, 0.6, 2.1),
              box(f"lights{k}", "signal_green", s * 0.389, 0, 1.05, 0.002, 0.1, 1.6),
              box(f"foot{k}", "dark_steel", s * 0.45, 0, 0.02, 0.16, 0.66, 0.04)]
    return v + [box("header", "detector_grey", 0, 0, 2.22, 1.02, 0.6, 0.24),
                box("signal_go", "signal_green", -0.15, 0.302, 2.22, 0.1, 0.004, 0.1),
                box("signal_stop", "signal_red", 0.15, 0.302, 2.22, 0.1, 0.004, 0.1),
                box("counter", "screen_lit", 0, 0.302, 2.22, 0.12, 0.004, 0.06)]


def body_scanner():
    """A millimetre-wave body scanner, walked into along y: the round floor platform with the
    yellow footprints, two tall curved housings either side, the roof, the operator's screen."""
    v = [cyl("platform", "dark_steel", 0, 0, 0.03, 0.6, 0.06),
         box("foot_l", "foot_yellow", -0.12, 0, 0.062, 0.12, 0.28, 0.002),
         box("foot_r", "foot_yellow", 0.12, 0, 0.062, 0.12, 0.28, 0.002)]
    for k, s in enumerate((-1, 1)):
        v += [box(f"housing{k}", "scanner_white", s * 0.65, 0, 1.1, 0.3, 1.1, 2.2),
              box(f"window{k}", "acrylic_glass", s * 0.499, 0, 1.1, 0.004, 0.9, 1.8),
              box(f"stripe{k}", "scanner_blue", s * 0.801, 0, 1.9, 0.004, 1.1, 0.1)]
    return v + [box("roof", "scanner_white", 0, 0, 2.25, 1.6, 1.1, 0.1),
                cyl("screen_post", "steel", 0.9, 0.45, 0.6, 0.02, 1.2),
                turned(box("screen", "screen_lit", 0.9, 0.45, 1.3, 0.04, 0.3, 0.22), "0 0 0.6")]


# ---- the departure lounge ----
def airport_seating(n=4):
    """A row of airport beam seating: n black moulded seats with fabric pads on one steel beam,
    armrests between them, two T legs; the backs at -y."""
    length = 0.6 * n + 0.1
    v = [box("beam", "dark_steel", 0, -0.05, 0.3, length, 0.08, 0.08)]
    v += [box(f"leg{i}", "dark_steel", s * (length / 2 - 0.3), -0.05, 0.15, 0.08, 0.55, 0.3)
          for i, s in enumerate((-1, 1))]
    for i in range(n):
        x = -length / 2 + 0.35 + 0.6 * i
        v += [box(f"seat{i}", "seat_black", x, 0.02, 0.44, 0.52, 0.5, 0.05),
              box(f"pad{i}", "seat_fabric_blue", x, 0.04, 0.475, 0.46, 0.42, 0.02),
              turned(box(f"back{i}", "seat_black", x, -0.25, 0.75, 0.52, 0.05, 0.55), "-0.15 0 0")]
    v += [box(f"arm{i}", "chrome", -length / 2 + 0.05 + 0.6 * i, 0.02, 0.64, 0.05, 0.45, 0.04) for i in range(n + 1)]
    return v


def charging_point():
    """A phone charging point: a slim white pillar with mains sockets and USB ports on all four
    faces, a small ledge for a phone, and a blue lit lightning sign on top."""
    v = [box("pillar", "socket_white", 0, 0, 0.6, 0.3, 0.3, 1.2),
         box("ledge", "dark_steel", 0, 0, 0.9, 0.4, 0.4, 0.02),
         box("cap", "airline_blue", 0, 0, 1.25, 0.3, 0.3, 0.1),
         box("sign", "fids_white", 0, 0.152, 1.25, 0.08, 0.002, 0.08)]
    for k, (dx, dy, sx, sy) in enumerate(((0, 0.151, 0.16, 0.002), (0, -0.151, 0.16, 0.002),
                                          (0.151, 0, 0.002, 0.16), (-0.151, 0, 0.002, 0.16))):
        v += [box(f"sockets{k}", "rubber", dx, dy, 1.05, sx, sy, 0.1),
              box(f"usb{k}", "dark_steel", dx, dy, 0.75, sx, sy, 0.05)]
    return v


def cafe_counter(length=3.0, d=0.7):
    """The cafe counter: a wooden front toward the customers (+y), a dark top, a glass pastry case
    at the west end with sandwiches, a card reader, cups stacked at the east end; the barista's
    side behind (-y)."""
    v = [box("body", "cafe_wood", 0, 0, 0.52, length, d, 1.04),
         box("top", "counter_top", 0, 0.02, 1.05, length + 0.04, d + 0.06, 0.03),
         box("case", "fridge_glass", -length / 2 + 0.5, 0.05, 1.28, 0.8, 0.5, 0.42),
         box("case_shelf", "steel", -length / 2 + 0.5, 0.05, 1.25, 0.76, 0.46, 0.01),
         box("card_reader", "rubber", -0.35, 0.3, 1.09, 0.08, 0.14, 0.05)]
    v += [box(f"sandwich{i}", "sandwich", -length / 2 + 0.2 + 0.15 * i, 0.05, 1.1, 0.12, 0.18, 0.06) for i in range(5)]
    v += [cyl(f"cups{i}", "cup_white", length / 2 - 0.2 - 0.12 * i, 0.1, 1.16, 0.045, 0.18) for i in range(3)]
    return v


def coffee_machine():
    """A two-group espresso machine standing on a counter, facing the barista (+y): the red body,
    the steel top with cups warming on it, two group heads with portafilters, a steam wand, the
    drip tray."""
    v = [box("body", "espresso_red", 0, 0, 0.24, 0.75, 0.5, 0.42),
         box("top", "steel", 0, 0, 0.46, 0.75, 0.5, 0.03),
         box("drip_tray", "steel", 0, 0.3, 0.03, 0.6, 0.12, 0.03),
         along_y(cyl("steam_wand", "chrome", 0.32, 0.3, 0.22, 0.01, 0.15))]
    for k, x in enumerate((-0.16, 0.16)):
        v += [cyl(f"group{k}", "chrome", x, 0.28, 0.32, 0.045, 0.06),
              along_y(cyl(f"portafilter{k}", "rubber", x, 0.38, 0.27, 0.012, 0.16))]
    return v + [cyl(f"cup{i}", "cup_white", -0.25 + 0.1 * i, 0, 0.515, 0.035, 0.07) for i in range(6)]


def display_fridge():
    """An upright drinks display fridge: a glass door toward the customer (+y), four shelves of
    bottles and sandwiches, the lit header panel."""
    v = [box("body", "steel", 0, 0, 1.0, 0.7, 0.68, 2.0),
         box("header", "airline_blue", 0, 0.34, 1.9, 0.7, 0.02, 0.18),
         box("door", "fridge_glass", 0, 0.345, 0.95, 0.62, 0.01, 1.6),
         box("handle", "chrome", 0.28, 0.37, 1.0, 0.02, 0.03, 0.4)]
    colours = ("drink_red", "drink_green", "drink_orange", "drink_blue")
    for i in range(4):
        z = 0.35 + 0.42 * i
        v.append(box(f"shelf{i}", "steel", 0, 0.05, z, 0.62, 0.5, 0.01))
        if i == 0:
            v += [box(f"sandwich{k}", "sandwich", -0.22 + 0.15 * k, 0.15, z + 0.05, 0.12, 0.16, 0.08) for k in range(4)]
        else:
            v += [cyl(f"bottle{i}_{k}", colours[(i + k) % 4], -0.25 + 0.1 * k, 0.2, z + 0.12, 0.03, 0.22) for k in range(6)]
    return v


def cafe_table(r=0.35):
    """A small round cafe table on a pedestal."""
    return [cyl("top", "table_white", 0, 0, 0.735, r, 0.03),
            cyl("pedestal", "steel", 0, 0, 0.37, 0.035, 0.7),
            cyl("foot", "dark_steel", 0, 0, 0.015, 0.24, 0.03)]


def staff_table(w=1.6, d=0.8):
    """A plain rectangular table on four legs."""
    return [box("top", "table_oak", 0, 0, 0.735, w, d, 0.03)] + legs("dark_steel", w / 2 - 0.05, d / 2 - 0.05, 0.72)


def chair():
    """A stacking chair: a red moulded seat and back (at -y) on a thin steel frame."""
    v = [box("seat", "chair_red", 0, 0, 0.45, 0.44, 0.42, 0.03),
         turned(box("back", "chair_red", 0, -0.2, 0.68, 0.42, 0.03, 0.36), "-0.12 0 0")]
    return v + legs("chrome", 0.19, 0.18, 0.44, 0.02) + [
        box("back_post_l", "chrome", -0.19, -0.19, 0.65, 0.02, 0.02, 0.42),
        box("back_post_r", "chrome", 0.19, -0.19, 0.65, 0.02, 0.02, 0.42)]


def shop_shelf(length=2.2, d=0.45, stock=0, double=False):
    """A shop shelving unit (a gondola when double-sided): a white back panel, four shelves toward
    +y (and -y when double) stocked with perfume boxes, bottles of spirits, chocolate or magazines."""
    v = [box("back", "shelf_white", 0, 0 if double else -d / 2 + 0.02, 0.85, length, 0.04, 1.7),
         box("plinth", "shelf_white", 0, 0, 0.06, length, d, 0.12),
         box("header", "airline_blue", 0, 0 if double else -d / 2 + 0.02, 1.78, length, 0.05, 0.16)]
    sides = (1, -1) if double else (1,)
    for side in sides:
        y0 = side * (0.03 + (d / 2 - 0.03) / 2) if double else 0.02
        depth = (d / 2 - 0.05) if double else d - 0.06
        for i, z in enumerate((0.45, 0.8, 1.15, 1.5)):
            v.append(box(f"shelf{side}_{i}", "shelf_white", 0, y0, z, length - 0.04, depth, 0.02))
            kind = (i + stock + (side < 0)) % 4
            n = int((length - 0.1) / 0.16)
            for k in range(n):
                x = -length / 2 + 0.13 + 0.16 * k
                if kind == 0:
                    v.append(box(f"perfume{side}_{i}_{k}", "perfume_box", x, y0, z + 0.09, 0.1, 0.08, 0.16))
                elif kind == 1:
                    v.append(cyl(f"spirit{side}_{i}_{k}", "spirit_amber", x, y0, z + 0.14, 0.04, 0.26))
                elif kind == 2:
                    v.append(box(f"chocolate{side}_{i}_{k}", "chocolate", x, y0, z + 0.05, 0.14, 0.12, 0.08))
                else:
                    c = ("magazine_a", "magazine_b", "magazine_c", "candy_pink")[k % 4]
                    v.append(turned(box(f"magazine{side}_{i}_{k}", c, x, y0 + side * 0.02, z + 0.14, 0.14, 0.02, 0.26),
                                    f"{-0.2 * side:g} 0 0"))
    return v


def till():
    """The shop's till: a checkout counter toward the customer (+y) with the till itself on it (the
    cash drawer, a touch screen facing the cashier at -y, a customer display), a card terminal, a
    scanner window, a rack of sweets on the customer side."""
    return [box("counter", "shelf_white", 0, 0, 0.48, 1.2, 0.6, 0.96),
            box("top", "counter_top", 0, 0, 0.975, 1.24, 0.64, 0.03),
            box("drawer", "till_black", 0.25, -0.05, 1.04, 0.4, 0.38, 0.1),
            turned(box("screen", "screen_lit", 0.25, -0.05, 1.2, 0.3, 0.02, 0.22), "0.3 0 0"),
            box("customer_display", "screen", 0.25, 0.15, 1.18, 0.16, 0.02, 0.07),
            box("card_terminal", "rubber", -0.1, 0.2, 1.02, 0.08, 0.15, 0.05),
            box("scanner", "acrylic_glass", -0.35, 0, 0.992, 0.3, 0.3, 0.004),
            box("sweet_rack", "candy_pink", 0, 0.33, 0.55, 0.9, 0.06, 0.7)]


def departure_screen():
    """A departures screen on a wall bracket (the wall behind at -y), centred on the model's
    height: yellow rows of flights on dark blue under a white title."""
    v = [box("bracket", "dark_steel", 0, -0.04, 0, 0.3, 0.05, 0.25),
         box("panel", "rubber", 0, 0, 0, 1.1, 0.06, 0.66),
         box("screen", "fids_blue", 0, 0.031, 0, 1.04, 0.004, 0.6),
         box("title", "fids_white", -0.25, 0.034, 0.24, 0.4, 0.002, 0.05)]
    return v + [box(f"row{i}", "fids_text", 0, 0.034, 0.14 - 0.07 * i, 0.94, 0.002, 0.035) for i in range(5)]


def water_fountain():
    """A wall-mounted drinking fountain with a bottle filler above it (the wall behind at -y): the
    steel basin with its bubbler, the push bar, the filler alcove and its sensor."""
    return [box("basin_body", "fountain_steel", 0, 0.16, 0.82, 0.46, 0.32, 0.22),
            box("basin", "dark_steel", 0, 0.18, 0.935, 0.36, 0.24, 0.01),
            cyl("bubbler", "chrome", 0.05, 0.2, 0.96, 0.015, 0.05),
            box("push_bar", "chrome", 0, 0.33, 0.86, 0.3, 0.02, 0.04),
            box("filler", "fountain_steel", 0, 0.06, 1.45, 0.42, 0.12, 0.8),
            box("alcove", "dark_steel", 0, 0.121, 1.4, 0.26, 0.002, 0.4),
            box("sensor", "signal_green", 0, 0.121, 1.7, 0.04, 0.002, 0.02)]


def bin_():
    """A stainless airport litter bin with two slots, one ringed green for recycling."""
    return [box("body", "bin_silver", 0, 0, 0.42, 0.5, 0.36, 0.84),
            box("lid", "dark_steel", 0, 0, 0.86, 0.52, 0.38, 0.04),
            box("slot_waste", "rubber", -0.12, 0.181, 0.7, 0.16, 0.004, 0.12),
            box("slot_recycle", "recycle_green", 0.12, 0.181, 0.7, 0.16, 0.004, 0.12)]


# ---- the boarding gate ----
def gate_desk():
    """The gate desk (podium) the gate agent works at: a blue front toward the passengers (+y), a
    worktop behind (-y) with a monitor and a boarding pass printer, the gate number on a screen."""
    return [box("body", "gate_blue", 0, 0.05, 0.52, 1.4, 0.5, 1.04),
            box("top", "desk_laminate", 0, 0, 1.06, 1.44, 0.64, 0.04),
            box("monitor", "screen", -0.25, -0.1, 1.27, 0.42, 0.04, 0.28),
            box("printer", "kiosk_white", 0.35, -0.1, 1.15, 0.26, 0.26, 0.14),
            cyl("post", "steel", 0.6, -0.2, 1.5, 0.03, 0.9),
            box("gate_screen", "screen", 0.6, -0.2, 2.15, 0.6, 0.05, 0.36),
            box("gate_screen_lit", "fids_blue", 0.6, -0.173, 2.15, 0.56, 0.004, 0.32),
            box("gate_number", "fids_text", 0.6, -0.17, 2.2, 0.2, 0.002, 0.14)]


def boarding_pass_reader():
    """A boarding pass reader on a pedestal, facing the passenger (+y): the slanted head with the
    glass scan window and the green and red lights, the small screen."""
    return [box("foot", "dark_steel", 0, 0, 0.02, 0.34, 0.34, 0.04),
            box("pedestal", "steel", 0, 0, 0.5, 0.2, 0.2, 0.96),
            turned(box("head", "kiosk_white", 0, 0.02, 1.05, 0.3, 0.3, 0.14), "-0.35 0 0"),
            turned(box("scan_window", "acrylic_glass", 0, 0.04, 1.126, 0.2, 0.18, 0.004), "-0.35 0 0"),
            box("light_go", "signal_green", -0.08, 0.17, 1.1, 0.05, 0.004, 0.03),
            box("light_stop", "signal_red", 0.08, 0.17, 1.1, 0.05, 0.004, 0.03),
            box("screen", "screen_lit", 0, 0.1, 1.3, 0.2, 0.02, 0.14)]


def gate_door(w=1.8, h=2.2):
    """A glazed double door to the apron, shut in its opening (the inside toward +y): a dark
    aluminium frame, two glass leaves with push bars and a green exit sign over it."""
    v = [box("frame_top", "door_frame", 0, 0, h - 0.04, w, 0.08, 0.08),
         box("frame_l", "door_frame", -w / 2 + 0.04, 0, h / 2, 0.08, 0.08, h),
         box("frame_r", "door_frame", w / 2 - 0.04, 0, h / 2, 0.08, 0.08, h),
         box("mullion", "door_frame", 0, 0, h / 2, 0.05, 0.08, h)]
    for k, s in enumerate((-1, 1)):
        v += [box(f"glass{k}", "door_glass", s * w / 4, 0, h / 2, w / 2 - 0.1, 0.02, h - 0.12),
              box(f"kick{k}", "door_frame", s * w / 4, 0, 0.12, w / 2 - 0.1, 0.04, 0.2),
              box(f"push_bar{k}", "chrome", s * w / 4, 0.06, 1.0, w / 2 - 0.2, 0.03, 0.04)]
    return v + [box("exit_sign", "recycle_green", 0, 0.08, h + 0.12, 0.4, 0.04, 0.15)]


def apron_window(w=2.2, h=1.9):
    """A big window onto the apron (the wall behind at -y), centred on the model's height: a dark
    frame, two panes, a mullion."""
    return [box("frame", "window_frame", 0, 0, 0, w + 0.06, 0.04, h + 0.06),
            box("pane", "apron_glass", 0, 0.022, 0, w - 0.04, 0.004, h - 0.04),
            box("mullion", "window_frame", 0, 0.025, 0, 0.05, 0.01, h)]


# ---- arrivals ----
def baggage_carousel(straight=3.6, r=1.25, feed=3.15):
    """A flat-plate baggage carousel, a racetrack along the model's x: the grey base, the ring of
    plates, the raised steel centre island, a few suitcases on the plates; at its east end (+x) the
    feed belt rising to a hatch with rubber curtains in the wall; a flight screen on a post."""
    v = [box("base_mid", "carousel_base", 0, 0, 0.17, straight, 2 * r, 0.34),
         box("plates_mid", "carousel_plate", 0, 0, 0.36, straight, 2 * r, 0.04),
         box("island_mid", "steel", 0, 0, 0.45, straight, 2 * r - 0.9, 0.18)]
    for k, s in enumerate((-1, 1)):
        v += [cyl(f"base_end{k}", "carousel_base", s * straight / 2, 0, 0.17, r, 0.34),
              cyl(f"plates_end{k}", "carousel_plate", s * straight / 2, 0, 0.36, r, 0.04),
              cyl(f"island_end{k}", "steel", s * straight / 2, 0, 0.45, r - 0.45, 0.18)]
    for i, (x, y, c, sx, sy, sz) in enumerate(((-1.2, -0.98, "case_red", 0.7, 0.42, 0.26),
                                               (0.6, 0.98, "case_black", 0.75, 0.45, 0.28),
                                               (-2.35, 0.55, "case_blue", 0.45, 0.62, 0.24),
                                               (1.6, -0.98, "case_green", 0.5, 0.36, 0.18))):
        v.append(box(f"suitcase{i}", c, x, y, 0.38 + sz / 2, sx, sy, sz))  # lying flat on the plates
    x0 = straight / 2 + r - 0.3  # the feed belt from the end of the loop up to the wall
    v += [turned(box("feed", "dark_steel", x0 + feed / 2, 0, 0.75, feed + 0.1, 0.8, 0.12), "0 -0.2 0"),
          turned(box("feed_belt", "belt_rubber", x0 + feed / 2, 0, 0.82, feed + 0.1, 0.7, 0.02), "0 -0.2 0"),
          box("feed_leg", "dark_steel", x0 + feed / 2, 0, 0.35, 0.1, 0.6, 0.7),
          box("hatch", "lead_curtain", x0 + feed - 0.02, 0, 1.25, 0.03, 1.0, 0.9),
          box("hatch_hood", "steel", x0 + feed - 0.2, 0, 1.75, 0.4, 1.1, 0.1),
          cyl("screen_post", "steel", -straight / 2 - r - 0.3, 0, 1.1, 0.03, 2.2),
          box("flight_screen", "screen", -straight / 2 - r - 0.3, 0, 2.2, 0.05, 0.6, 0.36),
          box("flight_screen_lit", "fids_blue", -straight / 2 - r - 0.327, 0, 2.2, 0.004, 0.56, 0.32)]
    return v


def lost_luggage_desk(w=2.0, wall=1.3):
    """The lost luggage (baggage services) desk: a counter with a purple front toward the
    passengers (+y), a monitor and a bag-tag printer behind it, a luggage size chart and the sign
    on the wall behind (wall = its distance behind the desk)."""
    return [box("body", "kiosk_white", 0, 0, 0.52, w, 0.7, 1.04),
            box("band", "lost_purple", 0, 0.352, 0.6, w, 0.004, 0.5),
            box("top", "counter_top", 0, 0.03, 1.06, w + 0.04, 0.76, 0.04),
            box("monitor", "screen", -0.4, -0.15, 1.28, 0.45, 0.04, 0.3),
            box("printer", "kiosk_white", 0.3, -0.15, 1.15, 0.25, 0.3, 0.14),
            box("chart", "paper", 0.5, -wall + 0.02, 1.5, 0.6, 0.004, 0.8),
            box("sign", "lost_purple", 0, -wall + 0.02, 2.4, 1.8, 0.04, 0.4),
            box("sign_text", "fids_white", 0, -wall + 0.042, 2.4, 1.2, 0.002, 0.12)]


# ---- the toilets ----
def toilet():
    """A toilet: the cistern against the wall (-y), the bowl, seat and lid in front of it."""
    return [box("cistern", "porcelain", 0, -0.22, 0.62, 0.42, 0.18, 0.4),
            cyl("bowl", "porcelain", 0, 0.05, 0.2, 0.19, 0.4),
            cyl("seat", "porcelain", 0, 0.06, 0.41, 0.21, 0.03),
            box("pedestal", "porcelain", 0, -0.08, 0.2, 0.3, 0.21, 0.4),
            turned(cyl("lid", "porcelain", 0, -0.12, 0.62, 0.2, 0.02), "-0.25 0 0"),
            box("flush", "chrome", 0, -0.22, 0.83, 0.1, 0.06, 0.02)]


def urinal():
    """A wall-hung urinal (the wall behind at -y) with its chrome flush valve above."""
    return [box("back", "porcelain", 0, 0.02, 0.85, 0.38, 0.08, 0.7),
            cyl("bowl", "porcelain", 0, 0.14, 0.72, 0.16, 0.36),
            box("lip", "porcelain", 0, 0.22, 0.88, 0.3, 0.06, 0.05),
            cyl("valve", "chrome", 0, 0.05, 1.35, 0.02, 0.25)]


def sink():
    """A wall-hung wash basin (the wall behind at -y) with its sensor tap and a soap dispenser."""
    return [box("basin", "porcelain", 0, 0.22, 0.8, 0.5, 0.42, 0.15),
            box("bowl", "white_tile", 0, 0.24, 0.86, 0.38, 0.3, 0.04),
            cyl("tap", "chrome", 0, 0.06, 0.95, 0.02, 0.16),
            box("spout", "chrome", 0, 0.12, 1.02, 0.03, 0.12, 0.02),
            cyl("trap", "chrome", 0, 0.1, 0.55, 0.03, 0.35),
            box("soap", "kiosk_white", 0.3, 0.045, 1.15, 0.1, 0.08, 0.18)]


def mirror(w=0.6, h=0.8):
    """A washroom mirror on the wall (behind at -y), centred on the model's height."""
    return [box("frame", "chrome", 0, 0, 0, w + 0.04, 0.02, h + 0.04),
            box("glass", "mirror", 0, 0.011, 0, w, 0.004, h)]


def hand_dryer():
    """A wall-mounted electric hand dryer (the wall behind at -y), its nozzle pointing down."""
    return [box("body", "porcelain", 0, 0.08, 1.2, 0.28, 0.16, 0.3),
            box("nozzle", "chrome", 0, 0.1, 1.03, 0.08, 0.08, 0.05),
            box("badge", "dark_metal", 0, 0.161, 1.26, 0.1, 0.002, 0.04)]


def baby_changing_table():
    """A wall-mounted fold-down baby changing table, folded down (the wall behind at -y): the grey
    back plate, the tray with its raised rim and the blue pad, the safety strap, the baby sign."""
    return [box("back_plate", "changing_grey", 0, 0.04, 0.95, 0.9, 0.08, 0.55),
            box("tray", "changing_grey", 0, 0.33, 0.86, 0.88, 0.5, 0.06),
            box("rim_front", "changing_grey", 0, 0.57, 0.92, 0.88, 0.03, 0.08),
            box("rim_l", "changing_grey", -0.43, 0.33, 0.92, 0.03, 0.5, 0.08),
            box("rim_r", "changing_grey", 0.43, 0.33, 0.92, 0.03, 0.5, 0.08),
            box("pad", "changing_pad", 0, 0.33, 0.9, 0.78, 0.42, 0.03),
            box("strap", "rubber", 0, 0.33, 0.92, 0.04, 0.42, 0.005),
            box("sign", "airline_blue", 0, 0.081, 1.15, 0.14, 0.002, 0.14)]


# ---- the staff room and the first aid room ----
def microwave():
    """A microwave oven on a wall shelf (the wall behind at -y): the shelf on two brackets, the
    white oven with its dark glass door and the control panel on the right, facing +y."""
    return [box("shelf", "shelf_white", 0, 0.23, 1.1, 0.62, 0.45, 0.03),
            box("bracket_l", "dark_steel", -0.26, 0.15, 1.0, 0.03, 0.3, 0.17),
            box("bracket_r", "dark_steel", 0.26, 0.15, 1.0, 0.03, 0.3, 0.17),
            box("body", "microwave_white", 0, 0.24, 1.27, 0.5, 0.38, 0.3),
            box("door", "screen", -0.05, 0.431, 1.27, 0.34, 0.004, 0.24),
            box("panel", "dark_steel", 0.19, 0.431, 1.27, 0.1, 0.004, 0.24),
            box("handle", "chrome", 0.12, 0.44, 1.27, 0.02, 0.02, 0.2)]


def treatment_couch(length=1.9, w=0.65):
    """A medical treatment couch along the model's x: a steel frame on four legs, the blue padded
    top with a raised backrest at the head end (-x), a roll of couch paper along it."""
    v = [box("frame", "steel", 0, 0, 0.6, length, w - 0.1, 0.08),
         box("pad", "couch_blue", 0.25, 0, 0.7, length - 0.5, w, 0.1),
         turned(box("backrest", "couch_blue", -length / 2 + 0.28, 0, 0.82, 0.62, w, 0.1), "0 0.45 0"),
         box("paper", "couch_paper", 0.2, 0, 0.752, length - 0.7, w - 0.15, 0.004),
         along_y(cyl("paper_roll", "couch_paper", length / 2 - 0.03, 0, 0.68, 0.05, w - 0.1)),
         box("shelf", "steel", 0, 0, 0.2, length - 0.1, w - 0.1, 0.02)]
    return v + legs("steel", length / 2 - 0.05, w / 2 - 0.08, 0.58, 0.04)


def medical_cabinet():
    """A medical cabinet against the wall (behind at -y): white steel, two glazed upper doors over
    shelves of boxes and bottles, solid lower doors, a green first aid cross."""
    v = [box("body", "cabinet_white", 0, 0, 0.9, 0.8, 0.4, 1.8),
         box("glass_l", "acrylic_glass", -0.2, 0.201, 1.35, 0.36, 0.004, 0.75),
         box("glass_r", "acrylic_glass", 0.2, 0.201, 1.35, 0.36, 0.004, 0.75),
         box("door_seam", "dark_steel", 0, 0.202, 0.45, 0.01, 0.004, 0.8),
         box("cross_v", "cross_green", 0, 0.203, 0.55, 0.06, 0.004, 0.2),
         box("cross_h", "cross_green", 0, 0.204, 0.55, 0.2, 0.004, 0.06)]
    for i, z in enumerate((1.1, 1.45)):
        v += [box(f"box{i}_{k}", ("paper", "cross_green", "drink_blue")[k % 3], -0.3 + 0.15 * k, 0.05, z + 0.08,
                  0.12, 0.2, 0.14) for k in range(5)]
    return v


def fire_extinguisher():
    """A red extinguisher on its wall bracket (the wall behind at -y)."""
    return [box("bracket", "dark_steel", 0, -0.08, 0.85, 0.1, 0.02, 0.3),
            cyl("body", "extinguisher_red", 0, 0, 0.8, 0.08, 0.5),
            sph("shoulder", "extinguisher_red", 0, 0, 1.05, 0.08),
            cyl("head", "black", 0, 0, 1.15, 0.025, 0.08),
            box("handle", "black", 0, 0.04, 1.19, 0.03, 0.12, 0.02),
            turned(cyl("hose", "black", 0.07, 0.03, 1.0, 0.012, 0.3), "0 0.3 0"),
            box("tag", "paper", 0, 0.081, 0.75, 0.06, 0.002, 0.09)]


# ---- the building ----
def walls():
    """The outer walls with the main entrance (south), the arrivals door (east) and the gate door
    (north); the landside/airside wall with the way into security; the reclaim hall's wall with
    its exit into the check-in hall; the first aid room's walls; the wall between security and
    the lounge; the east strip's walls with the doors of the staff room and the toilets; the
    toilet cubicle partitions."""
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

    with_openings(0, "x", 0, W, (MAIN_DOOR,), top=2.5)
    with_openings(D, "x", 0, W, (GATE_DOOR,), top=2.2)
    wall(0, 0, 0, D)
    with_openings(W, "y", 0, D, (ARRIVALS_DOOR,))
    with_openings(YA, "x", 0, W, (SECURITY_IN,), top=2.5)
    with_openings(XC, "y", 0, YA, (ARRIVALS_EXIT,), top=2.5)
    wall(XF, YF, XF, YA, c="partition")
    with_openings(YF, "x", XF, XC, (FIRST_AID_DOOR,), c="partition")
    with_openings(XS, "y", YA, D, (SECURITY_OUT,), top=2.5)
    with_openings(XE, "y", YA, D, (STAFF_DOOR, MENS_DOOR, WOMENS_DOOR), c="partition")
    wall(XE, YST, W, YST, c="white_tile")
    wall(XE, YMW, W, YMW, c="white_tile")
    # the toilet cubicles: a partition between the two toilets of each room
    wall(30.2, 15.05, W - T / 2, 15.05, 0, 2.0, c="cubicle")
    wall(30.2, 18.35, W - T / 2, 18.35, 0, 2.0, c="cubicle")
    return v


def floor():
    """The floor: pale terrazzo in the halls and security, blue carpet in the departure lounge,
    white tiles in the toilets, vinyl in the staff room and the first aid room."""
    v = base.floor_slab("floor_terminal", "terrazzo", W, D)
    v.append(box("lounge", "carpet_blue", (XS + XE) / 2, (YA + D) / 2, 0.0005, XE - XS, D - YA, 0.001))
    v.append(box("toilets", "white_tile", (XE + W) / 2, (YST + D) / 2, 0.0005, W - XE, D - YST, 0.001))
    v.append(box("staff_room", "vinyl", (XE + W) / 2, (YA + YST) / 2, 0.0005, W - XE, YST - YA, 0.001))
    v.append(box("first_aid", "vinyl", (XF + XC) / 2, (YF + YA) / 2, 0.0005, XC - XF, YA - YF, 0.001))
    return v


def check_in_hall(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    e0, e1 = MAIN_DOOR
    add("door_1", (e0 + 0.08, T / 2 + 0.46, 0, WEST), base.door())  # the main entrance, both leaves open
    add("door_2", (e1 - 0.08, T / 2 + 0.46, 0, WEST), base.door())
    for i, x in enumerate((2.6, 5.6, 13.4, 16.6), 1):
        add(f"window_{i}", (x, T / 2 + 0.02, 1.6, N), base.window())
    add("cash_machine", (1.0, T / 2 + 0.36, 0, N), cash_machine())
    add("bench_1", (4.1, T / 2 + 0.24, 0, N), bench())
    for i, x in enumerate((6.2, 6.9, 7.6), 1):
        add(f"luggage_trolley_{i}", (x, 1.05, 0, N), luggage_trolley())
    add("bench_2", (14.5, T / 2 + 0.24, 0, N), bench())
    add("bin_1", (12.3, 0.4, 0, N), bin_())
    add("flight_information_display", (9.5, 3.4, 0, S), flight_information_display())
    add("information_desk", (15.8, 2.6, 0, S), information_desk())
    for i, y in enumerate((3.6, 4.5, 5.4, 6.3), 1):
        add(f"check_in_kiosk_{i}", (T / 2 + 0.27, y, 0, E), check_in_kiosk())
    add("bin_2", (0.35, 7.3, 0, E), bin_())
    add("fire_extinguisher_1", (T / 2 + 0.1, 8.6, 0, E), fire_extinguisher())
    # four check-in desks, each with its scale to the east, the conveyor behind them on the wall
    for i, x in enumerate((7.4, 9.7, 12.0, 14.3), 1):
        add(f"check_in_desk_{i}", (x, 7.75, 0, S), check_in_desk())
        add(f"baggage_scale_{i}", (x + 1.1, 8.0, 0, S), baggage_scale())
    add("conveyor_belt", (11.35, YA - T / 2 - 0.34, 0, S), conveyor_belt(9.5))  # the hatch at its east end
    # the queue: a two-lane serpentine of stanchions in front of the desks
    xs = (6.6, 8.3, 10.0, 11.7, 13.4, 15.1)
    posts = [(x, 6.6, 1.7 if x < 15 else 0, N) for x in xs[1:]]             # the front row
    posts += [(x, 5.6, 1.7 if x < 13 else 0, N) for x in xs[:5]]            # the middle row (the turn at the east)
    posts += [(15.1, 5.6, 1.0, WEST)]                                       # closing the east end of the front lane
    posts += [(x, 4.6, 1.7 if x < 15 else 1.0, N if x < 15 else WEST) for x in xs]  # the back row, closed at the east
    for i, (x, y, belt, yaw) in enumerate(posts, 1):
        add(f"stanchion_{i}", (x, y, 0, yaw), stanchion(belt))
    add("car_hire_desk", (19.0, 5.2, 0, WEST), car_hire_desk(1.8, XC - T / 2 - 19.0 - 0.02))


def first_aid_room(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    f0, f1 = FIRST_AID_DOOR
    add("door_3", (f0 + 0.08, YF + T / 2 + 0.46, 0, WEST), base.door())  # hinged at the doorway's west side
    add("treatment_couch", (18.45, YA - T / 2 - 0.4, 0, N), treatment_couch())
    add("medical_cabinet", (XC - T / 2 - 0.21, 8.0, 0, WEST), medical_cabinet())
    add("bin_3", (16.9, 9.6, 0, N), bin_())


def reclaim_hall(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    a0, a1 = ARRIVALS_DOOR
    add("door_4", (W - T / 2 - 0.045, (a0 + a1) / 2, 0, WEST), gate_door(a1 - a0))  # the arrivals door from the apron, shut
    add("baggage_carousel", (26.0, 4.6, 0, N), baggage_carousel())
    add("lost_luggage_desk", (30.3, 1.35, 0, N), lost_luggage_desk(2.0, 1.35 - T / 2 - 0.02))
    for i, x in enumerate((21.0, 21.7, 22.4), 4):
        add(f"luggage_trolley_{i}", (x, 8.7, 0, S), luggage_trolley())
    add("bench_3", (24.0, T / 2 + 0.24, 0, N), bench())
    add("window_5", (24.0, T / 2 + 0.02, 1.6, N), base.window())
    add("window_6", (27.5, T / 2 + 0.02, 1.6, N), base.window())
    add("window_7", (W - T / 2 - 0.02, 2.5, 1.6, WEST), base.window())
    add("bin_4", (20.35, 4.6, 0, E), bin_())
    add("fire_extinguisher_2", (XC + T / 2 + 0.1, 7.2, 0, E), fire_extinguisher())


def security(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    add("roller_conveyor_1", (1.0, 11.65, 0, N), roller_conveyor(2.4, 2))
    add("x_ray_scanner", (1.0, 14.25, 0, N), x_ray_scanner(2.8))
    add("roller_conveyor_2", (1.0, 17.15, 0, N), roller_conveyor(3.0, 3))
    add("divesting_table_1", (1.8, 10.8, 0, N), divesting_table(1.2))
    add("divesting_table_2", (1.8, 12.2, 0, N), divesting_table(1.2))
    add("metal_detector", (3.4, 14.5, 0, N), metal_detector())
    add("body_scanner", (5.8, 14.5, 0, N), body_scanner())
    add("bin_5", (7.6, 10.4, 0, N), bin_())
    add("fire_extinguisher_3", (XS - T / 2 - 0.1, 11.2, 0, WEST), fire_extinguisher())


def lounge(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    # the duty-free / newsagent shop in the south-west
    add("shop_shelf_1", (9.65, YA + T / 2 + 0.23, 0, N), shop_shelf(2.2, 0.45, 0))
    add("shop_shelf_2", (12.0, YA + T / 2 + 0.23, 0, N), shop_shelf(2.2, 0.45, 1))
    add("shop_shelf_3", (10.8, 12.0, 0, N), shop_shelf(2.4, 0.7, 2, True))
    add("shop_shelf_4", (XS + T / 2 + 0.23, 12.0, 0, E), shop_shelf(1.6, 0.45, 3))
    add("till", (13.9, 12.2, 0, WEST), till())
    # the seating: four blocks of two rows back to back, two rows facing the apron windows
    n = [0]

    def seats(x, y, yaw):
        n[0] += 1
        add(f"airport_seating_{n[0]}", (x, y, 0, yaw), airport_seating(4))
    for x in (11.0, 14.0, 17.9):
        seats(x, 16.2, N); seats(x, 15.5, S)
    seats(11.0, 18.3, N); seats(14.0, 18.3, N)
    add("charging_point_1", (12.5, 15.85, 0, N), charging_point())
    add("charging_point_2", (12.5, 18.3, 0, N), charging_point())
    add("charging_point_3", (19.45, 15.85, 0, N), charging_point())
    # the cafe in the south-east
    add("cafe_counter", (21.5, 11.2, 0, N), cafe_counter(3.0))
    add("coffee_machine", (21.9, 11.2, 1.065, S), coffee_machine())  # facing the barista
    add("display_fridge", (19.3, YA + T / 2 + 0.36, 0, N), display_fridge())
    t, c = [0], [0]
    for x in (18.8, 20.6, 22.4):
        t[0] += 1
        add(f"table_{t[0]}", (x, 13.1, 0, N), cafe_table())
        for dx, yaw in ((-0.6, E), (0.6, WEST)):
            c[0] += 1
            add(f"chair_{c[0]}", (x + dx, 13.1, 0, yaw), chair())
    add("bin_6", (17.3, YA + T / 2 + 0.2, 0, N), bin_())
    # screens, water, bins, safety on the walls
    add("departure_screen_1", (XS + T / 2 + 0.07, 14.8, 2.2, E), departure_screen())
    add("departure_screen_2", (XE - T / 2 - 0.07, 17.4, 2.2, WEST), departure_screen())
    add("water_fountain", (XE - T / 2, 16.2, 0, WEST), water_fountain())
    add("bin_7", (9.3, 16.2, 0, N), bin_())
    add("bin_8", (16.3, 19.6, 0, S), bin_())
    add("fire_extinguisher_4", (XS + T / 2 + 0.1, 16.2, 0, E), fire_extinguisher())
    # the windows onto the apron along the north wall
    for i, x in enumerate((10.0, 12.6, 15.2, 17.8), 8):
        add(f"window_{i}", (x, D - T / 2 - 0.02, 1.6, S), apron_window())
    add("window_12", (23.35, D - T / 2 - 0.02, 1.6, S), apron_window(0.9, 1.9))


def boarding_gate(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    g0, g1 = GATE_DOOR
    add("door_5", ((g0 + g1) / 2, D - T / 2 - 0.045, 0, S), gate_door(g1 - g0))  # shut, just inside its opening
    add("departure_screen_3", ((g0 + g1) / 2, D - T / 2 - 0.07, 2.75, S), departure_screen())
    add("gate_desk", (19.9, 18.8, 0, S), gate_desk())
    add("boarding_pass_reader", (21.1, 18.7, 0, S), boarding_pass_reader())


def staff_room(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    s0, s1 = STAFF_DOOR
    add("door_6", (XE + 0.52, s1 - 0.04, 0, N), base.door())  # hinged at the doorway's north side, open inward
    for i, y in enumerate((10.6, 11.55, 12.5), 1):
        add(f"locker_{i}", (W - T / 2 - 0.23, y, 0, WEST), base.locker())
    add("table_4", (27.8, 11.7, 0, N), staff_table())
    for i, (x, y, yaw) in enumerate(((27.4, 10.95, N), (28.2, 10.95, N), (27.4, 12.45, S), (28.2, 12.45, S)), 7):
        add(f"chair_{i}", (x, y, 0, yaw), chair())
    add("microwave", (30.0, YA + T / 2, 0, N), microwave())
    add("fire_extinguisher_5", (XE + T / 2 + 0.1, 10.7, 0, E), fire_extinguisher())
    add("bin_9", (25.2, YA + T / 2 + 0.2, 0, N), bin_())


def toilets(out):
    add = lambda name, pose, vis: out.append(base.model(name, pose, vis))
    m0, m1 = MENS_DOOR
    w0, w1 = WOMENS_DOOR
    # the men's
    add("door_7", (XE + 0.52, m1 - 0.04, 0, N), base.door())
    add("toilet_1", (W - T / 2 - 0.32, 14.25, 0, WEST), toilet())
    add("toilet_2", (W - T / 2 - 0.32, 15.85, 0, WEST), toilet())
    for i, x in enumerate((27.0, 27.8, 28.6), 1):
        add(f"urinal_{i}", (x, YMW - T / 2 - 0.02, 0, S), urinal())
    for i, x in enumerate((26.2, 27.0), 1):
        add(f"sink_{i}", (x, YST + T / 2 + 0.01, 0, N), sink())
        add(f"mirror_{i}", (x, YST + T / 2 + 0.02, 1.65, N), mirror(0.5, 0.7))
    add("hand_dryer_1", (28.3, YST + T / 2 + 0.01, 0, N), hand_dryer())
    add("bin_10", (29.2, YST + T / 2 + 0.2, 0, N), bin_())
    # the women's
    add("door_8", (XE + 0.52, w1 - 0.04, 0, N), base.door())
    add("toilet_3", (W - T / 2 - 0.32, 17.55, 0, WEST), toilet())
    add("toilet_4", (W - T / 2 - 0.32, 19.15, 0, WEST), toilet())
    for i, x in enumerate((26.5, 27.3), 3):
        add(f"sink_{i}", (x, D - T / 2 - 0.01, 0, S), sink())
        add(f"mirror_{i}", (x, D - T / 2 - 0.02, 1.65, S), mirror(0.5, 0.7))
    add("hand_dryer_2", (28.4, D - T / 2 - 0.01, 0, S), hand_dryer())
    add("baby_changing_table", (27.0, YMW + T / 2, 0, N), baby_changing_table())
    add("bin_11", (28.8, YMW + T / 2 + 0.2, 0, N), bin_())


def main():
    out = [base.model("walls", (0, 0, 0, 0), walls()),
           base.model("floor", (0, 0, 0, 0), floor()),
           base.model("ceiling", (0, 0, 0, 0), base.ceiling_slab(W, D, H))]
    check_in_hall(out)
    first_aid_room(out)
    reclaim_hall(out)
    security(out)
    lounge(out)
    boarding_gate(out)
    staff_room(out)
    toilets(out)
    cool, warm = "0.8 0.8 0.78", "0.85 0.8 0.7"
    lights = [base.point_light(name, x, y, H - 0.25, rgb)
              for name, x, y, rgb in (("light_checkin_w", 3.5, 3.0, cool), ("light_checkin_m", 9.5, 3.0, cool),
                                      ("light_checkin_e", 15.0, 3.5, cool), ("light_desks_w", 8.0, 7.0, cool),
                                      ("light_desks_e", 13.5, 7.0, cool), ("light_first_aid", 18.2, 8.5, cool),
                                      ("light_reclaim_w", 23.0, 5.0, cool), ("light_reclaim_e", 29.0, 5.0, cool),
                                      ("light_security_s", 4.0, 12.5, cool), ("light_security_n", 4.0, 17.5, cool),
                                      ("light_shop", 11.0, 11.8, warm), ("light_lounge_w", 12.0, 16.5, warm),
                                      ("light_lounge_e", 17.5, 16.5, warm), ("light_cafe", 21.0, 12.5, warm),
                                      ("light_gate", 21.5, 18.3, warm), ("light_staff", 28.0, 11.7, cool),
                                      ("light_mens", 28.0, 15.0, cool), ("light_womens", 28.0, 18.3, cool))]
    print(base.world_sdf("semsplat_airport", """The semsplat airport: the terminal of a small regional airport of 32 m x 20 m on one floor
     (landside: the check-in hall with check-in desks, baggage scales and the conveyor belt, the
     self-service kiosks, the stanchion queue, luggage trolleys, the flight information display,
     the information desk, benches, a cash machine and the car hire desk; the first aid room; the
     arrivals baggage reclaim with the carousel and the lost luggage desk; airside: the security
     checkpoint with the X-ray scanner, roller conveyors, divesting tables, the metal detector and
     the body scanner; the departure lounge with airport seating, charging points, the cafe, the
     duty-free shop, departure screens and a water fountain; the boarding gate with the gate desk,
     the boarding pass reader and the gate door; the staff room; the men's and women's toilets)
     for measuring on a world nobody tuned on. Generated by airport_models/make_airport.py; all
     models are inline.""", lights, out))


if __name__ == "__main__":
    main()
